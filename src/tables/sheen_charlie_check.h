// An independent rule for the moments of the Charlie lobes (charlie_ek.h),
// shared by the family's checks and the engine presets' checks: nested
// adaptive Gauss-Kronrod over the half vector (theta_h, phi_h), which the
// generic lobe path (polar coordinates of wi) does not use.
#pragma once

#include <array>

#include "brdflut/charlie_ek.h"

namespace brdflut::tables {

// {E, F}: the integrals of f cos(theta_i) and f (1 - v.h)^5 cos(theta_i)
// over wi, to about 1e-10 (absolute). Slow (seconds to minutes) where both
// mu_o < 0.01 and alpha < 1e-3.
std::array<double, 2> charlie_moments_by_half_vector(double mu_o, double alpha, SheenShadowing shadowing);

}  // namespace brdflut::tables
