#include "brdflut/dipole.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "brdflut/error.h"
#include "brdflut/fresnel.h"
#include "brdflut/math.h"

namespace brdflut {

namespace {
std::string number(double v) {
    std::ostringstream s;
    s.precision(10);
    s << v;
    return s.str();
}
constexpr double kEps = std::numeric_limits<double>::epsilon();
}  // namespace

std::string_view to_string(DiffuseFresnel f) { return f == DiffuseFresnel::fit ? "fit" : "exact"; }

DiffuseFresnel diffuse_fresnel_from_string(std::string_view s) {
    if (s == "fit") return DiffuseFresnel::fit;
    if (s == "exact") return DiffuseFresnel::exact;
    throw Error("--fdr '" + std::string(s) + "' is not known; allowed: fit, exact");
}

void validate_dipole_eta(double eta, DiffuseFresnel f) {
    if (f == DiffuseFresnel::fit) {
        if (!(eta >= kDipoleFitEtaMin && eta <= kDipoleFitEtaMax))
            throw Error("--eta " + number(eta) + " is out of range for --fdr fit; allowed: " +
                        number(kDipoleFitEtaMin) + " <= eta <= " + number(kDipoleFitEtaMax) +
                        " (the range of the fit), or 0 < eta <= " + number(kDipoleExactEtaMax) +
                        " with --fdr exact");
    } else if (!(eta > 0.0 && eta <= kDipoleExactEtaMax)) {
        throw Error("--eta " + number(eta) + " is out of range; allowed: 0 < eta <= " +
                    number(kDipoleExactEtaMax) + " with --fdr exact");
    }
}

double diffuse_fresnel_reflectance_fit(double eta) {
    return -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta;
}

double diffuse_fresnel_reflectance_exact(double eta) {
    // Light leaving the medium: relative index n_outside / n_medium = 1 / eta.
    return fresnel_dielectric_average(1.0 / eta);
}

double diffuse_fresnel_reflectance(double eta, DiffuseFresnel f) {
    return f == DiffuseFresnel::fit ? diffuse_fresnel_reflectance_fit(eta)
                                    : diffuse_fresnel_reflectance_exact(eta);
}

double dipole_boundary_term(double F_dr) { return (1.0 + F_dr) / (1.0 - F_dr); }

Dipole::Dipole(double sigma_s_prime, double sigma_a, double A) {
    if (!(sigma_s_prime >= 0.0) || !std::isfinite(sigma_s_prime))
        throw Error("reduced scattering coefficient " + number(sigma_s_prime) +
                    " is not valid; allowed: a finite value >= 0");
    if (!(sigma_a >= 0.0) || !std::isfinite(sigma_a))
        throw Error("absorption coefficient " + number(sigma_a) +
                    " is not valid; allowed: a finite value >= 0");
    if (!(sigma_s_prime + sigma_a > 0.0))
        throw Error("reduced extinction sigma_s' + sigma_a is 0; allowed: > 0");
    if (!(A > 0.0) || !std::isfinite(A))
        throw Error("dipole boundary term A = " + number(A) + " is not valid; allowed: finite, > 0");
    sigma_t_ = sigma_s_prime + sigma_a;
    albedo_ = sigma_s_prime / sigma_t_;
    sigma_tr_ = std::sqrt(3.0 * sigma_a * sigma_t_);
    z_r_ = 1.0 / sigma_t_;
    z_v_ = z_r_ * (1.0 + 4.0 * A / 3.0);
    A_ = A;
}

Dipole Dipole::from_albedo(double albedo, double A) {
    if (!(albedo >= 0.0 && albedo <= 1.0))
        throw Error("albedo " + number(albedo) + " is out of range; allowed: 0 <= albedo <= 1");
    return Dipole(albedo, 1.0 - albedo, A);
}

double Dipole::profile(double r) const {
    auto term = [&](double z) {
        const double d = std::sqrt(r * r + z * z);
        const double sd = sigma_tr_ * d;
        return z * (1.0 + sd) * std::exp(-sd) / (d * d * d);
    };
    return albedo_ / (4.0 * kPi) * (term(z_r_) + term(z_v_));
}

double Dipole::shape_total() const {
    return std::exp(-sigma_tr_ * z_r_) + std::exp(-sigma_tr_ * z_v_);
}

double Dipole::shape_within(double r) const {
    if (std::isinf(r)) return shape_total();
    // e^(-s z) - (z/d) e^(-s d) = -e^(-s z) expm1(-s (d - z) + ln(z/d)), with
    // d - z = r^2 / (d + z) and ln(z/d) = -ln(1 + r^2/z^2) / 2.
    auto term = [&](double z) {
        const double d = std::sqrt(r * r + z * z);
        const double x = -sigma_tr_ * (r * r / (d + z)) - 0.5 * std::log1p(sqr(r / z));
        return -std::exp(-sigma_tr_ * z) * std::expm1(x);
    };
    return term(z_r_) + term(z_v_);
}

double Dipole::reflectance_within(double r) const { return 0.5 * albedo_ * shape_within(r); }

double Dipole::total_reflectance() const { return 0.5 * albedo_ * shape_total(); }

double Dipole::cdf(double r) const { return std::min(1.0, shape_within(r) / shape_total()); }

double dipole_total_reflectance(double albedo, double A) {
    if (!(albedo >= 0.0 && albedo <= 1.0))
        throw Error("albedo " + number(albedo) + " is out of range; allowed: 0 <= albedo <= 1");
    const double s = std::sqrt(3.0 * (1.0 - albedo));
    return 0.5 * albedo * (1.0 + std::exp(-4.0 / 3.0 * A * s)) * std::exp(-s);
}

double dipole_albedo_from_reflectance(double R, double A, double* error) {
    if (!(R >= 0.0 && R <= 1.0))
        throw Error("reflectance " + number(R) +
                    " is out of range; allowed: 0 <= reflectance <= 1 (the total at albedo 1)");
    if (error) *error = 0.0;
    if (R == 0.0) return 0.0;
    if (R == 1.0) return 1.0;
    // With s = sqrt(3(1 - a')) in [0, sqrt(3)] and k = 4A/3:
    //   T(s)  = ((1 - s^2/3)/2) e^-s (1 + e^-ks), falling from 1 to 0,
    //   T'(s) = -(s/3) e^-s (1 + e^-ks) - ((1 - s^2/3)/2) e^-s (1 + (1 + k) e^-ks) < 0.
    const double k = 4.0 * A / 3.0;
    auto T = [&](double s) { return 0.5 * (1.0 - s * s / 3.0) * std::exp(-s) * (1.0 + std::exp(-k * s)); };
    auto dT = [&](double s) {
        const double e = std::exp(-s), ek = std::exp(-k * s);
        return -(s / 3.0) * e * (1.0 + ek) - 0.5 * (1.0 - s * s / 3.0) * e * (1.0 + (1.0 + k) * ek);
    };
    double lo = 0.0, hi = std::sqrt(3.0);  // T(lo) = 1 > R > 0 = T(hi)
    double s = 0.5 * (lo + hi);
    for (int it = 0; it < 200; ++it) {
        const double f = T(s) - R;
        if (f == 0.0) break;
        if (f > 0.0) lo = s; else hi = s;
        double next = s - f / dT(s);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket
        const bool done = std::abs(next - s) <= 4.0 * kEps * std::max(s, 1e-300) || hi - lo <= 4.0 * kEps * hi;
        s = next;
        if (done) break;
    }
    const double albedo = 1.0 - s * s / 3.0;
    if (error) {
        // Distance to the root by one more Newton step, mapped to a' (da' = -(2s/3) ds),
        // plus the rounding of T and of 1 - s^2/3.
        const double ds = std::abs((T(s) - R) / dT(s)) + 8.0 * kEps * (1.0 + s) / std::abs(dT(s));
        *error = (2.0 * s / 3.0) * ds + 4.0 * kEps;
    }
    return albedo;
}

// Jensen, Marschner, Levoy and Hanrahan 2001, Figure 5: reduced scattering
// sigma_s' and absorption sigma_a in 1/mm for the R, G, B channels. The index
// is not part of the entry: the tables take it from --eta (default 1.3).
// pbrt's copy of this table pairs marble with 1.5, which reproduces the
// reflectance usually quoted for marble (0.83, 0.79, 0.75) where 1.3 gives
// (0.87, 0.83, 0.80).
const std::vector<MeasuredMaterial>& measured_materials() {
    static const std::vector<MeasuredMaterial> all = {
        {"apple", {2.29, 2.39, 1.97}, {0.0030, 0.0034, 0.046}},
        {"chicken1", {0.15, 0.21, 0.38}, {0.015, 0.077, 0.19}},
        {"chicken2", {0.19, 0.25, 0.32}, {0.018, 0.088, 0.20}},
        {"cream", {7.38, 5.47, 3.15}, {0.0002, 0.0028, 0.0163}},
        {"ketchup", {0.18, 0.07, 0.03}, {0.061, 0.97, 1.45}},
        {"marble", {2.19, 2.62, 3.00}, {0.0021, 0.0041, 0.0071}},
        {"potato", {0.68, 0.70, 0.55}, {0.0024, 0.0090, 0.12}},
        {"skim_milk", {0.70, 1.22, 1.90}, {0.0014, 0.0025, 0.0142}},
        {"skin1", {0.74, 0.88, 1.01}, {0.032, 0.17, 0.48}},
        {"skin2", {1.09, 1.59, 1.79}, {0.013, 0.070, 0.145}},
        {"whole_milk", {2.55, 3.21, 3.77}, {0.0011, 0.0024, 0.014}},
    };
    return all;
}

const MeasuredMaterial& find_measured_material(const std::string& name) {
    for (const MeasuredMaterial& m : measured_materials())
        if (name == m.name) return m;
    std::string known;
    for (const MeasuredMaterial& m : measured_materials()) known += (known.empty() ? "" : ", ") + std::string(m.name);
    throw Error("--material '" + name + "' is not known; allowed: " + known);
}

}  // namespace brdflut
