// Quadrature and Monte Carlo estimates of Fresnel hemispherical averages.
//
// For eta < 1 the reflectance has a square-root kink at the critical cosine
// mu_c = sqrt(1 - eta^2) (exactly for k = 0, smoothed over a width that
// grows with k otherwise). Each side of mu_c is integrated in s with
// mu = mu_c -/+ len s^2, which turns sqrt(|mu - mu_c|) into a linear
// function of s, so Gauss-Kronrod converges fast on both sides:
//
//   F_avg = integral over s in [0, 1] of 2 mu(s) F(mu(s)) 2 len s ds, summed
//           over the two sides (len = mu_c below, 1 - mu_c above).
#include "brdflut/fresnel_integrals.h"

#include <algorithm>
#include <cmath>

#include "brdflut/random.h"

namespace brdflut {
namespace {

constexpr int kMaxIntervals = 400;

// 2 * integral of F(mu) mu dmu over one side of mu_c, in s.
template <class Reflectance>
Estimate<1> side(const Reflectance& F, double mu_c, double len, double sign, double abs_tol) {
    AdaptiveOptions opt;
    opt.abs_tol = abs_tol;
    opt.max_intervals = kMaxIntervals;
    return integrate_adaptive<1>(
        [&](double s) {
            const double mu = mu_c + sign * len * s * s;
            return std::array<double, 1>{2.0 * mu * F(mu) * 2.0 * len * s};
        },
        0.0, 1.0, opt);
}

void add(Estimate<1>& to, const Estimate<1>& e) {
    to.value[0] += e.value[0];
    to.error[0] += e.error[0];
    to.evaluations += e.evaluations;
}

template <class Reflectance>
Estimate<1> average_mc(const Reflectance& F, long long samples, std::uint64_t seed) {
    Rng rng(seed, 0);
    MeanAccumulator<1> acc;
    for (long long s = 0; s < samples; ++s) {
        // Density 2 mu on [0, 1]: mu = sqrt(u); 1 - u keeps mu > 0.
        const double f = F(std::sqrt(1.0 - rng.uniform()));
        acc.add(&f);
    }
    return acc.estimate();
}

}  // namespace

Estimate<1> fresnel_dielectric_average_quadrature(double eta, double abs_tol) {
    const auto F = [eta](double mu) { return fresnel_dielectric(mu, eta); };
    if (eta >= 1.0) return side(F, 0.0, 1.0, 1.0, abs_tol);
    // Below mu_c everything is reflected: 2 * integral of mu dmu = mu_c^2.
    const double mu_c = std::sqrt(1.0 - eta * eta);
    Estimate<1> out = side(F, mu_c, 1.0 - mu_c, 1.0, abs_tol);
    out.value[0] += mu_c * mu_c;
    return out;
}

Estimate<1> fresnel_conductor_average_quadrature(double eta, double k, FresnelForm form,
                                                 double abs_tol) {
    const auto F = [=](double mu) { return fresnel_conductor(mu, eta, k, form); };
    if (eta >= 1.0) return side(F, 0.0, 1.0, 1.0, abs_tol);
    const double mu_c = std::sqrt(1.0 - eta * eta);
    Estimate<1> out = side(F, mu_c, mu_c, -1.0, 0.5 * abs_tol);
    add(out, side(F, mu_c, 1.0 - mu_c, 1.0, 0.5 * abs_tol));
    return out;
}

Estimate<1> fresnel_dielectric_average_mc(double eta, long long samples, std::uint64_t seed) {
    return average_mc([eta](double mu) { return fresnel_dielectric(mu, eta); }, samples, seed);
}

Estimate<1> fresnel_conductor_average_mc(double eta, double k, FresnelForm form,
                                         long long samples, std::uint64_t seed) {
    return average_mc([=](double mu) { return fresnel_conductor(mu, eta, k, form); }, samples,
                      seed);
}

}  // namespace brdflut
