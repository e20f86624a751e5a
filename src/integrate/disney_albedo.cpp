// Quadrature of the directional albedo of the Disney lobes.
//
// Diffuse and subsurface. With cos^2(theta_d) = (1 + wi.wo)/2 and
// wi.wo = mu_i mu_o + sin_i sin_o cos(phi), the grazing retro-reflection term
// F90 - 1 = m + d cos(phi) is linear in cos(phi), so the product
// (1 + X w_i)(1 + X w_o), w = (1 - mu)^5, averages over phi to
//   <F> = 1 + m (w_i + w_o) + (m^2 + d^2/2) w_i w_o,
// a polynomial in mu_i (degree 7). Then
//   E_d  = 2 * integral of <F_d> mu_i dmu_i                          (exact Gauss),
//   E_ss = 2.5 (integral of <F_ss> mu_i/(mu_i + mu_o) dmu_i
//               - (1/2) integral of <F_ss> mu_i dmu_i + 1/4),
// the first term integrated in v = ln(mu_i + mu_o), where it is smooth.
//
// Sheen. The lobe depends on wi only through wi.wo = 2 v^2 - 1, v = cos(theta_d).
// Integrating in polar coordinates about wo, dw_i = 4 v dv dphi', and the
// clipped cosine has a closed form over phi':
//   K(u) = integral over phi' of max(0, u mu_o + sqrt(1 - u^2) sin_o cos(phi'))
//        = 2 pi u mu_o                          u >= sin_o
//        = 2 (u mu_o phi_m + sqrt(sin_o^2 - u^2)),  phi_m = acos(-u mu_o/(sqrt(1-u^2) sin_o)),  |u| < sin_o
//        = 0                                    u <= -sin_o,
// so E = integral of (1 - v)^5 K(2 v^2 - 1) 4 v dv: a polynomial above
// v_b = sqrt((1 + sin_o)/2), a smooth function times (v - v_a)^(3/2) near the
// ends of [v_a, v_b] (removed by a smoothstep change of variable).
//
// Clearcoat. Over the half vector (dw_i = 4 (wo.h) dw_h):
//   E = integral of F_c G_c (wo.h) / (mu_o cos(theta_h)) D_c cos(theta_h) dw_h.
// The GTR1 measure D cos(theta_h) dw_h is uniform in
//   P = 1 - ln((t^2 + a^2)/(t^2 + 1)) / ln(a^2),  t = tan(theta_h),
// (times dphi / 2 pi), roughly ln(t) rescaled: the lobe is smooth in P for any
// alpha. The azimuth is clipped to the upper hemisphere as in the GGX
// integrals (reflection_clip.h): P covers the full circles below the clipped
// band t in (t_a, t_b); across the band the variable is ln(t), in which the
// clipped arc's end moves steadily at every view angle.
#include <cmath>

#include "brdflut/disney.h"
#include "brdflut/microfacet.h"
#include "integrate/lobe_albedo_detail.h"
#include "integrate/half_circle.h"
#include "integrate/reflection_clip.h"

namespace brdflut::detail {

namespace {

// <F> for F90 - 1 = m + d cos(phi): average over phi of (1 + X w_i)(1 + X w_o).
double schlick_pair_phi_average(double m, double d2, double w_i, double w_o) {
    return 1.0 + m * (w_i + w_o) + (m * m + 0.5 * d2) * w_i * w_o;
}

// Smoothstep s(u) = 3u^2 - 2u^3 and its derivative: maps [0, 1] onto itself
// with zero slope at both ends.
double smoothstep(double u) { return u * u * (3.0 - 2.0 * u); }
double smoothstep_slope(double u) { return 6.0 * u * (1.0 - u); }

// One Gauss-Kronrod (15, 31) panel on [-1, 1] for an integrand g that is even:
// 16 evaluations. Returns {integral over [0, 1], QUADPACK error estimate}.
template <class G>
std::array<double, 2> even_panel(G&& g) {
    using R = KronrodNodes<31>;
    double y[16];
    y[15] = g(0.0);
    for (std::size_t j = 0; j < 15; ++j) y[j] = g(R::x[j]);
    double k = R::wk[15] * y[15], gauss = R::wg[7] * y[15];
    for (std::size_t j = 0; j < 15; ++j) {
        k += 2.0 * R::wk[j] * y[j];
        if (j % 2 == 1) gauss += 2.0 * R::wg[j / 2] * y[j];
    }
    double asc = R::wk[15] * std::abs(y[15] - 0.5 * k);
    for (std::size_t j = 0; j < 15; ++j) asc += 2.0 * R::wk[j] * std::abs(y[j] - 0.5 * k);
    // The panel on [-1, 1] has half-width 1; [0, 1] carries half of it.
    return {0.5 * k, kronrod_error((k - gauss) * 0.5, 0.5 * asc, 0.5 * k)};
}

}  // namespace

Estimate<1> disney_diffuse_albedo(double mu_o, double roughness, double /*abs_tol*/) {
    mu_o = clamp01(mu_o);
    const double sin2_o = 1.0 - mu_o * mu_o, w_o = schlick_weight(mu_o);
    // F_D90 - 1 = -1/2 + r (1 + wi.wo)
    return exact_polynomial_integral(
        [&](double mu_i) {
            const double m = -0.5 + roughness * (1.0 + mu_i * mu_o);
            const double d2 = sqr(roughness) * (1.0 - mu_i * mu_i) * sin2_o;
            return std::array<double, 1>{2.0 * mu_i *
                                         schlick_pair_phi_average(m, d2, schlick_weight(mu_i), w_o)};
        },
        0.0, 1.0, 8);
}

Estimate<1> disney_subsurface_albedo(double mu_o, double roughness, double abs_tol) {
    mu_o = clamp01(mu_o);
    const double sin2_o = 1.0 - mu_o * mu_o, w_o = schlick_weight(mu_o);
    // F_ss90 - 1 = r (1 + wi.wo)/2 - 1
    auto f_ss = [&](double mu_i) {
        const double m = 0.5 * roughness * (1.0 + mu_i * mu_o) - 1.0;
        const double d2 = 0.25 * sqr(roughness) * (1.0 - mu_i * mu_i) * sin2_o;
        return schlick_pair_phi_average(m, d2, schlick_weight(mu_i), w_o);
    };
    const Estimate<1> plain = exact_polynomial_integral(
        [&](double mu_i) { return std::array<double, 1>{mu_i * f_ss(mu_i)}; }, 0.0, 1.0, 8);
    // mu_i in [0, delta] is left out of the v integral (v would reach -inf at
    // mu_o = 0); it adds at most 4 delta, counted in the error.
    constexpr double kDelta = 1e-14;
    AdaptiveOptions opt;
    opt.abs_tol = 0.2 * abs_tol;
    const Estimate<1> ratio = integrate_adaptive<1>(
        [&](double v) {
            const double mu_i = std::max(0.0, std::exp(v) - mu_o);
            return std::array<double, 1>{mu_i * f_ss(mu_i)};
        },
        std::log(mu_o + kDelta), std::log1p(mu_o), opt);
    Estimate<1> out;
    out.value[0] = 2.5 * (ratio.value[0] - 0.5 * plain.value[0] + 0.25);
    out.error[0] = 2.5 * (ratio.error[0] + 4.0 * kDelta + 0.5 * plain.error[0]);
    out.evaluations = ratio.evaluations + plain.evaluations;
    return out;
}

Estimate<1> disney_sheen_albedo(double mu_o, double abs_tol) {
    mu_o = clamp01(mu_o);
    const double sin_o = safe_sqrt(1.0 - mu_o * mu_o);
    // v_a = sqrt((1 - sin_o)/2) with 1 - sin_o = mu_o^2 / (1 + sin_o).
    const double v_a = std::sqrt(0.5 * mu_o * mu_o / (1.0 + sin_o));
    const double v_b = std::sqrt(0.5 * (1.0 + sin_o));
    // Unclipped part: K = 2 pi u mu_o.
    Estimate<1> out = exact_polynomial_integral(
        [&](double v) {
            const double u = 2.0 * v * v - 1.0;
            return std::array<double, 1>{schlick_weight(v) * kTwoPi * u * mu_o * 4.0 * v};
        },
        v_b, 1.0, 8);
    if (v_b > v_a) {
        auto clipped = [&](double v) {
            const double u = 2.0 * v * v - 1.0;
            const double b = safe_sqrt(1.0 - u * u) * sin_o;
            if (b == 0.0) return 0.0;
            const double phi_m = std::acos(std::clamp(-u * mu_o / b, -1.0, 1.0));
            const double k = 2.0 * (u * mu_o * phi_m + safe_sqrt(sin_o * sin_o - u * u));
            return schlick_weight(v) * k * 4.0 * v;
        };
        const double len = v_b - v_a;
        AdaptiveOptions opt;
        opt.abs_tol = 0.5 * abs_tol;
        const Estimate<1> c = integrate_adaptive<1>(
            [&](double s) {
                return std::array<double, 1>{clipped(v_a + len * smoothstep(s)) * len *
                                             smoothstep_slope(s)};
            },
            0.0, 1.0, opt);
        out.value[0] += c.value[0];
        out.error[0] += c.error[0];
        out.evaluations += c.evaluations;
    }
    return out;
}

Estimate<1> disney_clearcoat_albedo(double mu_o, double gloss, double abs_tol) {
    Estimate<1> out;
    mu_o = std::min(mu_o, 1.0);
    if (!(mu_o > 0.0)) return out;  // G1(mu_o) = 0 on the horizon
    const double sin_o = safe_sqrt(1.0 - mu_o * mu_o);
    const double alpha = clearcoat_alpha(gloss);
    const double a2 = alpha * alpha, ln_a2 = std::log(a2);
    const Ggx masking{kClearcoatGeometryAlpha};
    const double g1_o = masking.G1(mu_o);
    const double ag2 = sqr(kClearcoatGeometryAlpha);

    // t = tan(theta_h) from P: t^2 = a^2 (a^(-2P) - 1) / (1 - a^(2(1 - P))).
    auto t_of_p = [&](double p) {
        return std::sqrt(a2 * std::expm1(-p * ln_a2) / -std::expm1((1.0 - p) * ln_a2));
    };
    auto p_of_t = [&](double t) { return 1.0 - std::log1p((a2 - 1.0) / (t * t + 1.0)) / ln_a2; };

    // What depends on t only, hoisted out of the phi integral.
    struct Ring {
        double a1, a0;     // wo.h = a1 cos(phi) + a0
        double two_cos_h;  // mu_i = two_cos_h (wo.h) - mu_o
        double b1;         // (wo.h) / (mu_o cos(theta_h)) = 1 + b1 cos(phi)
    };
    auto ring = [&](double t) {
        const double cos_h = 1.0 / std::sqrt(1.0 + t * t);
        return Ring{sin_o * t * cos_h, mu_o * cos_h, 2.0 * cos_h, sin_o * t / mu_o};
    };
    // Integrand at cos(phi) with respect to dP dphi / (2 pi), without 1/pi.
    // G1(mu_i) = 2 mu_i / (mu_i + sqrt(a_g^2 + (1 - a_g^2) mu_i^2)).
    auto at = [&](const Ring& q, double cos_phi) {
        const double o_h = q.a1 * cos_phi + q.a0;
        const double mu_i = q.two_cos_h * o_h - mu_o;
        if (mu_i <= 0.0 || o_h <= 0.0) return 0.0;
        const double f = kClearcoatF0 + (1.0 - kClearcoatF0) * schlick_weight(o_h);
        const double g1_i = 2.0 * mu_i / (mu_i + std::sqrt(ag2 + (1.0 - ag2) * mu_i * mu_i));
        return f * g1_o * g1_i * (1.0 + q.b1 * cos_phi);
    };

    // Error budget: 0.2 abs_tol for each outer range (two), 0.25 abs_tol for
    // the inner integrals each accumulates (their QUADPACK estimates jump by
    // orders of magnitude per refinement, so the share mostly decides how
    // often an inner panel passes). The inner tolerance at an outer node
    // is that budget over the node's weight times the range (so the weighted
    // inner errors integrate to at most the budget), capped.
    AdaptiveOptions outer_opt;
    outer_opt.abs_tol = 0.2 * abs_tol;
    outer_opt.controlled = 1;
    outer_opt.rule = KronrodRule::k31;
    const double inner_budget = 0.25 * abs_tol;
    constexpr double kMaxInnerTol = 1e-6;
    auto inner_tol = [&](double weight) {
        return weight * kMaxInnerTol > inner_budget ? inner_budget / weight : kMaxInnerTol;
    };

    // Integral over phi in [0, pi] (the integrand is even, smooth and
    // periodic: doubling trapezoid): {value, error estimate}.
    auto full_circle = [&](double t, double tol) -> std::array<double, 2> {
        const Ring q = ring(t);
        return trapezoid_half_circle<1>(
            [&](double cos_phi) { return std::array<double, 1>{at(q, cos_phi)}; }, tol);
    };
    // Integral over the clipped circle phi in [0, phi_max], cos(phi_max) = c in
    // (-1, 1), in s = tan(phi / 4): cos(phi) = (1 - 6 s^2 + s^4) / (1 + s^2)^2,
    // dphi = 4 ds / (1 + s^2), so the integrand is rational in s (no
    // trigonometric function) and s stays within [0, 1] for any phi_max <= pi,
    // s1 = tan(phi_max / 4) = sin(phi_max/2) / (1 + cos(phi_max/2)). Adaptive
    // (15, 31) over [0, s1]; short arcs (c >= kShortArc) first try one
    // symmetric panel over [-s1, s1] (the integrand is even in s: 16
    // evaluations), kept when its estimate is within tol. Longer arcs rarely
    // pass it: the G1(mu_i) factor has branch points near the arc's end.
    constexpr double kShortArc = 0.2;
    auto clipped_circle = [&](double t, double c, double tol) -> std::array<double, 2> {
        const Ring q = ring(t);
        const double s1 = std::sqrt(0.5 * (1.0 - c)) / (1.0 + std::sqrt(0.5 * (1.0 + c)));
        auto h = [&](double s) {
            const double s2 = s * s, d = 1.0 / (1.0 + s2);
            return 4.0 * d * at(q, (1.0 - s2 * (6.0 - s2)) * d * d);
        };
        if (c >= kShortArc) {
            const std::array<double, 2> r = even_panel([&](double v) { return s1 * h(s1 * v); });
            if (r[1] <= tol) return r;
        }
        AdaptiveOptions opt;
        opt.rule = KronrodRule::k31;
        opt.abs_tol = tol;
        const Estimate<1> e = integrate_adaptive<1>(
            [&](double s) { return std::array<double, 1>{h(s)}; }, 0.0, s1, opt);
        return {e.value[0], e.error[0]};
    };

    auto accumulate = [&](const Estimate<2>& e) {
        out.value[0] += e.value[0];
        out.error[0] += e.error[0] + e.value[1];
        out.evaluations += e.evaluations;
    };

    const ReflectionBand band = reflection_band(mu_o, sin_o);
    const double p_a = p_of_t(band.t_a);
    {
        const double tol = inner_tol(kInvPi * p_a);
        accumulate(integrate_adaptive<2>(
            [&](double p) -> std::array<double, 2> {
                const std::array<double, 2> r = full_circle(t_of_p(p), tol);
                return {r[0] * kInvPi, r[1] * kInvPi};
            },
            0.0, p_a, outer_opt));
    }
    if (sin_o > 0.0) {
        // Across the clipped band the variable is tau = ln(t): there
        // c(t) = (mu_o / sin_o) sinh(tau) and the band is tau in [-T, T],
        // T = ln(t_b), so the arc's end moves at a steady pace however wide
        // the band is (at grazing it spans t_b / t_a = ((1 + sin_o)/mu_o)^2,
        // which P crushes against its ends). The phi integral behaves like
        // (T -+ tau)^(3/2) at both ends; tau = -T + 2 T s(u) with the
        // smoothstep s flattens them. dP/dtau = 2 (1 - a^2) t^2 /
        // (|ln a^2| (t^2 + a^2)(t^2 + 1)).
        const double big_t = std::log(band.t_b);
        const double dp_scale = 2.0 * (1.0 - a2) / -ln_a2;
        auto band_integrand = [&](double u) -> std::array<double, 2> {
            const double t = std::exp(big_t * (2.0 * smoothstep(u) - 1.0));
            const double c = reflection_cos_phi_max(t, mu_o, sin_o);
            if (c >= 1.0) return {0.0, 0.0};
            const double t2 = t * t;
            const double w = 2.0 * big_t * smoothstep_slope(u) * dp_scale * t2 /
                             ((t2 + a2) * (t2 + 1.0)) * kInvPi;
            if (!(w > 0.0)) return {0.0, 0.0};
            const double tol = inner_tol(w);
            const std::array<double, 2> r = c > -1.0 ? clipped_circle(t, c, tol)
                                                     : full_circle(t, tol);
            return {r[0] * w, r[1] * w};
        };
        // Past T = 1.5 (mu_o below about 0.42) one panel over the band always
        // fails; starting from its two halves (split at tau = 0) saves it.
        accumulate(integrate_adaptive_panels<2>(band_integrand, 0.0, 1.0, big_t > 1.5 ? 2 : 1, outer_opt));
    }
    return out;
}

Estimate<1> disney_clearcoat_albedo_average(double gloss, double abs_tol) {
    const double alpha = clearcoat_alpha(gloss);
    const double a2 = alpha * alpha, ln_a2 = std::log(a2);
    const double ag2 = sqr(kClearcoatGeometryAlpha);
    auto g1 = [&](double mu) { return 2.0 * mu / (mu + std::sqrt(ag2 + (1.0 - ag2) * mu * mu)); };

    // Budget: 0.5 abs_tol for the outer integral over the half vector, 0.4
    // abs_tol for the (u, psi) integrals it accumulates; within those, 0.3 of
    // their tolerance for each range of u and 0.2 for the psi integrals of each.
    constexpr double kMaxTol = 1e-6;
    auto tol_for = [&](double budget, double weight) {
        return weight * kMaxTol > budget ? budget / weight : kMaxTol;
    };

    // K(u) = integral over psi of G1(A + B cos psi) G1(A - B cos psi), both
    // cosines positive, A = u cos_h, B = sqrt(1 - u^2) sin_h; {value, error}.
    auto ring = [&](double u, double cos_h, double sin_h, double tol) -> std::array<double, 2> {
        const double a = u * cos_h, b = safe_sqrt(1.0 - u * u) * sin_h;
        auto g = [&](double x) {
            const double mu_o = a + b * x, mu_i = a - b * x;
            if (mu_o <= 0.0 || mu_i <= 0.0) return 0.0;
            return g1(mu_o) * g1(mu_i);
        };
        if (a >= b) {  // the full circle: 2 * integral over [0, pi] (trapezoid)
            const std::array<double, 2> r = trapezoid_half_circle<1>(
                [&](double x) { return std::array<double, 1>{g(x)}; }, 0.5 * tol);
            return {2.0 * r[0], 2.0 * r[1]};
        }
        // |cos psi| < k = a / b: 4 * integral over psi' = pi/2 - psi in
        // [0, asin k] of g(sin psi'), even in psi'; in s = tan(psi'/2),
        // sin psi' = 2 s / (1 + s^2), s1 = k / (1 + sqrt(1 - k^2)).
        const double k = a / b, s1 = k / (1.0 + std::sqrt((1.0 - k) * (1.0 + k)));
        auto h = [&](double s) {
            const double d = 1.0 / (1.0 + s * s);
            return 2.0 * d * g(2.0 * s * d);
        };
        std::array<double, 2> r = even_panel([&](double v) { return s1 * h(s1 * v); });
        if (!(r[1] <= 0.25 * tol)) {
            AdaptiveOptions opt;
            opt.rule = KronrodRule::k31;
            opt.abs_tol = 0.25 * tol;
            const Estimate<1> e = integrate_adaptive<1>(
                [&](double s) { return std::array<double, 1>{h(s)}; }, 0.0, s1, opt);
            r = {e.value[0], e.error[0]};
        }
        return {4.0 * r[0], 4.0 * r[1]};
    };

    // I(theta_h) = integral over wo of F(u) u G1(mu_o) G1(mu_i), u = wo.h:
    // for u < sin_h the azimuth about h is clipped (K behaves like
    // (sin_h - u)^(3/2) there: u = sin_h (1 - (1 - v)^2) flattens it), for
    // u > sin_h it is the full circle.
    auto fresnel = [](double u) { return kClearcoatF0 + (1.0 - kClearcoatF0) * schlick_weight(u); };
    auto half_vector = [&](double cos_h, double sin_h, double tol) -> std::array<double, 2> {
        AdaptiveOptions opt;
        opt.abs_tol = 0.3 * tol;
        opt.controlled = 1;
        opt.rule = KronrodRule::k31;
        const double inner_budget = 0.2 * tol;
        std::array<double, 2> r{};
        auto add = [&](const Estimate<2>& e) {
            r[0] += e.value[0];
            r[1] += e.error[0] + e.value[1];
        };
        if (sin_h > 0.0) {
            add(integrate_adaptive<2>(
                [&](double v) -> std::array<double, 2> {
                    const double u = sin_h * v * (2.0 - v);
                    const double w = fresnel(u) * u * 2.0 * sin_h * (1.0 - v);
                    if (!(w > 0.0)) return {0.0, 0.0};
                    const std::array<double, 2> q = ring(u, cos_h, sin_h, tol_for(inner_budget, w));
                    return {w * q[0], w * q[1]};
                },
                0.0, 1.0, opt));
        }
        add(integrate_adaptive<2>(
            [&](double u) -> std::array<double, 2> {
                const double w = fresnel(u) * u;
                const std::array<double, 2> q =
                    ring(u, cos_h, sin_h, tol_for(inner_budget, w * (1.0 - sin_h)));
                return {w * q[0], w * q[1]};
            },
            sin_h, 1.0, opt));
        return r;
    };

    // E_avg = (1/pi) integral of f mu_i mu_o dw_i dw_o; with dw_i = 4 (wo.h) dw_h
    // and D cos(theta_h) dw_h = dP dphi_h / (2 pi) (P the GTR1 variable of
    // disney_clearcoat_albedo):
    //   E_avg = (1/pi) integral over P in [0, 1] of I(theta_h) / cos(theta_h),
    // taken in P = s(q), the smoothstep: I / cos(theta_h) goes like
    // cos(theta_h) ~ sqrt(1 - P) at P = 1, and I has odd powers of
    // sin(theta_h) ~ sqrt(P) at P = 0. A single (15, 31) panel over q never
    // passes: the integral starts from the two halves q < 1/2, q > 1/2.
    AdaptiveOptions outer_opt;
    outer_opt.abs_tol = 0.5 * abs_tol;
    outer_opt.controlled = 1;
    outer_opt.rule = KronrodRule::k31;
    const double mid_budget = 0.4 * abs_tol;
    auto integrand = [&](double q) -> std::array<double, 2> {
        const double p = smoothstep(q);
        const double t2 = a2 * std::expm1(-p * ln_a2) / -std::expm1((1.0 - p) * ln_a2);
        const double cos_h = 1.0 / std::sqrt(1.0 + t2), sin_h = std::sqrt(t2) * cos_h;
        const double w = smoothstep_slope(q) * kInvPi / cos_h;
        if (!(w > 0.0) || !(cos_h > 0.0)) return {0.0, 0.0};
        const std::array<double, 2> r = half_vector(cos_h, sin_h, tol_for(mid_budget, w));
        return {w * r[0], w * r[1]};
    };
    const Estimate<2> e = integrate_adaptive_panels<2>(integrand, 0.0, 1.0, 2, outer_opt);
    Estimate<1> out;
    out.value[0] = e.value[0];
    out.error[0] = e.error[0] + e.value[1];
    out.evaluations = e.evaluations;
    return out;
}

}  // namespace brdflut::detail
