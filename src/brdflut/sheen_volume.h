// The "volume" sheen of Zeltner, Burley and Chiang 2022: the simulated layer
// itself, not the talk's analytic approximation (zeltner_sheen.h). A
// plane-parallel slab of unit thickness and unit density, without
// absorption, filled with fibre-like SGGX microflakes standing along the
// normal (S = diag(1, 1, sigma^2), sigma = alpha^2) and scattering by the
// specular microflake phase function; nothing below it. Its directional
// albedo is the fraction of light arriving at cos(theta) = mu that leaves
// through the top.
//
// The talk computed it by a random walk (tizian/ltc-sheen
// fitting/src/bsdfs/sheen_volume.h @92624114): 2e6 seeded walks a texel, cut
// after 16 scatterings, a walk still inside after its 16th scattering
// counted as reflected when its new direction points up. Here it is computed
// deterministically, both as the layer's true albedo (every scattering
// order) and as the talk's truncated walk.
//
// Method. Extinction s(w) = sqrt(1 - w.z^2 + sigma^2 w.z^2) and the phase
// function depend on directions only through their cosines and the azimuth
// between them, so the albedo, an integral over every outgoing azimuth, needs
// only the azimuthal average of the phase function, which has a closed form
// (fibre_phase_azimuthal). With it the transport is one-dimensional in
// depth and in the direction cosine nu:
//  - nu: Gauss-Legendre panels on each hemisphere, graded towards the
//    horizon; the scattering integral over nu is product integration
//    against the local cubic interpolant of the unknown between the nodes
//    (exact for a cubic whatever the width of the phase function's peak,
//    which is about sigma wide);
//  - depth: the unknown cubic between the nodes of a mesh graded
//    geometrically towards both faces, the exponential transport along each
//    direction integrated exactly against it;
//  - orders: the adjoint (the probability that light leaving a scattering at
//    depth z in direction nu reaches the top). The talk's cut walk is built
//    order by order. For every order the scattering that keeps a direction
//    is summed in closed form (it only lowers the extinction) and the rest
//    solved by BiCGSTAB to a residual of 1e-14 (summed order by order it
//    took 7,000 orders at alpha = 0.01, as light creeps between directions).
// One solve serves every mu of one alpha.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "brdflut/generic_lobe.h"
#include "brdflut/zeltner_sheen.h"

namespace brdflut {

// The azimuthal average of the fibre SGGX's specular phase function: the
// density over the new direction cosine nu of light travelling along a
// direction of cosine nu_in (both propagation directions, nu = +1 up),
//   P(nu_in -> nu) = integral over dphi of D(h) / (4 s(nu_in)),
//   h = normalize(w - w_in),
// in closed form: with c = (1 - sigma^2)(nu - nu_in)^2, a = 1 - nu nu_in,
// S = sqrt((1 - nu^2)(1 - nu_in^2)), A = 2 sigma^2 a + c, B = 2 sigma^2 S,
// Q = sqrt(A^2 - B^2):
//   P = (1 - 2 c / Q + c^2 A / Q^3) / (2 sigma s(nu_in)).
// (Far from the peak at nu = nu_in the bracket cancels; there the azimuthal
// integral is taken by a periodic trapezoid rule, exact to rounding.)
// Integrates to 1 over nu in [-1, 1].
double fibre_phase_azimuthal(double sigma, double nu_in, double nu);
// Its azimuthal moments c_m = integral over dphi of D(h) / (4 s(nu_in))
// cos(m phi), m = 0..count-1 (c_0 = fibre_phase_azimuthal), phi the azimuth
// between the two propagation directions: with rho = B / (A + Q),
//   c_m = (delta_m0 - 2 c rho^m / Q + c^2 rho^m (m / Q^2 + A / Q^3)) / (2 sigma s(nu_in)).
void fibre_phase_modes(double sigma, double nu_in, double nu, int count, double* out);

struct SheenVolumeOptions {
    // Direction cosines per hemisphere: Gauss-Legendre, nodes_per_panel on
    // each panel of [0, horizon_panel], [horizon_panel, 2 horizon_panel], ...
    // (doubling below 0.9), [.., 1].
    int nodes_per_panel = 12;
    double horizon_panel = 1e-3;
    int depth_refine = 1;  // 1, 2, 4...: halves the depth mesh's steps that many times over
    // Also the talk's walk, cut after this many scatterings (a walk still
    // inside after the last counted when its direction points up); 0: not
    // computed.
    int cut_after = 0;
    // The every-order solve (reflectances()[0], transmittance); false: only
    // the single scattering and the cut walk.
    bool every_order = true;
    bool transmission = false;  // also the fraction leaving through the bottom
};

class SheenVolumeLayer {
public:
    // alpha in (0, 1] (sigma = alpha^2).
    SheenVolumeLayer(double alpha, const SheenVolumeOptions& options = {});
    // For light arriving at cos(theta) = mu in (0, 1], the fraction leaving
    // through the top: {every order, the cut walk (NaN unless cut_after),
    // the single scattering}.
    std::array<double, 3> reflectances(double mu) const;
    double reflectance(double mu) const;  // every order
    // Fraction leaving through the bottom, every order (options.transmission only).
    double transmittance(double mu) const;
    // BiCGSTAB iterations of the every-order solve and its final residual
    // (largest absolute value).
    int iterations() const { return iterations_; }
    double residual() const { return residual_; }

private:
    double first_collision(const std::vector<double>& row, double lambda, const std::vector<double>& v) const;
    double sigma_;
    SheenVolumeOptions options_;
    std::vector<double> nodes_;  // Gauss-Legendre nodes on (0, 1), ascending
    std::vector<double> depth_;  // depth mesh, 0 (top) to 1 (bottom)
    // Adjoints, [ordinate][depth node]: ordinate j < n up (nu = nodes_[j]),
    // n + j down (nu = -nodes_[j]).
    std::vector<double> to_top_, to_bottom_, single_, cut_;
    int iterations_ = 0;
    double residual_ = 0.0;
};

// The layer's BRDF, for fitting: the single scattering exact (the talk's
// analytic f_ss, which is this layer's own), the multiple scattering from
// the reflection operator of the same discrete directions per azimuthal mode
// m < modes, built by doubling a thin layer (exact in depth: a layer of
// 2^-doublings, single scattering with its exact attenuation, doubled), its
// discrete single scattering taken off, interpolated by cubics in both
// cosines. No Fresnel.
struct SheenVolumeBrdfOptions {
    int nodes_per_panel = 8;
    double horizon_panel = 1e-3;
    int modes = 6;
    int doublings = 44;
};

class SheenVolumeLobe final : public GenericLobe {
public:
    explicit SheenVolumeLobe(double alpha, const SheenVolumeBrdfOptions& options = {});
    double f(const Vec3& wo, const Vec3& wi) const override;
    // The multiple scattering's albedo at mu_o: 2 pi * integral of its
    // azimuthal mean over mu_i times mu_i,
    // exact for the interpolant (the lobe's albedo is this plus the single
    // scattering's, which is the layer's R_ss).
    double multiple_scattering_albedo(double mu_o) const;
    bool has_sampler() const override { return true; }
    LobeSample sample(const Vec3& wo, double u1, double u2) const override { return single_.sample(wo, u1, u2); }

private:
    double interpolate(const std::vector<double>& table, double mu_o, double mu_i) const;
    ZeltnerApproxSheenLobe single_;
    std::vector<double> nodes_;
    // Per mode, [out][in] over nodes: the multiple scattering's moment at
    // the node pair.
    std::vector<std::vector<double>> moments_;
};

// The talk's random walk, as an independent route: the fraction of `paths`
// walks leaving through the top,
// with its standard error (max_bounces: 0 every order, k > 0 the walk cut
// after k scatterings as SheenVolumeOptions::cut_after). Flake normals are drawn from D restricted to the
// side facing the light by rejection (correct for every sigma, slow where
// the visible area is small: keep sigma s(w) above about 1e-3).
struct SheenVolumeEstimate {
    double mean = 0.0, standard_error = 0.0;
};
SheenVolumeEstimate sheen_volume_reflectance_mc(double alpha, double mu, int max_bounces, long long paths,
                                                std::uint64_t seed);

}  // namespace brdflut
