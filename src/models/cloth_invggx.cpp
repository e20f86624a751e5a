// Unreal's legacy cloth lobe: D_InvGGX with Vis_Cloth (brdflut/cloth_invggx.h).
#include "brdflut/cloth_invggx.h"

#include <cmath>

#include "brdflut/math.h"
#include "brdflut/sheen.h"

namespace brdflut {

double inv_ggx_distribution(double alpha, double c) {
    const double a2 = alpha * alpha;
    const double d = (c - a2 * c) * c + a2;
    return (1.0 + 4.0 * a2 * a2 / (d * d)) / (kPi * (1.0 + 4.0 * a2));
}

double inv_ggx_cloth_albedo_alpha_one(double mu) {
    if (mu <= 0.0) return 0.5;
    const double c = 1.0 - mu;
    // Near mu = 1 the two terms cancel: 1/c + mu ln(mu)/c^2 = 1/2 + c/6 + c^2/12 + O(c^3).
    if (c < 1e-3) return 0.5 * (0.5 + c / 6.0 + c * c / 12.0);
    return 0.5 * (1.0 / c + mu * std::log1p(-c) / (c * c));
}

double InvGgxClothLobe::f(const Vec3& wo, const Vec3& wi) const {
    if (!(wo.z > 0.0) || !(wi.z > 0.0)) return 0.0;
    const Vec3 s{wo.x + wi.x, wo.y + wi.y, wo.z + wi.z};
    const double len = std::sqrt(dot(s, s));
    if (!(len > 0.0)) return 0.0;
    return inv_ggx_distribution(alpha_, s.z / len) * neubelt_visibility(wo.z, wi.z);
}

}  // namespace brdflut
