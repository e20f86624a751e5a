// The lobes of the Disney principled BRDF, per unit base colour (rho = 1).
//
// Burley 2012, "Physically-Based Shading at Disney", sections 5.3 (diffuse,
// subsurface), 5.4 (sheen) and 5.5 (clearcoat: GTR1 distribution).
//
// Every function returns the BRDF value f(wo, wi) (per steradian) for
// directions in the shading frame (normal +z); 0 below the horizon (wo on
// the horizon gives the limit value; the clearcoat is 0 there). theta_d is
// the angle between the light and the half vector: cos(theta_d) = wi.h = wo.h.
#pragma once

#include "brdflut/math.h"

namespace brdflut {

// The clearcoat width alpha = mix(0.1, 0.001, gloss), gloss in [0, 1].
constexpr double clearcoat_alpha(double gloss) { return 0.1 + (0.001 - 0.1) * gloss; }

// Width of the separable Smith GGX masking of the clearcoat lobe.
inline constexpr double kClearcoatGeometryAlpha = 0.25;

// Reflectance of the clearcoat at normal incidence (index 1.5).
inline constexpr double kClearcoatF0 = 0.04;

// GTR1 ("generalized Trowbridge-Reitz", gamma = 1) distribution for
// 0 < alpha < 1: D = (alpha^2 - 1) / (pi ln(alpha^2) (1 + (alpha^2 - 1) cos^2(theta_h))),
// normalized so that integral of D cos(theta_h) dw_h = 1.
double gtr1_D(double cos_theta_h, double alpha);

// (1/pi) f_d: f_d = (1 + (F_D90 - 1)(1 - mu_i)^5)(1 + (F_D90 - 1)(1 - mu_o)^5),
// F_D90 = 0.5 + 2 r cos^2(theta_d), r the perceptual roughness.
double disney_diffuse_brdf(const Vec3& wo, const Vec3& wi, double roughness);

// (1/pi) f_ss: f_ss = 1.25 (F_ss (1 / (mu_i + mu_o) - 0.5) + 0.5), F_ss as f_d
// with F_ss90 = r cos^2(theta_d) (Hanrahan-Krueger-like subsurface lobe).
double disney_subsurface_brdf(const Vec3& wo, const Vec3& wi, double roughness);

// The sheen lobe per unit (untinted) sheen weight: (1 - cos(theta_d))^5.
double disney_sheen_brdf(const Vec3& wo, const Vec3& wi);

// The clearcoat lobe with weight 1: F_c G_c D_c / (4 mu_i mu_o), D_c GTR1 with
// alpha = clearcoat_alpha(gloss), F_c = 0.04 + 0.96 (1 - cos(theta_d))^5,
// G_c = G1(mu_o) G1(mu_i) of GGX with alpha = 0.25.
double disney_clearcoat_brdf(const Vec3& wo, const Vec3& wi, double gloss);

}  // namespace brdflut
