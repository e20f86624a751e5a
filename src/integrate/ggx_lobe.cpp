// GGX as a generic lobe, and its moments over the half vector (ggx_lobe.h).
#include "brdflut/ggx_lobe.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "brdflut/quadrature.h"

namespace brdflut {

double ggx_D_along(double alpha, const Vec3& m) {
    const double t2 = (m.x * m.x + m.y * m.y) / (m.z * m.z);
    const double a2 = alpha * alpha, c2 = 1.0 / (1.0 + t2), d = a2 + t2;
    return a2 / (kPi * c2 * c2 * d * d);
}

double GgxLobe::f(const Vec3& wo, const Vec3& wi) const {
    if (!(wo.z > 0.0) || !(wi.z > 0.0)) return 0.0;
    const Vec3 h{wo.x + wi.x, wo.y + wi.y, wo.z + wi.z};
    const double g = kind_ == GgxLobeKind::vndf ? ggx_.G1(wo.z) : ggx_.G2(wo.z, wi.z, vis_);
    return ggx_D_along(ggx_.alpha, h) * g / (4.0 * wo.z * wi.z);
}

LobeHints GgxLobe::hints(const Vec3& wo) const {
    return microfacet_reflection_hints(wo, ggx_.alpha);
}

LobeSample GgxLobe::sample(const Vec3& wo, double u1, double u2) const {
    LobeSample s;
    if (!(wo.z > 0.0)) return s;
    if (kind_ == GgxLobeKind::vndf) {
        // Visible normals: the estimate of a moment is then the weight itself.
        const Vec3 m = ggx_.sample_visible_normal(wo, u1, u2);
        const double o_m = dot(wo, m);
        if (!(o_m > 0.0)) return s;
        s.wi = {2.0 * o_m * m.x - wo.x, 2.0 * o_m * m.y - wo.y, 2.0 * o_m * m.z - wo.z};
        // Density G1(mu_o) (wo.m) D(m) / mu_o over dw_i = 4 (wo.m) dm.
        // D from m's components, as f has it (from cos(theta_m) it would lose
        // digits to 1 - cos^2 at small alpha).
        s.pdf = ggx_.G1(wo.z) * ggx_D_along(ggx_.alpha, m) / (4.0 * wo.z);
        return s;
    }
    // A defensive mixture: half the draws reflect normals from D cos(theta_m)
    // (tan^2(theta_m) = alpha^2 u / (1 - u)), half are cosine weighted. The
    // density is at least half of each, so the estimate is bounded where f
    // peaks and the tail of D (a share alpha^2 of the normals, which the
    // first half alone would almost never draw at small alpha) is sampled
    // too: the standard error then covers what it estimates. (Visible
    // normals alone would make the estimate G2 / G1(mu_o), 1 but for rare
    // draws below the horizon.)
    const double a2 = ggx_.alpha * ggx_.alpha;
    if (u1 < 0.5) {
        const double u = 2.0 * u1;
        const double t2 = a2 * u / (1.0 - u);
        const double cos_m = 1.0 / std::sqrt(1.0 + t2), sin_m = std::sqrt(t2) * cos_m, phi = kTwoPi * u2;
        const Vec3 m{sin_m * std::cos(phi), sin_m * std::sin(phi), cos_m};
        const double o_m = dot(wo, m);
        if (!(o_m > 0.0)) return s;
        s.wi = {2.0 * o_m * m.x - wo.x, 2.0 * o_m * m.y - wo.y, 2.0 * o_m * m.z - wo.z};
    } else {
        const double u = 2.0 * u1 - 1.0, r = std::sqrt(u), phi = kTwoPi * u2;
        s.wi = {r * std::cos(phi), r * std::sin(phi), std::sqrt(1.0 - u)};
    }
    if (!(s.wi.z > 0.0)) return s;
    // The density of wi under each half; D cos(theta_m) from the components
    // of the half vector (from cos(theta_m) it would lose digits to
    // 1 - cos^2 at small alpha).
    const Vec3 h{wo.x + s.wi.x, wo.y + s.wi.y, wo.z + s.wi.z};
    const double hl = std::sqrt(dot(h, h)), o_h = dot(wo, h) / hl;
    const double p_normals = o_h > 0.0 ? ggx_D_along(ggx_.alpha, h) * (h.z / hl) / (4.0 * o_h) : 0.0;
    s.pdf = 0.5 * p_normals + 0.5 * s.wi.z * kInvPi;
    return s;
}

template <std::size_t N>
std::array<double, N> ggx_moments_half_vector(double mu_o, double alpha, Visibility vis, GgxLobeKind kind,
                                              const std::array<MomentWeight, N>& weights, double abs_tol) {
    std::array<double, N> total{};
    mu_o = std::clamp(mu_o, kGenericGrazingMu, 1.0);
    const Ggx ggx{alpha};
    const double sin_o = std::sqrt((1.0 - mu_o) * (1.0 + mu_o));
    const double g_o = ggx.G1(mu_o);
    AdaptiveOptions inner;
    inner.abs_tol = 0.1 * abs_tol;
    inner.max_intervals = 300;
    inner.rule = KronrodRule::k21;
    AdaptiveOptions outer = inner;
    outer.abs_tol = 0.25 * abs_tol;
    // The azimuth integral at t = tan(theta_h), per unit u: phi over [0,
    // phi_max] (doubled for the other half), mu_i = 2 c^2 (o_h / c) - mu_o.
    auto ring = [&](double t) -> std::array<double, N> {
        std::array<double, N> out{};
        if (!std::isfinite(t)) return out;
        const double c2 = 1.0 / (1.0 + t * t), c = std::sqrt(c2);
        double phi_max = kPi;
        if (sin_o * t > 0.0) {
            const double cos_max = mu_o * (t * t - 1.0) / (2.0 * sin_o * t);
            if (cos_max >= 1.0) return out;
            if (cos_max > -1.0) phi_max = std::acos(cos_max);
        } else if (!(t < 1.0)) {
            return out;
        }
        auto integrand = [&](double phi) -> std::array<double, N> {
            std::array<double, N> v{};
            const double oh_over_c = sin_o * t * std::cos(phi) + mu_o;
            const double mu_i = 2.0 * c2 * oh_over_c - mu_o;
            if (!(mu_i > 0.0)) return v;
            const double o_h = std::min(oh_over_c * c, 1.0);
            const double g = kind == GgxLobeKind::vndf ? g_o : ggx.G2(mu_o, mu_i, vis);
            const double base = g * oh_over_c / (mu_o * kPi);
            for (std::size_t k = 0; k < N; ++k) v[k] = base * weights[k](o_h);
            return v;
        };
        // The weight's features at small v.h (a dielectric Fresnel of a
        // large index turns within v.h ~ 1/n) sit next to the clip, where v.h
        // is smallest (mu_o / (2c) at mu_i = 0): panels end where v.h is
        // that plus 10^-k, k = 1..12, so that no feature down to that scale
        // falls between the rule's nodes.
        std::vector<double> cuts{0.0};
        if (phi_max < kPi && sin_o * t > 0.0) {
            const double oh_min = mu_o / (2.0 * c);
            for (int k = 1; k <= 12; ++k) {
                const double cp = ((oh_min + std::pow(10.0, -k)) / c - mu_o) / (sin_o * t);
                if (cp < 1.0 && cp > -1.0) {
                    const double phi = std::acos(cp);
                    if (phi > cuts.back() && phi < phi_max) cuts.push_back(phi);
                }
            }
        }
        cuts.push_back(phi_max);
        std::array<double, N> sum{};
        for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
            const auto e = integrate_adaptive<N>(integrand, cuts[i], cuts[i + 1], inner);
            for (std::size_t k = 0; k < N; ++k) sum[k] += e.value[k];
        }
        return sum;
    };
    auto add = [&](const Estimate<N>& e) {
        for (std::size_t k = 0; k < N; ++k) total[k] += e.value[k];
    };
    // t where the clip starts (t_a = mu_o / (1 + sin_o)) and where nothing is
    // left (t_b = (1 + sin_o) / mu_o). [0, t_a] in u = u_a (1 - (1 - s)^2),
    // flat at u_a; [t_a, t_b] in ln(t) through a smoothstep, flat at both
    // ends (du = 2 alpha^2 t^2 / (alpha^2 + t^2)^2 dln(t)).
    const double a2 = alpha * alpha;
    const double t_a = mu_o / (1.0 + sin_o), t_b = (1.0 + sin_o) / mu_o;
    const double u_a = t_a * t_a / (a2 + t_a * t_a);
    add(integrate_adaptive<N>(
        [&](double s) {
            const double r = 1.0 - s, u = u_a * (1.0 - r * r);
            std::array<double, N> v = ring(alpha * std::sqrt(u / (1.0 - u)));
            for (double& x : v) x *= 2.0 * u_a * r;
            return v;
        },
        0.0, 1.0, outer));
    if (t_b > t_a) {
        const double v_a = std::log(t_a), len = std::log(t_b) - v_a;
        add(integrate_adaptive_panels<N>(
            [&](double s) {
                const double t = std::exp(v_a + len * s * s * (3.0 - 2.0 * s));
                const double d = a2 + t * t;
                std::array<double, N> v = ring(t);
                for (double& x : v) x *= 2.0 * a2 * t * t / (d * d) * len * 6.0 * s * (1.0 - s);
                return v;
            },
            0.0, 1.0, std::max(1, static_cast<int>(std::ceil(len))), outer));
    }
    return total;
}

template std::array<double, 1> ggx_moments_half_vector<1>(double, double, Visibility, GgxLobeKind,
                                                          const std::array<MomentWeight, 1>&, double);
template std::array<double, 2> ggx_moments_half_vector<2>(double, double, Visibility, GgxLobeKind,
                                                          const std::array<MomentWeight, 2>&, double);
template std::array<double, 3> ggx_moments_half_vector<3>(double, double, Visibility, GgxLobeKind,
                                                          const std::array<MomentWeight, 3>&, double);

}  // namespace brdflut
