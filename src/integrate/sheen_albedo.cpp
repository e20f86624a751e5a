// Quadrature and Monte Carlo estimates of the Charlie sheen albedo.
//
// Quadrature. With dw_i = 4 (wo.h) dw_h,
//
//   E = integral of [D(h) cos(theta_h) dw_h] g(h),   g = 4 V mu_i (wo.h) / cos(theta_h),
//
// and with u = sin(theta_h) the bracket is (2 + 1/alpha) u^(1 + 1/alpha) du dphi / (2 pi).
// The reflected direction stays above the horizon, mu_i = 2 (wo.h) cos(theta_h) - mu_o > 0,
// exactly when tan(theta_h) < t_max(phi), the positive root of
// mu_o t^2 - 2 sin(theta_o) cos(phi) t - mu_o = 0. With n = 2 + 1/alpha and
// u = u_max v^(1/n) the measure becomes u_max^n dv: uniform in v, so the
// distribution's peak at grazing microfacets (large n) needs no special care:
//
//   E = (1/pi) integral over phi in [0, pi] of u_max(phi)^n integral over v in [0, 1] of g dv.
//
// Both integrals use adaptive Gauss-Kronrod (7, 15), the inner one to a
// tolerance divided by its weight u_max^n; v(s) with dv/ds = 105 s^2 (1 - s)^4
// smooths both ends (g ~ 1/cos(theta_h) at u = 1 when mu_o = 0, and
// u ~ v^(1/n) at v = 0).
#include <cmath>

#include "brdflut/random.h"
#include "brdflut/sheen.h"
#include "brdflut/sheen_integrals.h"

namespace brdflut {
namespace {

// tan(theta_h) beyond which the reflection of wo leaves the hemisphere, in
// the form without cancellation for either sign of cos(phi).
double tan_max(double mu_o, double sin_o, double cos_phi) {
    const double b = sin_o * cos_phi;
    const double r = std::sqrt(b * b + mu_o * mu_o);
    return b >= 0.0 ? (b + r) / mu_o : mu_o / (r - b);
}

}  // namespace

Estimate<1> sheen_charlie_albedo(double mu_o, double alpha, double abs_tol) {
    Estimate<1> out;
    if (!(alpha > 0.0)) return out;  // the lobe vanishes
    mu_o = clamp01(mu_o);
    const double sin_o = safe_sqrt(1.0 - mu_o * mu_o);
    const double n = 2.0 + 1.0 / alpha;

    // g = 4 V mu_i (wo.h) / cos(theta_h) at u = sin(theta_h), given 1 - u
    // separately (cos(theta_h) = sqrt((1 - u)(1 + u)) without cancellation).
    auto g = [&](double u, double one_minus_u, double cos_phi) {
        const double cos_h = safe_sqrt(one_minus_u * (1.0 + u));
        if (!(cos_h > 0.0)) return 0.0;
        const double o_h = sin_o * u * cos_phi + mu_o * cos_h;
        const double mu_i = 2.0 * o_h * cos_h - mu_o;
        if (mu_i <= 0.0) return 0.0;
        return 4.0 * neubelt_visibility(mu_o, mu_i) * mu_i * o_h / cos_h;
    };

    AdaptiveOptions outer_opt;
    outer_opt.abs_tol = 0.5 * abs_tol;
    outer_opt.controlled = 1;

    // Weighted inner integral at phi: {u_max^n * integral of g dv, its error}.
    auto over_u = [&](double phi) -> std::array<double, 2> {
        const double cos_phi = std::cos(phi);
        const double t = mu_o > 0.0 ? tan_max(mu_o, sin_o, cos_phi) : (cos_phi > 0.0 ? HUGE_VAL : 0.0);
        const double root = std::sqrt(1.0 + t * t);
        const double u_max = t == HUGE_VAL ? 1.0 : t / root;
        const double one_minus_u_max = t == HUGE_VAL ? 0.0 : 1.0 / (root * (root + t));
        const double weight = std::pow(u_max, n);
        if (!(weight > 0.0)) return {0.0, 0.0};
        // The weighted error is what counts: a small weight allows a looser inner tolerance.
        AdaptiveOptions inner_opt;
        inner_opt.abs_tol = 0.1 * abs_tol / weight;
        const Estimate<1> in = integrate_adaptive<1>(
            [&](double s) -> std::array<double, 1> {
                // v = integral of 105 t^2 (1 - t)^4 dt over [0, s]; w = 1 - v,
                // each from its own polynomial where it is small.
                const double r = 1.0 - s;
                const double v_poly = s * s * s * (35.0 + s * (-105.0 + s * (126.0 + s * (-70.0 + 15.0 * s))));
                const double w_poly = sqr(sqr(r)) * r * (21.0 + r * (-35.0 + 15.0 * r));
                const double v = s < 0.5 ? v_poly : 1.0 - w_poly;
                const double w = s < 0.5 ? 1.0 - v_poly : w_poly;
                const double dv = 105.0 * s * s * sqr(sqr(r));
                if (!(v > 0.0)) return {0.0};
                const double e = -std::expm1(std::log1p(-w) / n);  // 1 - v^(1/n)
                const double u = u_max * (1.0 - e);
                return {g(u, one_minus_u_max + u_max * e, cos_phi) * dv};
            },
            0.0, 1.0, inner_opt);
        return {weight * in.value[0], weight * in.error[0]};
    };

    // At mu_o = 0 nothing is reflected for cos(phi) < 0: stop at the jump.
    const double phi_end = mu_o > 0.0 ? kPi : 0.5 * kPi;
    const Estimate<2> e = integrate_adaptive<2>(over_u, 0.0, phi_end, outer_opt);
    out.value[0] = e.value[0] * kInvPi;
    out.error[0] = (e.error[0] + e.value[1]) * kInvPi;
    out.evaluations = e.evaluations;
    return out;
}

// Monte Carlo, independent of the quadrature: wi from an equal mixture of
// the uniform hemisphere (density 1/(2 pi)) and the reflection of a normal
// drawn from D cos(theta_h) (density D cos(theta_h) / (4 wo.h) in wi); the
// BRDF is evaluated pointwise (charlie_sheen_brdf). Weight f mu_i / pdf(wi).
Estimate<1> sheen_charlie_albedo_mc(double mu_o, double alpha, long long samples, std::uint64_t seed) {
    Estimate<1> out;
    if (!(alpha > 0.0)) return out;
    const Charlie charlie{alpha};
    const Vec3 wo = direction_from_mu(clamp01(mu_o));
    Rng rng(seed, 2);
    MeanAccumulator<1> acc;
    for (long long s = 0; s < samples; ++s) {
        const double pick = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
        const double phi = kTwoPi * u2;
        Vec3 wi;
        if (pick < 0.5) {
            const double z = 1.0 - u1;  // uniform in (0, 1]
            const double r = safe_sqrt(1.0 - z * z);
            wi = {r * std::cos(phi), r * std::sin(phi), z};
        } else {
            const double sin_h = charlie.sample_sin_theta(u1);
            const double cos_h = safe_sqrt(1.0 - sin_h * sin_h);
            const Vec3 h{sin_h * std::cos(phi), sin_h * std::sin(phi), cos_h};
            const double o_h = dot(wo, h);
            wi = {2.0 * o_h * h.x - wo.x, 2.0 * o_h * h.y - wo.y, 2.0 * o_h * h.z - wo.z};
        }
        double w = 0.0;
        if (wi.z > 0.0) {
            const Vec3 sum{wo.x + wi.x, wo.y + wi.y, wo.z + wi.z};
            const double len = std::sqrt(dot(sum, sum));
            const double cos_h = sum.z / len;
            const double o_h = dot(wo, sum) / len;
            const double pdf_charlie = o_h > 0.0 ? charlie.D(cos_h) * cos_h / (4.0 * o_h) : 0.0;
            const double pdf = 0.5 / kTwoPi + 0.5 * pdf_charlie;
            w = charlie_sheen_brdf(charlie, wo, wi) * wi.z / pdf;
        }
        acc.add(&w);
    }
    return acc.estimate();
}

}  // namespace brdflut
