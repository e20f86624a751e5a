// Charlie sheen: a microfacet lobe for cloth and dust.
//
// Estevez and Kulla 2017, "Production Friendly Microfacet Sheen BRDF"
// Neubelt and Pettineo 2013, "Crafting a Next-Gen Material Pipeline for The
//                             Order: 1886" (the visibility term)
//
// f(wo, wi) = D(h) V(mu_o, mu_i), no Fresnel, h = normalize(wo + wi), with
//   D(h) = (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi)
//   V    = 1 / (4 (mu_i + mu_o - mu_i mu_o))
// Roughness: alpha = perceptual_roughness^2 (alpha_from_perceptual), as
// Filament and glTF's KHR_materials_sheen do; alpha in (0, 1].
#pragma once

#include <cmath>

#include "brdflut/math.h"

namespace brdflut {

struct Charlie {
    double alpha;

    // Density of microfacet normals per unit projected area:
    // integral of D(m) cos(theta_m) dw_m = 1.
    double D(double cos_theta_m) const {
        if (cos_theta_m <= 0.0) return 0.0;
        const double sin2 = std::max(0.0, 1.0 - cos_theta_m * cos_theta_m);
        const double inv = 1.0 / alpha;
        return (2.0 + inv) * std::pow(sin2, 0.5 * inv) / kTwoPi;
    }

    // sin(theta_m) of a normal drawn from D cos(theta_m) dw_m, from a uniform
    // number in [0, 1): the CDF of sin(theta_m) is sin^(2 + 1/alpha).
    double sample_sin_theta(double u) const { return std::pow(u, alpha / (2.0 * alpha + 1.0)); }
};

// Neubelt and Pettineo's visibility, for mu_o, mu_i in [0, 1] (not both 0).
inline double neubelt_visibility(double mu_o, double mu_i) {
    return 1.0 / (4.0 * (mu_i + mu_o - mu_i * mu_o));
}

// f = D V for directions in the shading frame (normal +z); 0 below the horizon.
double charlie_sheen_brdf(const Charlie& charlie, const Vec3& wo, const Vec3& wi);

}  // namespace brdflut
