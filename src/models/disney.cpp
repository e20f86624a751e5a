#include "brdflut/disney.h"

#include <cmath>

#include "brdflut/microfacet.h"

namespace brdflut {

namespace {
// cos^2(theta_d) = (wi.h)^2 with h = (wi + wo)/|wi + wo|, that is (1 + wi.wo) / 2.
double cos2_theta_d(const Vec3& wo, const Vec3& wi) { return 0.5 * (1.0 + dot(wo, wi)); }

// (1 + (F90 - 1)(1 - mu_i)^5)(1 + (F90 - 1)(1 - mu_o)^5)
double schlick_pair(double f90, double mu_o, double mu_i) {
    return (1.0 + (f90 - 1.0) * schlick_weight(mu_i)) * (1.0 + (f90 - 1.0) * schlick_weight(mu_o));
}
}  // namespace

double gtr1_D(double cos_theta_h, double alpha) {
    if (cos_theta_h <= 0.0) return 0.0;
    const double a2 = alpha * alpha;
    return (a2 - 1.0) / (kPi * std::log(a2) * (1.0 + (a2 - 1.0) * sqr(cos_theta_h)));
}

double disney_diffuse_brdf(const Vec3& wo, const Vec3& wi, double roughness) {
    if (wo.z < 0.0 || wi.z <= 0.0) return 0.0;
    const double f90 = 0.5 + 2.0 * roughness * cos2_theta_d(wo, wi);
    return kInvPi * schlick_pair(f90, wo.z, wi.z);
}

double disney_subsurface_brdf(const Vec3& wo, const Vec3& wi, double roughness) {
    if (wo.z < 0.0 || wi.z <= 0.0) return 0.0;
    const double fss = schlick_pair(roughness * cos2_theta_d(wo, wi), wo.z, wi.z);
    return kInvPi * 1.25 * (fss * (1.0 / (wi.z + wo.z) - 0.5) + 0.5);
}

double disney_sheen_brdf(const Vec3& wo, const Vec3& wi) {
    if (wo.z < 0.0 || wi.z <= 0.0) return 0.0;
    return schlick_weight(std::sqrt(cos2_theta_d(wo, wi)));
}

double disney_clearcoat_brdf(const Vec3& wo, const Vec3& wi, double gloss) {
    if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
    Vec3 h{wo.x + wi.x, wo.y + wi.y, wo.z + wi.z};
    const double len = std::sqrt(dot(h, h));
    h = {h.x / len, h.y / len, h.z / len};
    const double f = kClearcoatF0 + (1.0 - kClearcoatF0) * schlick_weight(dot(wo, h));
    const Ggx masking{kClearcoatGeometryAlpha};
    const double g = masking.G1(wo.z) * masking.G1(wi.z);
    return f * g * gtr1_D(h.z, clearcoat_alpha(gloss)) / (4.0 * wo.z * wi.z);
}

}  // namespace brdflut
