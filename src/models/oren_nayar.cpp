#include "brdflut/oren_nayar.h"

#include <cmath>

namespace brdflut {

double OrenNayar::brdf(const Vec3& wo, const Vec3& wi) const {
    if (wo.z < 0.0 || wi.z <= 0.0) return 0.0;
    const double sin_o = safe_sqrt(1.0 - sqr(wo.z)), sin_i = safe_sqrt(1.0 - sqr(wi.z));
    double term = 0.0;
    if (sin_o > 0.0 && sin_i > 0.0) {
        const double cos_dphi = (wo.x * wi.x + wo.y * wi.y) / (sin_o * sin_i);
        // sin(alpha) tan(beta): alpha the larger angle, beta the smaller.
        const double sin_a_tan_b = wi.z < wo.z ? sin_i * sin_o / wo.z : sin_o * sin_i / wi.z;
        term = std::max(0.0, cos_dphi) * sin_a_tan_b;
    }
    return kInvPi * (A() + B() * term);
}

double FujiiOrenNayar::brdf(const Vec3& wo, const Vec3& wi) const {
    if (wo.z < 0.0 || wi.z <= 0.0) return 0.0;
    const double s = dot(wo, wi) - wo.z * wi.z;
    const double s_over_t = s > 0.0 ? s / std::max(wo.z, wi.z) : s;
    return kInvPi * A() * (1.0 + sigma * s_over_t);
}

double FujiiOrenNayar::albedo(double mu) const {
    mu = clamp01(mu);
    const double sin_t = safe_sqrt(1.0 - mu * mu);
    const double theta = std::acos(mu);
    // tan(theta)(1 - sin^3) = sin cos (1 + sin + sin^2) / (1 + sin), using
    // 1 - sin = cos^2 / (1 + sin): no cancellation at grazing angles.
    const double tan_term = sin_t * mu * (1.0 + sin_t + sin_t * sin_t) / (1.0 + sin_t);
    const double g = sin_t * (theta - sin_t * mu) + (2.0 / 3.0) * (tan_term - sin_t);
    return A() * (1.0 + sigma * kInvPi * g);
}

double Eon::multiple_scattering_brdf(double mu_o, double mu_i) const {
    if (mu_o <= 0.0 || mu_i <= 0.0) return 0.0;
    const double one_minus_avg = 1.0 - fon.average_albedo();
    // sigma = 0 (Lambert): no energy is lost, and the lobe vanishes like sigma.
    if (!(one_minus_avg > 0.0)) return 0.0;
    return kInvPi * (1.0 - fon.albedo(mu_o)) * (1.0 - fon.albedo(mu_i)) / one_minus_avg;
}

double Eon::brdf(const Vec3& wo, const Vec3& wi) const {
    if (wo.z < 0.0 || wi.z <= 0.0) return 0.0;
    return fon.brdf(wo, wi) + multiple_scattering_brdf(wo.z, wi.z);
}

}  // namespace brdflut
