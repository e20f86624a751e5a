#include "brdflut/sheen.h"

namespace brdflut {

double charlie_sheen_brdf(const Charlie& charlie, const Vec3& wo, const Vec3& wi) {
    if (wo.z < 0.0 || wi.z <= 0.0) return 0.0;
    const Vec3 s{wo.x + wi.x, wo.y + wi.y, wo.z + wi.z};
    const double len = std::sqrt(dot(s, s));
    if (!(len > 0.0)) return 0.0;
    return charlie.D(s.z / len) * neubelt_visibility(wo.z, wi.z);
}

}  // namespace brdflut
