// Directional integrals of the single-scattering GGX BRDF with F = 1:
//
//   A(mu_o) = integral of f (1 - (1 - wo.h)^5) cos(theta_i) dw_i
//   B(mu_o) = integral of f (1 - wo.h)^5 cos(theta_i) dw_i
//   f = D(h) G2(wo, wi) / (4 mu_o mu_i)
//
// so that an engine computes the split-sum specular term as F0 A + B and the
// directional albedo E = A + B. Two independent routes: deterministic
// quadrature (the default) and a seeded Monte Carlo estimate.
#pragma once

#include <cstdint>

#include "brdflut/microfacet.h"
#include "brdflut/quadrature.h"

namespace brdflut {

// At mu_o = 0 the integrand is 0/0 (G2 -> 0 against 1/mu_o); the integrals
// are continuous there and tend to a nonzero limit (E -> 1 at alpha = 1), so
// mu_o = 0 is evaluated at this cosine, within 1e-11 of the limit down to
// alpha = 1.5e-5.
inline constexpr double kGrazingMu = 1e-16;

// Default absolute tolerance of the functions below.
inline constexpr double kGgxAbsTolerance = 1e-9;
// Absolute tolerance of the GGX quadrature tables (ggx_dfg, ggx_albedo,
// ggx_albedo_avg). The per-value error estimate stays below it and is
// honest, so with float rounding (at most 6e-8 below 1) every stored value
// is within 1e-7 of the exact integral; measured errors are near 1e-12.
inline constexpr double kGgxTableTolerance = 1e-8;

// Deterministic quadrature over the half vector. value = {A, B}, error = the
// estimated absolute error of each, evaluations = how many times the
// integrand over the azimuth was evaluated (the work). mu_o in [0, 1],
// alpha >= 0.
Estimate<2> ggx_split_sum(double mu_o, double alpha, Visibility vis, double abs_tol = kGgxAbsTolerance);

// E_avg(alpha) = 2 * integral of E(mu) mu dmu over [0, 1], by quadrature
// (evaluations: those of all its split sums).
Estimate<1> ggx_albedo_average(double alpha, Visibility vis, double abs_tol = kGgxAbsTolerance);

// Monte Carlo estimates by visible-normal sampling (Heitz 2018): value = the
// mean, error = its standard error. Reproducible for a given seed.
Estimate<2> ggx_split_sum_mc(double mu_o, double alpha, Visibility vis, long long samples,
                             std::uint64_t seed);
// E_avg by sampling mu with density 2 mu, then one visible normal per mu.
Estimate<1> ggx_albedo_average_mc(double alpha, Visibility vis, long long samples,
                                  std::uint64_t seed);

}  // namespace brdflut
