// Directional and average albedos of the rough dielectric (GGX glass) of
// Walter et al. 2007, "Microfacet Models for Refraction through Rough
// Surfaces": GGX normals, the exact unpolarized dielectric Fresnel F (1 under
// total internal reflection) and Smith shadowing-masking G2 (height
// correlated 1 / (1 + Lambda(o) + Lambda(i)) by default, or separable
// G1(o) G1(i); Lambda of the transmitted direction is taken of |cos|).
//
// The view direction wo lies on the near side of an interface of relative
// index eta (the far side's index over the near side's): eta = n > 1 seen
// from outside, eta = 1/n from inside the denser medium. With wo fixed and
// the integral taken over the other direction wi:
//
//   E_R(mu_o) = integral over the near hemisphere of f_r |cos(theta_i)| dw_i
//             = integral of F(wo.h) D(h) G2 (wo.h) / mu_o dw_h
//   E_T(mu_o) = integral over the far hemisphere of f_t |cos(theta_i)| dw_i
//             = integral of (1 - F(wo.h)) D(h) G2 (wo.h) / mu_o dw_h
//
// with Walter's eta_o^2 factor in f_t: E_T is the fraction of the energy
// arriving along wo that crosses the interface (the smooth limit of E_R + E_T
// is F + (1 - F) = 1 on both sides). A renderer that carries radiance across
// the interface instead multiplies E_T by 1 / eta^2. A direction reflected
// or refracted about h that lands on the wrong side of the macro surface
// (wi below the horizon for reflection, above it for transmission)
// contributes nothing; microfacets facing away from wo (wo.h <= 0) are not
// seen. Averages: E_avg = 2 * integral of E(mu) mu dmu over [0, 1].
//
// With eta = 1 there is no Fresnel reflection (E_R = 0) but the model still
// masks the straight-through path twice: E_T = G2(wo, -wo) (1 + Lambda(wo)),
// which is 1 only for alpha = 0. The tables evaluate the model as it is.
#pragma once

#include <cstdint>

#include "brdflut/microfacet.h"
#include "brdflut/quadrature.h"

namespace brdflut {

// Default absolute tolerance of the functions below.
inline constexpr double kGlassAbsTolerance = 1e-9;
// Absolute tolerance of each channel of the glass quadrature tables. The
// estimates it leaves stay well below it (the largest estimate plus float
// rounding, at most 3e-8 below 1, is 5.8e-8 over the default and Cycles
// tables; bench/RESULTS.md), so every stored value is within 1e-7 of the
// exact integral, which a test checks.
inline constexpr double kGlassTableTolerance = 5e-8;

// E_T with the separable G by an n x n tensor Gauss-Legendre rule over the
// visible-normal sample space (u1, u2) in [0, 1]^2 of Heitz 2018: the mean
// over the nodes of (1 - F(wo.m)) G1(wi) for the direction wi refracted
// about the sampled normal m, counted when wi leaves on the far side. A
// second route to ggx_glass's E_T (separable), independent of its
// half-vector quadrature; at n = 32 it is Mitsuba 3's construction of the
// roughplastic transmittance (microfacet.h, eval_transmittance, for eta > 1).
// The integrand has kinks where wi grazes the surface, so the rule converges
// slowly; mu_o in (0, 1], alpha > 0, eta > 0, nodes >= 1.
double ggx_transmission_visible_normal_rule(double mu_o, double alpha, double eta, int nodes);

// Deterministic quadrature over the half vector. value = {E_R, E_T}, error =
// the estimated absolute error of each. mu_o in [0, 1] (0 is taken at
// 1e-16, the grazing limit), alpha >= 0 (0: the smooth interface, F and
// 1 - F), eta > 0.
Estimate<2> ggx_glass(double mu_o, double alpha, double eta, Visibility vis,
                      double abs_tol = kGlassAbsTolerance);

// {E_R avg, E_T avg}: 2 * integral of E(mu) mu dmu, by quadrature over the
// half vector and the direction of wo about it:
//   E_avg = (1/pi) integral of D(h) dw_h  integral over c = wo.h in [0, 1] of
//           c {F(c), 1 - F(c)}  integral over the azimuth psi of wo about h of G2,
// on the domain where wo and the reflected (refracted) direction are on the
// right sides. F depends on c alone, so the Fresnel factor leaves the psi
// integral, and every domain of psi is an interval in closed form.
// The two channels are separate integrals. From inside (eta < 1) E_T avg
// is taken from outside by the reciprocity of Walter's model,
//   E_T avg(alpha, 1/n) = E_T avg(alpha, n) / n^2,
// so only the outside transmission is ever integrated (the tests hold it
// against the inside computed by ggx_glass_average_over_mu).
Estimate<2> ggx_glass_average(double alpha, double eta, Visibility vis,
                              double abs_tol = kGlassAbsTolerance);
// Its parts, for callers that share them between tables (the outside
// transmission of index n serves both sides): E_R avg at eta; E_T avg from
// outside at n >= 1 (eta = n); and the pair {E_R avg, E_T avg} at eta from
// the two (E_T scaled by eta^2 when eta < 1, n = 1 / eta).
Estimate<1> ggx_glass_average_reflection(double alpha, double eta, Visibility vis,
                                         double abs_tol = kGlassAbsTolerance);
Estimate<1> ggx_glass_average_transmission_outside(double alpha, double n, Visibility vis,
                                                   double abs_tol = kGlassAbsTolerance);
Estimate<2> ggx_glass_average_of_parts(const Estimate<1>& reflection, const Estimate<1>& transmission_outside,
                                       double eta);
// The same averages by a second route: adaptive quadrature in mu of
// ggx_glass(mu) (much slower; the tests hold the two against each other).
Estimate<2> ggx_glass_average_over_mu(double alpha, double eta, Visibility vis,
                                      double abs_tol = kGlassAbsTolerance);

// Monte Carlo estimates by visible-normal sampling (Heitz 2018), both
// channels from each sampled normal: value = the mean, error = its standard
// error. Reproducible for a given seed.
Estimate<2> ggx_glass_mc(double mu_o, double alpha, double eta, Visibility vis, long long samples,
                         std::uint64_t seed);
// The averages by sampling mu with density 2 mu, then one visible normal per mu.
Estimate<2> ggx_glass_average_mc(double alpha, double eta, Visibility vis, long long samples,
                                 std::uint64_t seed);

}  // namespace brdflut
