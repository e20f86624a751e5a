// Quadrature and Monte Carlo estimates of the dipole's reflectance.
//
// Quadrature. With r = z_r x / (1 - x), dr = z_r / (1 - x)^2 dx, the integrand
// 2 pi r R_d(r) becomes a smooth function of x on [0, 1): it vanishes like x
// at 0 and, without absorption, R_d ~ 1/r^3 so 2 pi r R_d dr tends to a
// finite limit as x -> 1; with absorption it decays to 0 there. The range is
// split where the real (r = z_r, x = 1/2) and virtual (r = z_v) sources stop
// looking like points.
#include "brdflut/dipole_integrals.h"

#include <cmath>
#include <vector>

#include "brdflut/math.h"
#include "brdflut/random.h"

namespace brdflut {

Estimate<1> dipole_reflectance_quadrature(const Dipole& d, double r_max, double abs_tol) {
    Estimate<1> out;
    if (!(r_max > 0.0)) return out;
    const double z = d.z_r();
    auto f = [&](double x) -> std::array<double, 1> {
        if (x >= 1.0) {
            // Limit x -> 1 (r -> infinity). With absorption the integrand vanishes;
            // without, 2 pi r R_d -> (a'/2)(z_r + z_v)/r^2 and times dr/dx this
            // tends to (a'/2)(z_r + z_v)/z_r. (The Kronrod nodes never reach x = 1.)
            if (d.sigma_tr() > 0.0) return {0.0};
            return {0.5 * d.albedo() * (d.z_r() + d.z_v()) / z};
        }
        const double r = z * x / (1.0 - x);
        const double jac = z / sqr(1.0 - x);
        return {kTwoPi * r * d.profile(r) * jac};
    };
    const double x_max = std::isinf(r_max) ? 1.0 : r_max / (r_max + z);
    std::vector<double> breaks{0.0};
    for (double rb : {z, d.z_v()}) {
        const double xb = rb / (rb + z);
        if (xb > breaks.back() && xb < x_max) breaks.push_back(xb);
    }
    breaks.push_back(x_max);
    AdaptiveOptions opt;
    opt.abs_tol = abs_tol / static_cast<double>(breaks.size() - 1);
    opt.max_intervals = 2000;
    for (std::size_t p = 0; p + 1 < breaks.size(); ++p) {
        const Estimate<1> e = integrate_adaptive<1>(f, breaks[p], breaks[p + 1], opt);
        out.value[0] += e.value[0];
        out.error[0] += e.error[0];
        out.evaluations += e.evaluations;
    }
    return out;
}

Estimate<1> dipole_total_reflectance_mc(const Dipole& d, long long samples, std::uint64_t seed) {
    Rng rng(seed, 2);
    MeanAccumulator<1> acc;
    const double z1 = d.z_r(), z2 = d.z_v();
    auto pdf = [](double r, double z) { return z / sqr(r + z); };
    for (long long s = 0; s < samples; ++s) {
        // Pick a component, then invert its CDF r / (r + z): r = z u / (1 - u).
        const double z = rng.uniform() < 0.5 ? z1 : z2;
        const double u = rng.uniform();
        const double r = z * u / (1.0 - u);
        const double p = 0.5 * (pdf(r, z1) + pdf(r, z2));
        const double w = kTwoPi * r * d.profile(r) / p;
        acc.add(&w);
    }
    return acc.estimate();
}

}  // namespace brdflut
