#include "brdflut/fresnel.h"

#include <cmath>
#include <complex>
#include <string>

#include "brdflut/error.h"
#include "brdflut/fresnel_integrals.h"
#include "brdflut/math.h"

namespace brdflut {

FresnelAmplitudes fresnel_dielectric_amplitudes(double cos_i, double eta) {
    cos_i = clamp01(cos_i);
    // Matched index: there is no interface, so nothing is reflected, at
    // grazing incidence too (where the formulas below would give 0/0).
    if (eta == 1.0) return {0.0, 0.0};
    const double sin2_t = (1.0 - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1.0) return {1.0, 1.0};  // total internal reflection
    const double cos_t = std::sqrt(1.0 - sin2_t);
    const double rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    const double rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    return {rs, rp};
}

double fresnel_dielectric(double cos_i, double eta) {
    const FresnelAmplitudes r = fresnel_dielectric_amplitudes(cos_i, eta);
    return 0.5 * (r.rs * r.rs + r.rp * r.rp);
}

double fresnel_dielectric_average(double eta) {
    return fresnel_dielectric_average_quadrature(eta, 1e-14).value[0];
}

// Closed form of 2 * integral of F(mu) mu dmu for n > 1, as tabulated in the
// project's field notes (it follows from integrating Rs and Rp in sin^2).
double fresnel_dielectric_average_closed_form(double eta) {
    if (!(eta >= 1.0) || !std::isfinite(eta))
        throw Error("fresnel_dielectric_average_closed_form: eta " + std::to_string(eta) +
                    " is out of range; allowed: eta >= 1 (use F_avg(1/n) = 1 - (1 - F_avg(n)) / n^2 "
                    "inside the denser medium)");
    if (eta == 1.0) return 0.0;
    const double n = eta, n2 = n * n, n4 = n2 * n2;
    const double n2p1 = n2 + 1.0, n4m1 = n4 - 1.0;
    return 0.5 + (n - 1.0) * (3.0 * n + 1.0) / (6.0 * sqr(n + 1.0)) +
           n2 * sqr(n2 - 1.0) / (n2p1 * n2p1 * n2p1) * std::log((n - 1.0) / (n + 1.0)) -
           2.0 * n2 * n * (n2 + 2.0 * n - 1.0) / (n2p1 * n4m1) +
           8.0 * n4 * (n4 + 1.0) / (n2p1 * n4m1 * n4m1) * std::log(n);
}

double fresnel_conductor(double cos_i, double eta, double k) {
    using C = std::complex<double>;
    cos_i = clamp01(cos_i);
    const double sin2_i = 1.0 - cos_i * cos_i;
    const C n(eta, k);
    const C n2 = n * n;
    // w = n cos(theta_t) = sqrt(n^2 - sin^2(theta_i)). The principal root has
    // Im(w) >= 0 (as Im(n^2) = 2 eta k >= 0): the transmitted wave decays
    // into the conductor; for k = 0 beyond the critical angle w is imaginary
    // and both |rs| and |rp| are 1.
    // Matched index (eta = 1, k = 0): no interface, nothing reflected, at
    // grazing incidence too (where the quotients below would be 0/0).
    if (eta == 1.0 && k == 0.0) return 0.0;
    const C w = std::sqrt(n2 - sin2_i);
    const C rs_den = cos_i + w, rp_den = n2 * cos_i + w;
    const C rs = (cos_i - w) / rs_den;
    const C rp = (n2 * cos_i - w) / rp_den;
    return 0.5 * (std::norm(rs) + std::norm(rp));
}

double fresnel_conductor_approx(double cos_i, double eta, double k) {
    cos_i = clamp01(cos_i);
    const double c2 = cos_i * cos_i;
    const double nk2 = eta * eta + k * k;
    const double two_eta_c = 2.0 * eta * cos_i;
    const double r_par2 = (nk2 * c2 - two_eta_c + 1.0) / (nk2 * c2 + two_eta_c + 1.0);
    const double r_perp2 = (nk2 - two_eta_c + c2) / (nk2 + two_eta_c + c2);
    return 0.5 * (r_par2 + r_perp2);
}

std::string_view to_string(FresnelForm f) { return f == FresnelForm::approx ? "approx" : "exact"; }

FresnelForm fresnel_form_from_string(std::string_view s) {
    if (s == "exact") return FresnelForm::exact;
    if (s == "approx") return FresnelForm::approx;
    throw Error("--fresnel '" + std::string(s) + "' is not known; allowed: exact, approx");
}

double fresnel_conductor(double cos_i, double eta, double k, FresnelForm form) {
    return form == FresnelForm::approx ? fresnel_conductor_approx(cos_i, eta, k)
                                       : fresnel_conductor(cos_i, eta, k);
}

}  // namespace brdflut
