// Photon beam diffusion (Habel, Christensen and Jarosz 2013) as pbrt-v4
// defines it for its BSSRDFTable: the radial profile of a semi-infinite
// medium lit by a beam at normal incidence, the sum of a single-scattering
// term and a multiple-scattering term (a continuum of dipoles along the
// refracted beam), the effective albedo rho_eff (the integral of the
// profile over the surface) and its inversion.
//
// Habel, Christensen and Jarosz 2013, "Photon Beam Diffusion: A Hybrid Monte
// Carlo Method for Subsurface Scattering"
// d'Eon and Irving 2011, "A Quantized-Diffusion Model for Rendering
// Translucent Materials" (the Fresnel moment fits, the Grosjean diffusion
// coefficient, the exitance factors cPhi and cE)
// Pharr, Jakob and Humphreys, "Physically Based Rendering", 4th edition,
// section 11.4 (BeamDiffusionMS, BeamDiffusionSS, ComputeBeamDiffusionBSSRDF
// in mmp/pbrt-v4 src/pbrt/bssrdf.cpp).
//
// Units: lengths in mean free paths, sigma_t = sigma_s + sigma_a = 1, so the
// single-scattering albedo rho = sigma_s and sigma_a = 1 - rho (pbrt's
// table). eta is the relative index n_medium / n_outside, g the
// Henyey-Greenstein asymmetry (clamped to [-0.99, 0.99] as pbrt does).
//
// Definitions (all per unit area, r >= 0 the distance on the surface):
//   reduced: sigma'_s = rho (1 - g), sigma'_t = sigma_a + sigma'_s, rho' = sigma'_s / sigma'_t
//   D = (2 sigma_a + sigma'_s) / (3 sigma'_t^2) (Grosjean), sigma_tr = sqrt(sigma_a / D)
//   ze = -2 D (1 + 3 M2) / (1 - 2 M1), cPhi = (1 - 2 M1)/4, cE = (1 - 3 M2)/2,
//   M1, M2 the polynomial fits of the Fresnel moments at eta (pbrt's FresnelMoment1/2)
//   a real source at depth z, its image at zv = 2 ze - z, dr = |(r, z)|, dv = |(r, zv)|:
//     phi(z) = (e^(-sigma_tr dr)/dr - e^(-sigma_tr dv)/dv) / (4 pi D)
//     E(z)   = (z (1 + sigma_tr dr) e^(-sigma_tr dr)/dr^3 - zv (1 + sigma_tr dv) e^(-sigma_tr dv)/dv^3) / (4 pi)
//     kappa(z) = 1 - e^(-2 sigma'_t (dr + z))
//   Sr_ms(r) = integral over z in [0, inf) of sigma'_t e^(-sigma'_t z) kappa rho'^2 (cPhi phi + cE E) dz
//   Sr_ss(r) = integral over t in [t_c, inf) of sigma_t rho e^(-sigma_t (t + d)) p(t/d) (1 - F(t/d)) (t/d) / d^2 dt,
//     d = |(r, t)|, t_c = r sqrt(eta^2 - 1) (no transmission below it: total internal reflection),
//     p the Henyey-Greenstein phase (1 - g^2) / (4 pi (1 + g^2 + 2 g c)^(3/2)), F the dielectric
//     Fresnel reflectance leaving the medium (relative index 1/eta)
//   pbrt-v4 evaluates each integral as a 100-point midpoint rule in the exponential sampling variable
//   u = 1 - e^(-sigma'_t z) (u = 1 - e^(-sigma_t (t - t_c))); the integrals above are their exact values.
//   Its table stores 2 pi r Sr(r); as r -> 0, Sr_ms grows as ln(1/r) (2 pi r Sr_ms -> 0) and Sr_ss as
//   1/r: 2 pi r Sr_ss -> 2 pi sigma_t rho integral over theta in [0, theta_c] of p T cos(theta) dtheta,
//   sin(theta_c) = 1/eta, the value this code gives at r = 0.
//   rho_eff = integral over r in [0, inf) of 2 pi r (Sr_ss + Sr_ms) dr.
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "brdflut/quadrature.h"

namespace brdflut {

// pbrt-v4's polynomial fits of the first and second Fresnel moments
// (d'Eon and Irving 2011), of the relative index eta.
double fresnel_moment1_fit(double eta);
double fresnel_moment2_fit(double eta);

// The Henyey-Greenstein phase in pbrt-v4's convention (c is the cosine
// between the two directions pointing away from the scattering point; g is
// clamped to [-0.99, 0.99]).
double henyey_greenstein_pbrt(double c, double g);

// How the exponentials of pbrt's midpoint rules are evaluated: std::exp, or
// pbrt-v4's CPU FastExp (a cubic fit of 2^f on [0, 1) times 2^i, 0 below
// 2^-126), evaluated here in double.
enum class PbrtExp { exact, fast };
double pbrt_fast_exp(double x);

// The medium of pbrt's table: sigma_t = 1, sigma_s = rho, sigma_a = 1 - rho.
class BeamDiffusion {
public:
    BeamDiffusion(double rho, double g, double eta);

    // The integrands, per unit z (multiple scattering, over [0, inf)) and per
    // unit t (single scattering, over [t_c(r), inf)).
    double ms_integrand(double z, double r) const;
    double ss_integrand(double t, double r) const;
    double t_crit(double r) const { return r * crit_slope_; }

    // 2 pi r Sr_ss and 2 pi r Sr_ms (the weight of pbrt's table), at r >= 0
    // (their limits at r = 0), by adaptive Gauss-Kronrod with a relative
    // tolerance; error: the QUADPACK estimate plus a bound on the truncated
    // ends (below 1e-15 relative).
    Estimate<1> weighted_ss(double r, double rel_tol) const;
    Estimate<1> weighted_ms(double r, double rel_tol) const;
    // The same by pbrt-v4's 100-point midpoint rules (BeamDiffusionSS/MS).
    double weighted_ss_midpoint(double r, int n = 100, PbrtExp e = PbrtExp::exact) const;
    double weighted_ms_midpoint(double r, int n = 100, PbrtExp e = PbrtExp::exact) const;

    // 2 pi r Sr_ss(r) -> this as r -> 0.
    double weighted_ss_at_zero(double rel_tol, double* error = nullptr) const;

    // rho_eff split into its single- and multiple-scattering parts: the
    // integral of 2 pi r Sr over [0, inf), nested adaptive quadrature.
    Estimate<2> rho_eff(double rel_tol) const;

    double rho() const { return rho_; }
    double sigma_tr() const { return sigma_tr_; }

private:
    double rho_, g_, eta_;
    double sigmap_t_, rhop_, D_, sigma_tr_, ze_, cphi_, ce_, crit_slope_;
};

// pbrt-v4's grids: rho_i = (1 - e^(-8 i/(n - 1))) / (1 - e^(-8)), and radii
// 0, r_1, r_1 q, r_1 q^2, .. (r_1 = 2.5e-3, q = 1.2).
std::vector<double> pbrt_rho_samples(int n = 100);
std::vector<double> pbrt_radius_samples(int n = 64);

// pbrt-v4's Catmull-Rom integral of samples f over increasing nodes (finite
// difference slopes, one-sided at the ends), and the inverse of the
// Catmull-Rom interpolant of increasing f at y (clamped to the end nodes).
double catmull_rom_integral(const std::vector<double>& nodes, const std::vector<double>& f);
double catmull_rom_invert(const std::vector<double>& nodes, const std::vector<double>& f, double y);

// The albedo rho whose exact rho_eff is a target (rho_eff rises with rho),
// in x = 1 - sqrt(1 - rho), where rho_eff is smooth up to rho = 1: a guess
// from the Catmull-Rom inverse of rho_eff at 33 nodes uniform in x (at
// tolerance 1e-7), then secant steps on rho_eff(x) - target within the
// nodes' bracket (bisection when a step leaves it) until the step is below
// 1e-12 or the residual below rho_eff's own error. Targets at or beyond
// rho_eff(1) give 1, at or below 0 give 0. *error: the last step plus the
// residual error over the slope, in rho.
class RhoEffInverse {
public:
    RhoEffInverse(double g, double eta, double rel_tol);
    double albedo(double target, double* error = nullptr) const;
    // The exact rho_eff(1 - (1 - x)^2) (both parts) and its error.
    double rho_eff_of_x(double x, double rel_tol, double* error = nullptr) const;

private:
    double g_, eta_, tol_;
    std::vector<double> x_, f_;  // the guess nodes
};

}  // namespace brdflut
