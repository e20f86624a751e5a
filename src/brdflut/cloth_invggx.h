// Unreal Engine's legacy cloth lobe (its Cloth shading model without
// Substrate): the inverted GGX distribution D_InvGGX with the cloth
// visibility Vis_Cloth, no Fresnel.
//
//   D(a2, n.h) = (1 + 4 a2^2 / d^2) / (pi (1 + 4 a2)),  d = (n.h)^2 (1 - a2) + a2,
//   V(mu_o, mu_i) = 1 / (4 (mu_i + mu_o - mu_i mu_o)),
//   f = D V,
//
// with a2 = alpha^2 (Unreal passes the product of its two GGX alphas). At
// alpha = 1, D = 1/pi everywhere and the albedo has the closed form
// E(mu) = (1/(1 - mu) + mu ln(mu) / (1 - mu)^2) / 2.
//
// Unreal Engine BRDF.ush (D_InvGGX, Vis_Cloth) and
// ShadingEnergyConservationTable.usf (BUILD_ENERGY_TABLE 2 without Substrate).
#pragma once

#include "brdflut/generic_lobe.h"

namespace brdflut {

// D_InvGGX at a2 = alpha^2 and n.h = c.
double inv_ggx_distribution(double alpha, double c);
// The albedo at alpha = 1 (the closed form above), mu in [0, 1].
double inv_ggx_cloth_albedo_alpha_one(double mu);

class InvGgxClothLobe final : public GenericLobe {
public:
    explicit InvGgxClothLobe(double alpha) : alpha_(alpha) {}
    double f(const Vec3& wo, const Vec3& wi) const override;
    double alpha() const { return alpha_; }

private:
    double alpha_;
};

}  // namespace brdflut
