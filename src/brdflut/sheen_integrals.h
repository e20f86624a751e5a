// Directional albedo of the Charlie sheen lobe (sheen.h), no Fresnel:
//
//   E(mu_o, alpha) = integral of D(h) V(mu_o, mu_i) cos(theta_i) dw_i
//
// Filament's cloth DFG term. Neubelt's V is not energy conserving: E grows
// without bound as mu_o -> 0 and alpha -> 0 together (E(0, alpha) ~ alpha^-1/2).
#pragma once

#include <cstdint>

#include "brdflut/quadrature.h"

namespace brdflut {

inline constexpr double kSheenAbsTolerance = 1e-9;

// Deterministic quadrature over the half vector; mu_o in [0, 1], alpha in
// [0, 1]. At alpha = 0 the lobe vanishes (E = 0, the limit for mu_o > 0).
Estimate<1> sheen_charlie_albedo(double mu_o, double alpha, double abs_tol = kSheenAbsTolerance);

// Monte Carlo: wi from an equal mixture of the uniform hemisphere and the
// reflection of Charlie-distributed normals; value = mean, error = standard error.
Estimate<1> sheen_charlie_albedo_mc(double mu_o, double alpha, long long samples, std::uint64_t seed);

}  // namespace brdflut
