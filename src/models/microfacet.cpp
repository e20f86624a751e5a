#include "brdflut/microfacet.h"

#include <cmath>

#include "brdflut/error.h"

namespace brdflut {

std::string_view to_string(Visibility v) {
    switch (v) {
        case Visibility::separable: return "separable";
        case Visibility::schlick_smith: return "schlick_smith";
        case Visibility::smith_joint_approx: return "smith_joint_approx";
        case Visibility::height_correlated: break;
    }
    return "height_correlated";
}

Visibility visibility_from_string(std::string_view s) {
    if (s == "height_correlated") return Visibility::height_correlated;
    if (s == "separable") return Visibility::separable;
    if (s == "schlick_smith") return Visibility::schlick_smith;
    if (s == "smith_joint_approx") return Visibility::smith_joint_approx;
    throw Error("visibility '" + std::string(s) +
                "' is not known; allowed: height_correlated, separable, schlick_smith, smith_joint_approx");
}

// Heitz 2018, "Sampling the GGX Distribution of Visible Normals", listing 1.
Vec3 Ggx::sample_visible_normal(const Vec3& wo, double u1, double u2) const {
    // Stretch the view direction to the hemisphere configuration.
    Vec3 vh{alpha * wo.x, alpha * wo.y, wo.z};
    const double vlen = std::sqrt(dot(vh, vh));
    vh = {vh.x / vlen, vh.y / vlen, vh.z / vlen};
    const double lensq = vh.x * vh.x + vh.y * vh.y;
    Vec3 t1 = lensq > 0.0 ? Vec3{-vh.y / std::sqrt(lensq), vh.x / std::sqrt(lensq), 0.0}
                          : Vec3{1.0, 0.0, 0.0};
    Vec3 t2{vh.y * t1.z - vh.z * t1.y, vh.z * t1.x - vh.x * t1.z, vh.x * t1.y - vh.y * t1.x};
    // Uniform point on the projected disk, warped to the visible half.
    const double r = std::sqrt(u1);
    const double phi = kTwoPi * u2;
    const double p1 = r * std::cos(phi);
    double p2 = r * std::sin(phi);
    const double s = 0.5 * (1.0 + vh.z);
    p2 = (1.0 - s) * safe_sqrt(1.0 - p1 * p1) + s * p2;
    const double pz = safe_sqrt(1.0 - p1 * p1 - p2 * p2);
    const Vec3 nh{p1 * t1.x + p2 * t2.x + pz * vh.x, p1 * t1.y + p2 * t2.y + pz * vh.y,
                  p1 * t1.z + p2 * t2.z + pz * vh.z};
    // Unstretch back to the ellipsoid configuration.
    Vec3 m{alpha * nh.x, alpha * nh.y, std::max(0.0, nh.z)};
    const double mlen = std::sqrt(dot(m, m));
    if (mlen == 0.0) return {0.0, 0.0, 1.0};
    return {m.x / mlen, m.y / mlen, m.z / mlen};
}

}  // namespace brdflut
