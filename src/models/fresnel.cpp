#include "brdflut/fresnel.h"

#include <cmath>

#include "brdflut/math.h"
#include "brdflut/quadrature.h"

namespace brdflut {

FresnelAmplitudes fresnel_dielectric_amplitudes(double cos_i, double eta) {
    cos_i = clamp01(cos_i);
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
    AdaptiveOptions opt;
    opt.abs_tol = 1e-14;
    opt.max_intervals = 400;
    auto f = [&](double mu) { return std::array<double, 1>{2.0 * mu * fresnel_dielectric(mu, eta)}; };
    if (eta >= 1.0) return integrate_adaptive<1>(f, 0.0, 1.0, opt).value[0];
    // Below the critical cosine mu_c = sqrt(1 - eta^2) everything is reflected:
    // 2 * integral of mu dmu over [0, mu_c] = mu_c^2. Above it F has a square
    // root at mu_c; mu = mu_c + (1 - mu_c) s^2 makes the integrand smooth.
    const double mu_c = std::sqrt(1.0 - eta * eta);
    const double len = 1.0 - mu_c;
    const double rest = integrate_adaptive<1>(
                            [&](double s) {
                                const double mu = mu_c + len * s * s;
                                std::array<double, 1> v = f(mu);
                                v[0] *= 2.0 * len * s;
                                return v;
                            },
                            0.0, 1.0, opt)
                            .value[0];
    return mu_c * mu_c + rest;
}

}  // namespace brdflut
