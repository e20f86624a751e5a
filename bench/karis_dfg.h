// The estimator engines ship for the split-sum table: Karis 2013's
// IntegrateBRDF as Filament's offline generator runs it (libs/ibl,
// CubemapIBL::DFG), written here from the math for the benchmark that
// compares it with brdflut's quadrature. It is a baseline, not part of the
// library.
//
// Karis 2013, "Real Shading in Unreal Engine 4" (split sum, IntegrateBRDF)
// Heitz 2014, "Understanding the Masking-Shadowing Function in
//   Microfacet-Based BRDFs" (height-correlated Smith G2)
//
// Per texel (mu_o = n.v, alpha), N points u_i of the Hammersley set
// (i / N, radical inverse of i in base 2) pick half vectors h with density
// D(h) (n.h) by inverting the GGX distribution's CDF:
//   phi = 2 pi u_x,  cos^2(theta_h) = (1 - u_y) / (1 + (alpha^2 - 1) u_y).
// With l = 2 (v.h) h - v and the Jacobian dw_l / dw_h = 4 (v.h), the
// estimate of the integral of f (n.l) dw_l over the sampled half vectors is
//   (4 / N) * sum over n.l > 0 of  V(n.v, n.l) (n.l) (v.h) / (n.h) * {1 - Fc, Fc}
// with Fc = (1 - v.h)^5 and Filament's height-correlated visibility
//   V = G2 / (4 (n.v) (n.l))
//     = 0.5 / ((n.l) sqrt(n.v^2 (1 - alpha^2) + alpha^2)
//              + (n.v) sqrt(n.l^2 (1 - alpha^2) + alpha^2)),
// which is brdflut's height-correlated G2 (ggx_dfg's default).
//
// As in Filament, every texel draws its own N points (angles, sines and
// cosines per sample and texel; nothing is hoisted out of the texel), the
// points are float, a negative n.l drops the sample (it counts in N), and
// the table is filled one row (one alpha) per task. The benchmark evaluates
// it at ggx_dfg's own texel centres so that the two tables compare value for
// value (Filament's rows sit at sqrt(alpha) = (height - y + 0.5) / height,
// one texel above the centres (height - y - 0.5) / height, its top row
// clamped to 1). Real is the arithmetic
// of everything after the points: float (the cheapest) or double (what
// Filament's current sources use).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace bench {

// Radical inverse of i in base 2 (the bits of i mirrored), in [0, 1).
inline float radical_inverse2(std::uint32_t i) {
    i = (i << 16) | (i >> 16);
    i = ((i & 0x55555555u) << 1) | ((i & 0xAAAAAAAAu) >> 1);
    i = ((i & 0x33333333u) << 2) | ((i & 0xCCCCCCCCu) >> 2);
    i = ((i & 0x0F0F0F0Fu) << 4) | ((i & 0xF0F0F0F0u) >> 4);
    i = ((i & 0x00FF00FFu) << 8) | ((i & 0xFF00FF00u) >> 8);
    return static_cast<float>(i) * (1.0f / 4294967296.0f);
}

template <class Real>
struct KarisDfg {
    Real a, b;  // the two split-sum terms: F0 a + b (F90 = 1)
};

// The estimate of (A, B) at mu_o = n.v and alpha with `samples` points.
template <class Real>
KarisDfg<Real> karis_integrate_brdf(Real mu_o, Real alpha, std::uint32_t samples) {
    constexpr Real kTwoPi = Real(6.283185307179586476925286766559);
    const Real one = Real(1), zero = Real(0);
    const Real alpha2 = alpha * alpha;
    const Real v_x = std::sqrt(one - mu_o * mu_o), v_z = mu_o;  // v in the x-z plane
    const float inv_n = 1.0f / static_cast<float>(samples);
    Real sum_a = zero, sum_b = zero;
    for (std::uint32_t i = 0; i < samples; ++i) {
        const Real u_x = static_cast<Real>(static_cast<float>(i) * inv_n);
        const Real u_y = static_cast<Real>(radical_inverse2(i));
        // GGX half vector with density D (n.h); (alpha^2 - 1) as
        // (alpha - 1)(alpha + 1) for accuracy at small alpha.
        const Real phi = kTwoPi * u_x;
        const Real cos2 = (one - u_y) / (one + (alpha + one) * ((alpha - one) * u_y));
        const Real cos_h = std::sqrt(cos2);
        const Real sin_h = std::sqrt(one - cos2);
        const Real h_x = sin_h * std::cos(phi), h_y = sin_h * std::sin(phi), h_z = cos_h;
        (void)h_y;  // v has no y component, l.z needs none either
        const Real v_h = v_x * h_x + v_z * h_z;
        const Real l_z = Real(2) * v_h * h_z - v_z;
        const Real n_l = std::clamp(l_z, zero, one);
        const Real n_h = std::clamp(h_z, zero, one);
        const Real v_h_c = std::clamp(v_h, zero, one);
        if (n_l > zero) {
            const Real g_l = mu_o * std::sqrt((n_l - n_l * alpha2) * n_l + alpha2);
            const Real g_v = n_l * std::sqrt((mu_o - mu_o * alpha2) * mu_o + alpha2);
            const Real vis = Real(0.5) / (g_v + g_l);
            const Real w = vis * n_l * (v_h_c / n_h);
            const Real m = one - v_h_c;
            const Real fc = (m * m) * (m * m) * m;
            sum_a += w * (one - fc);
            sum_b += w * fc;
        }
    }
    const Real scale = Real(4) / static_cast<Real>(samples);
    return {sum_a * scale, sum_b * scale};
}

}  // namespace bench
