// Quadrature and Monte Carlo estimates of the GGX split-sum integrals.
//
// Quadrature. Substituting the half vector h for wi (dw_i = 4 (wo.h) dw_h):
//
//   integral of f cos(theta_i) dw_i = integral of D(h) G2 (wo.h) / mu_o dw_h.
//
// With t = tan(theta_h) and x = ln(t / alpha), the measure D cos(theta_h) dw_h
// becomes (1/2) sech^2(x) dx dphi / (2 pi): the GGX distribution is a smooth
// bump of unit width in x whatever alpha is, so the integrand has no boundary
// layers left for small alpha. The reflected direction stays above the
// horizon exactly when cos(phi) > c(t) = -mu_o (1 - t^2) / (2 t sin(theta_o)):
//   t <= t_a = mu_o / (1 + sin(theta_o))   every phi    (full circle)
//   t_a < t < t_b = (1 + sin(theta_o)) / mu_o   |phi| < acos(c(t))
//   t >= t_b                                      none.
// Both phi and x are integrated with adaptive Gauss-Kronrod, split at t_a;
// inside the clipped band the x substitution is made smooth at both ends
// (the phi integral behaves like (t - t_a)^(3/2) there).
#include "brdflut/ggx_integrals.h"

#include <cmath>
#include <vector>

#include "integrate/reflection_clip.h"

namespace brdflut {
namespace {

// Upper end of the x range: beyond it the weight 2 e^(-2x), against an
// integrand that grows at most like e^x, leaves less than 1e-15.
constexpr double kHighX = 36.0;

struct SplitSumIntegrand {
    Ggx ggx;
    Visibility vis;
    double mu_o, sin_o;
    double lambda_o;  // hoisted: Lambda(mu_o) is the same for every h

    // Integrand over phi at fixed t = tan(theta_h), without the 1/pi
    // normalization (applied by the caller): {A, B} parts.
    std::array<double, 2> at(double t, double cos_phi) const {
        const double cos_h = 1.0 / std::sqrt(1.0 + t * t);
        const double sin_h = t * cos_h;
        const double o_h = sin_o * sin_h * cos_phi + mu_o * cos_h;
        const double mu_i = 2.0 * o_h * cos_h - mu_o;
        if (mu_i <= 0.0 || o_h <= 0.0) return {0.0, 0.0};
        const double g2 = vis != Visibility::height_correlated
                              ? ggx.G2(mu_o, mu_i, vis)
                              : 1.0 / (1.0 + lambda_o + ggx.lambda(mu_i));
        // (wo.h) / (mu_o cos(theta_h)) = (sin_o t cos(phi) + mu_o) / mu_o
        const double v = g2 * (sin_o * t * cos_phi + mu_o) / mu_o;
        const double fc = schlick_weight(o_h);
        return {v - v * fc, v * fc};
    }
};

}  // namespace

Estimate<2> ggx_split_sum(double mu_o, double alpha, Visibility vis, double abs_tol) {
    Estimate<2> out;
    if (!(mu_o > 0.0)) return out;  // grazing limit: no light reflected
    if (mu_o > 1.0) mu_o = 1.0;
    if (!(alpha > 0.0)) {            // mirror limit
        const double fc = schlick_weight(mu_o);
        out.value = {1.0 - fc, fc};
        return out;
    }
    const double sin_o = safe_sqrt(1.0 - mu_o * mu_o);
    const Ggx ggx{alpha};
    const SplitSumIntegrand f{ggx, vis, mu_o, sin_o, ggx.lambda(mu_o)};
    const double ln_alpha = std::log(alpha);

    // (1/2) sech^2(x) / pi: the measure in x times the phi normalization,
    // with phi integrated over [0, pi] only (the integrand is even in phi).
    auto weight = [](double x) {
        const double c = std::cosh(x);
        return 0.5 / (c * c) * kInvPi;
    };

    AdaptiveOptions inner_opt;
    inner_opt.abs_tol = 0.1 * abs_tol;
    AdaptiveOptions outer_opt;
    outer_opt.abs_tol = 0.5 * abs_tol;
    outer_opt.controlled = 2;

    // Integral over phi in [0, phi_max] at fixed t: {A, B, error estimate}.
    auto over_phi = [&](double t, double phi_max) -> std::array<double, 3> {
        if (phi_max >= kPi) {
            // Full circle: the integrand is smooth, even and 2 pi periodic in
            // phi, so the trapezoidal rule converges exponentially; double
            // the nodes until two successive sums agree.
            auto sample = [&](double phi) { return f.at(t, std::cos(phi)); };
            std::array<double, 2> ends = sample(0.0), mid = sample(kPi);
            std::array<double, 2> sum{0.5 * (ends[0] + mid[0]), 0.5 * (ends[1] + mid[1])};
            std::array<double, 2> prev{HUGE_VAL, HUGE_VAL};
            for (int n = 1; n <= 4096; n *= 2) {
                // Add the nodes (2k + 1) pi / (2n), halving the step to pi / (2n).
                for (int k = 0; k < n; ++k) {
                    const std::array<double, 2> y = sample((2 * k + 1) * kPi / (2.0 * n));
                    sum[0] += y[0];
                    sum[1] += y[1];
                }
                const double h = kPi / (2.0 * n);
                const std::array<double, 2> cur{sum[0] * h, sum[1] * h};
                const double err = std::abs(cur[0] - prev[0]) + std::abs(cur[1] - prev[1]);
                if (n >= 4 && err <= inner_opt.abs_tol) return {cur[0], cur[1], err};
                prev = cur;
            }
            return {prev[0], prev[1], inner_opt.abs_tol};
        }
        const Estimate<2> in = integrate_adaptive<2>(
            [&](double phi) { return f.at(t, std::cos(phi)); }, 0.0, phi_max, inner_opt);
        return {in.value[0], in.value[1], in.error[0] + in.error[1]};
    };

    // Outer integrand in x, weighted: {A, B, accumulated inner error}.
    auto outer = [&](double x, bool clipped) -> std::array<double, 3> {
        const double t = alpha * std::exp(x);
        double phi_max = kPi;
        if (clipped) {
            phi_max = detail::reflection_phi_max(t, mu_o, sin_o);
            if (phi_max == 0.0) return {0.0, 0.0, 0.0};
        }
        std::array<double, 3> r = over_phi(t, phi_max);
        const double w = weight(x);
        for (double& v : r) v *= w;
        return r;
    };

    auto accumulate = [&](const Estimate<3>& e) {
        for (int c = 0; c < 2; ++c) {
            out.value[c] += e.value[c];
            out.error[c] += e.error[c] + e.value[2];
        }
        out.evaluations += e.evaluations;
    };

    // Full circle for t <= t_a (normal incidence: t_a = 1, nothing beyond).
    const detail::ReflectionBand band = detail::reflection_band(mu_o, sin_o);
    const double x_a = sin_o == 0.0 ? -ln_alpha : std::log(band.t_a) - ln_alpha;
    const double x_b = sin_o == 0.0 ? x_a : std::log(band.t_b) - ln_alpha;
    // Up to t = alpha (x = 0) integrate in xi = t^2 / (alpha^2 + t^2), where
    // the distribution's measure is uniform: dxi dphi / (2 pi).
    const double x_split = std::min(0.0, x_a);
    {
        const double e2 = std::exp(2.0 * x_split);
        const double xi_end = e2 / (1.0 + e2);
        accumulate(integrate_adaptive<3>(
            [&](double xi) -> std::array<double, 3> {
                const double t = alpha * std::sqrt(xi / (1.0 - xi));
                std::array<double, 3> r = over_phi(t, kPi);
                for (double& v : r) v *= kInvPi;
                return r;
            },
            0.0, xi_end, outer_opt));
    }
    if (x_a > x_split)
        accumulate(integrate_adaptive<3>([&](double x) { return outer(x, false); }, x_split,
                                         std::min(x_a, kHighX), outer_opt));
    const double p0 = x_a, p1 = std::min(x_b, kHighX);
    if (p1 > p0) {
        // x = p0 + (p1 - p0) s(u), s(u) = 3u^2 - 2u^3: smooth at both ends.
        const double len = p1 - p0;
        accumulate(integrate_adaptive<3>(
            [&](double u) {
                const double x = p0 + len * u * u * (3.0 - 2.0 * u);
                const double jac = len * 6.0 * u * (1.0 - u);
                std::array<double, 3> r = outer(x, true);
                for (double& v : r) v *= jac;
                return r;
            },
            0.0, 1.0, outer_opt));
    }
    return out;
}

Estimate<1> ggx_albedo_average(double alpha, Visibility vis, double abs_tol) {
    // E(mu) falls from about 1 to 0 where Lambda(mu) ~ 1, that is mu ~ alpha:
    // break the mu range geometrically from there so that no panel's nodes
    // can step over the drop.
    std::vector<double> breaks{0.0};
    for (double m = alpha; m < 1.0 && alpha > 0.0; m *= 4.0) breaks.push_back(m);
    breaks.push_back(1.0);
    const double panels = static_cast<double>(breaks.size() - 1);
    AdaptiveOptions opt;
    opt.abs_tol = 0.5 * abs_tol / panels;
    opt.controlled = 1;
    Estimate<1> out;
    for (std::size_t p = 0; p + 1 < breaks.size(); ++p) {
        const Estimate<2> e = integrate_adaptive<2>(
            [&](double mu) -> std::array<double, 2> {
                const Estimate<2> s = ggx_split_sum(mu, alpha, vis, 0.25 * abs_tol);
                return {2.0 * mu * (s.value[0] + s.value[1]), 2.0 * mu * (s.error[0] + s.error[1])};
            },
            breaks[p], breaks[p + 1], opt);
        out.value[0] += e.value[0];
        out.error[0] += e.error[0] + e.value[1];
        out.evaluations += e.evaluations;
    }
    return out;
}

}  // namespace brdflut
