// What the quadrature (ggx_glass.cpp) and the Monte Carlo estimates
// (ggx_glass_monte_carlo.cpp) of the GGX dielectric albedos share: the
// grazing limit of the view and the smooth interface, where there is
// nothing to integrate.
#pragma once

#include <algorithm>

#include "brdflut/fresnel.h"
#include "brdflut/quadrature.h"

namespace brdflut::detail {

// mu_o = 0 is taken at this cosine (see glass_integrals.h).
inline constexpr double kGlassGrazingMu = 1e-16;

// The smooth interface (alpha = 0): {F(mu), 1 - F(mu)}.
inline Estimate<2> glass_smooth_limit(double mu_o, double eta) {
    Estimate<2> out;
    const double F = fresnel_dielectric(std::min(mu_o, 1.0), eta);
    out.value = {F, 1.0 - F};
    return out;
}

}  // namespace brdflut::detail
