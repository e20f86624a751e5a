// The F82-tint Fresnel of metals (Kutz et al. 2021, "Novel aspects of the
// Adobe Standard Material"; Hoffman 2023, "Generalization of Adobe's Fresnel
// Model"), in the form Blender Cycles (bsdf_util.h: fresnel_f82,
// fresnel_f82tint_B) and EEVEE (eevee_lut_comp.glsl: "integral = F0 * scale +
// F90 * bias - F82_tint * metal_bias") evaluate:
//
//   F(mu) = F0 + (1 - F0) (1 - mu)^5 - b mu (1 - mu)^6,
//   b     = [F0 + (1 - F0) (6/7)^5] (1 - t) 7^7 / 6^6,
//
// t the F82 tint: b makes F(1/7) = t * Schlick(1/7) at mu = 1/7 (about 82
// degrees), where mu (1 - mu)^6 peaks. The correction term b mu (1 - mu)^6
// vanishes at normal (mu = 1) and grazing (mu = 0) incidence. F is linear in
// F0 and b, so any moment of it over a lobe is F0 A + B - b C with the split
// sums A (weight 1 - (1 - c)^5), B ((1 - c)^5) and C (c (1 - c)^6). Engines
// clamp F to [0, 1] where they evaluate it; the tables hold the linear form.
#pragma once

#include <cmath>

namespace brdflut {

inline double f82_tint_b(double f0, double tint) {
    const double f = 6.0 / 7.0, f5 = f * f * f * f * f;
    return (f0 + (1.0 - f0) * f5) * (1.0 - tint) * 7.0 / (f5 * f);
}

inline double f82_tint_fresnel(double mu, double f0, double b) {
    const double m = 1.0 - mu, m5 = m * m * m * m * m;
    return f0 + (1.0 - f0) * m5 - b * mu * m5 * m;
}

// Its hemispherical average 2 * integral of F(mu) mu dmu: 2 B(2, 6) = 1/21
// and 2 B(3, 7) = 1/126 give F0 + (1 - F0)/21 - b/126 (OpenPBR issue #187).
inline double f82_tint_average(double f0, double b) { return f0 + (1.0 - f0) / 21.0 - b / 126.0; }

}  // namespace brdflut
