// GGX reflection as a generic lobe (generic_lobe.h), for Fresnel-weighted
// moments of any weight of c = wo.h, and a second, independent quadrature
// of the same moments over the half vector.
//
// Two lobes:
//   brdf:  f = D(h) G2(mu_o, mu_i) / (4 mu_o mu_i), G2 by a Visibility;
//   vndf:  f = D(h) G1(mu_o) / (4 mu_o mu_i), so that f cos(theta_i) dw_i is
//          the density of visible normals D_wo(h) dh = G1(mu_o) (wo.h) D(h) /
//          mu_o dh (dw_i = 4 (wo.h) dh), restricted to the half vectors
//          whose reflection stays above the horizon. Its moment of a weight
//          w is the mean of w over the directions a visible-normal sampler
//          draws, those below the horizon counting 0: what Blender Cycles
//          tabulates as table_ggx_gen_schlick_s and _ior_s
//          (cycles_precompute.cpp, the F0 -> F90 interpolation factor s).
#pragma once

#include <array>
#include <utility>
#include <vector>

#include "brdflut/generic_lobe.h"
#include "brdflut/microfacet.h"

namespace brdflut {

enum class GgxLobeKind { brdf, vndf };

class GgxLobe final : public GenericLobe {
public:
    explicit GgxLobe(double alpha, Visibility vis = Visibility::height_correlated, GgxLobeKind kind = GgxLobeKind::brdf)
        : ggx_{alpha}, vis_(vis), kind_(kind) {}
    double f(const Vec3& wo, const Vec3& wi) const override;
    // Peak at the mirror direction, width 2 alpha, aspect min(1, mu_o + alpha).
    LobeHints hints(const Vec3& wo) const override;
    // Visible normals (Heitz 2018), reflected, for the vndf lobe; for the
    // brdf lobe an equal mixture of reflected normals from D cos(theta_m)
    // and cosine-weighted directions.
    bool has_sampler() const override { return true; }
    LobeSample sample(const Vec3& wo, double u1, double u2) const override;

private:
    Ggx ggx_;
    Visibility vis_;
    GgxLobeKind kind_;
};

// GGX's D at the direction of m (any length, m.z > 0), from its components.
double ggx_D_along(double alpha, const Vec3& m);

// The moments of the lobe for up to four weights by a route that shares
// nothing with the generic path: the integral over the half vector in
// u = t^2 / (alpha^2 + t^2) (t = tan(theta_h): D cos(theta_h) dw_h = du
// dphi / (2 pi), uniform in u) and its azimuth phi, the azimuth clipped
// exactly where the reflection reaches the horizon, u split where the clip
// starts (a (u - u_a)^(3/2) kink), adaptive Gauss-Kronrod at both levels:
//
//   M_k = integral of G(mu_o, mu_i) (wo.h) w_k(wo.h) / (mu_o cos(theta_h)) D cos(theta_h) dw_h,
//
// G = G2 for the brdf lobe, G1(mu_o) for the vndf lobe.
template <std::size_t N>
std::array<double, N> ggx_moments_half_vector(double mu_o, double alpha, Visibility vis, GgxLobeKind kind,
                                              const std::array<MomentWeight, N>& weights, double abs_tol = 1e-11);

}  // namespace brdflut
