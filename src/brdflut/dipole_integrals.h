// Integrals of the dipole profile by routes independent of its closed forms:
// adaptive quadrature of 2 pi r R_d(r) and a seeded Monte Carlo estimate.
// The tests compare both against Dipole::reflectance_within and
// dipole_total_reflectance.
#pragma once

#include <cstdint>

#include "brdflut/dipole.h"
#include "brdflut/quadrature.h"

namespace brdflut {

// integral of 2 pi r R_d(r) dr over [0, r_max] (r_max may be +infinity) by
// adaptive Gauss-Kronrod in x = r / (r + z_r), which maps [0, inf) onto
// [0, 1) and keeps the 1/r^2 tail of a non-absorbing medium smooth.
// value = the integral, error = the estimated absolute error.
Estimate<1> dipole_reflectance_quadrature(const Dipole& d, double r_max, double abs_tol);

// The total reflectance by Monte Carlo: r drawn from the mixture, with
// weights 1/2 each, of the densities z / (r + z)^2 for z = z_r and z = z_v
// (heavy-tailed, so the variance stays finite without absorption); each
// sample contributes 2 pi r R_d(r) / pdf(r). value = the mean, error = its
// standard error.
Estimate<1> dipole_total_reflectance_mc(const Dipole& d, long long samples, std::uint64_t seed);

}  // namespace brdflut
