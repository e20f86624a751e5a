// Pre-integrated skin (Penner 2011): the diffuse light of a sphere of radius
// rho lit by a distant light at angle theta from the normal, blurred by a
// radial diffusion profile R(r) on its surface and normalized, per colour
// channel.
//
// Penner and Borshukov 2011, "Pre-Integrated Skin Shading" (GPU Pro 2; the
// ring integral). d'Eon and Luebke 2007, "Advanced Techniques for Realistic
// Real-Time Skin Rendering" (GPU Gems 3, ch. 14: the six-Gaussian skin fit).
// Christensen and Burley 2015 (burley.h); Jensen et al. 2001 (dipole.h).
//
// Two geometries:
//   ring    Penner's formula, the profile along a great circle through the
//           point:  D = int cos+(theta + x) R(2 rho sin(|x|/2)) dx
//                       / int R(2 rho sin(|x|/2)) dx,  x in [-pi, pi].
//           Defined when R is finite at r = 0 (the dipole, Gaussians). For
//           Burley's profile, R ~ 1/r, both integrals diverge like the
//           integral of dx/|x|, and the ratio tends to cos+(theta) at every
//           radius: a midpoint rule (MaterialX's 32 samples) returns a finite
//           value that grows towards that limit as the samples are refined.
//   sphere  the profile over the whole sphere, by area:
//           D = int cos+(incidence at q) R(|p - q|) dA_q / int R(|p - q|) dA_q.
//           With q at polar angle alpha from p, |p - q| = 2 rho sin(alpha/2)
//           and dA = rho^2 sin(alpha) dalpha dphi = r dr dphi, so the
//           denominator is the profile's reflectance within r = 2 rho (a
//           closed form) and Burley's 1/r is integrable. The azimuth has a
//           closed form: the mean over phi of max(0, a + b cos(phi)) with
//           a = cos(theta) cos(alpha), b = sin(theta) sin(alpha).
// Both tend to cos+(theta) as rho -> infinity (curvature 0). Both conserve
// energy: over the sphere, the integral of D dA is the projected area
// pi rho^2 (sphere: integral of D dmu over [-1, 1] = 1/2), and over the ring
// the integral of D dtheta over [0, pi] is 1, as for cos+.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "brdflut/dipole.h"
#include "brdflut/quadrature.h"

namespace brdflut {

enum class SkinGeometry { ring, sphere };
std::string_view to_string(SkinGeometry g);
SkinGeometry skin_geometry_from_string(std::string_view s);  // throws brdflut::Error

// A radially symmetric profile of one colour channel, r in mm, R in 1/mm^2.
class RadialProfile {
public:
    // A s (e^(-s r) + e^(-s r/3)) / (8 pi r), s = 1/d, d in mm.
    static RadialProfile burley(double albedo, double d);
    static RadialProfile dipole(const Dipole& d);
    // Sum of w_i e^(-r^2 / (2 v_i)) / (2 pi v_i), v_i in mm^2.
    static RadialProfile gaussians(std::vector<std::pair<double, double>> weight_variance);

    double value(double r) const;       // R(r)
    double radial(double r) const;      // 2 pi r R(r), finite at r = 0
    double within(double r) const;      // integral of 2 pi r' R(r') dr' over [0, r], closed form
    double total() const { return within(HUGE_VAL); }
    bool finite_at_origin() const { return kind_ != Kind::burley; }
    // The length over which the profile falls: d (Burley), 1/sigma_tr or the
    // source depth (dipole), the smallest sqrt(v) (Gaussians), in mm.
    double scale() const;
    // A radius drawn from 2 pi r R(r) restricted to [0, r_max], by the
    // inverse of within(r) / within(r_max) at u (Burley: burley_inverse_cdf;
    // otherwise bisection on the closed form).
    double sample_radius(double u, double r_max) const;

private:
    enum class Kind { burley, dipole, gaussians };
    explicit RadialProfile(Kind k) : kind_(k), dipole_(Dipole::from_albedo(0.5, 1.0)) {}
    Kind kind_;
    double A_ = 1.0, d_ = 1.0;
    Dipole dipole_;
    std::vector<std::pair<double, double>> g_;
};

using SkinProfile = std::array<RadialProfile, 3>;

// d'Eon and Luebke 2007's six Gaussians for skin, variances in mm^2 and
// weights (R, G, B) per Gaussian.
struct SkinGaussian {
    double variance;
    std::array<double, 3> weight;
};
const std::vector<SkinGaussian>& deon_skin_gaussians();
SkinProfile deon_skin_profile();

// D(theta, rho) per channel at n_dot_l = cos(theta) in [-1, 1] and
// curvature = 1/rho (1/mm, >= 0; 0 gives the limit cos+(theta)), by adaptive
// Gauss-Kronrod split where the integrand has kinks (cos(theta +- x) = 0),
// to abs_tol in D. Ring: a first pass finds each channel's denominator, the
// second integrates both integrals divided by it. Sphere: the numerator
// divided by the closed-form denominator. error: the quadrature estimates
// carried through the ratio plus rounding.
Estimate<3> preintegrated_skin(const SkinProfile& p, SkinGeometry g, double n_dot_l, double curvature,
                               double abs_tol);
// The same ratio by a different rule: composite 32-point Gauss-Legendre on
// panels graded geometrically towards both ends of every piece between the
// kinks (the profile's peak at x = 0 included; widths halving down to 2^-50
// of the piece), with the sphere's denominator integrated too (not its
// closed form). No error estimate.
std::array<double, 3> preintegrated_skin_gauss(const SkinProfile& p, SkinGeometry g, double n_dot_l,
                                               double curvature);
// Monte Carlo, per channel: sphere, q drawn by area from an equal mixture
// of the density proportional to R (radius by the profile's inverse CDF,
// azimuth uniform) and the uniform one, each sample worth cos+ at q times
// the ratio of the profile's density to the mixture's; ring, x uniform on [0, pi] and the ratio of
// the two means with its delta-method standard error. value = the
// estimate, error = its standard error.
Estimate<3> preintegrated_skin_mc(const SkinProfile& p, SkinGeometry g, double n_dot_l, double curvature,
                                  long long samples, std::uint64_t seed);

// (1/(2 pi)) integral over phi of max(0, a + b cos(phi)), b >= 0.
double clamped_cosine_azimuth_mean(double a, double b);

}  // namespace brdflut
