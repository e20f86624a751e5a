#include "brdflut/beckmann.h"

#include <algorithm>
#include <cmath>

namespace brdflut {

double Beckmann::lambda_of_a(double a) {
    if (!(a > 0.0)) return HUGE_VAL;
    // Past a = 27 exp(-a^2) and erfc(a) underflow (Lambda < 1e-300).
    if (a > 27.0) return 0.0;
    constexpr double kInvSqrtPi = 0.56418958354775628694807945156077259;
    return 0.5 * (std::exp(-a * a) * kInvSqrtPi / a - std::erfc(a));
}

namespace {
// Lambda of the view direction, which every wi of one view's integrals
// shares: the last one computed on this thread, recomputed when alpha or
// mu_o changes. The same value as Beckmann::lambda(mu_o), at the cost of one
// erfc per view instead of one per evaluation.
double view_lambda(const Beckmann& b, double mu_o) {
    return per_cosine(b.alpha, mu_o, [&] { return b.lambda(mu_o); });
}
}  // namespace

double Beckmann::brdf(const Vec3& wo, const Vec3& wi, Visibility vis) const {
    if (!(wo.z > 0.0) || !(wi.z > 0.0)) return 0.0;
    const Vec3 h{wo.x + wi.x, wo.y + wi.y, wo.z + wi.z};
    const double t2 = (h.x * h.x + h.y * h.y) / (h.z * h.z);  // tan^2(theta_h)
    const double c2 = 1.0 / (1.0 + t2);                         // cos^2(theta_h)
    double g2;  // G2(wo.z, wi.z, vis), term for term
    if (vis == Visibility::schlick_smith) {
        g2 = G2(wo.z, wi.z, vis);
    } else {
        const double lo = view_lambda(*this, wo.z), li = lambda(wi.z);
        g2 = vis == Visibility::separable ? (1.0 / (1.0 + lo)) * (1.0 / (1.0 + li)) : 1.0 / (1.0 + lo + li);
    }
    return D_from_tan2(t2, c2) * g2 / (4.0 * wo.z * wi.z);
}

double Beckmann::brdf_v_cavity(const Vec3& wo, const Vec3& wi) const {
    if (!(wo.z > 0.0) || !(wi.z > 0.0)) return 0.0;
    const Vec3 h{wo.x + wi.x, wo.y + wi.y, wo.z + wi.z};  // not normalized: G takes a ratio
    const double t2 = (h.x * h.x + h.y * h.y) / (h.z * h.z);
    const double c2 = 1.0 / (1.0 + t2);
    const double o_h = dot(wo, h);
    const double g = std::min(1.0, 2.0 * h.z * std::min(wo.z, wi.z) / o_h);
    return D_from_tan2(t2, c2) * g / (4.0 * wo.z * wi.z);
}

Vec3 Beckmann::sample_normal(double u1, double u2) const {
    const double t2 = -alpha * alpha * std::log1p(-u1);
    const double c = 1.0 / std::sqrt(1.0 + t2);
    const double s = std::sqrt(t2) * c;
    const double phi = kTwoPi * u2;
    return {s * std::cos(phi), s * std::sin(phi), c};
}

}  // namespace brdflut

namespace brdflut {

LobeHints BeckmannLobe::hints(const Vec3& wo) const { return microfacet_reflection_hints(wo, model_.alpha); }

LobeSample BeckmannLobe::sample(const Vec3& wo, double u1, double u2) const {
    LobeSample s;
    const Vec3 m = model_.sample_normal(u1, u2);
    const double o_m = dot(wo, m);
    if (!(o_m > 0.0)) return s;
    s.wi = {2.0 * o_m * m.x - wo.x, 2.0 * o_m * m.y - wo.y, 2.0 * o_m * m.z - wo.z};
    const double t2 = (m.x * m.x + m.y * m.y) / (m.z * m.z);
    s.pdf = model_.D_from_tan2(t2, m.z * m.z) * m.z / (4.0 * o_m);
    return s;
}

}  // namespace brdflut
