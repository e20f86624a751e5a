// Hemispherical averages of Fresnel reflectance,
//
//   F_avg = 2 * integral of F(mu) mu dmu over [0, 1],
//
// the albedo of a smooth interface under uniform illumination and the input
// of multiple-scattering Fresnel terms (Kulla and Conty 2017). Two
// independent routes: adaptive quadrature (the default) and Monte Carlo.
#pragma once

#include <cstdint>

#include "brdflut/fresnel.h"
#include "brdflut/quadrature.h"

namespace brdflut {

// Absolute tolerance of the quadrature at default settings.
inline constexpr double kFresnelAbsTolerance = 1e-11;

// Dielectric, relative index eta > 0; for eta < 1 the mu range is split at
// the critical cosine sqrt(1 - eta^2), below which F = 1.
Estimate<1> fresnel_dielectric_average_quadrature(double eta,
                                                  double abs_tol = kFresnelAbsTolerance);

// Conductor, index eta + i k (eta > 0, k >= 0). For eta < 1 the range is
// split at sqrt(1 - eta^2), where F has a square-root kink for k = 0 and a
// sharp bend for small k.
Estimate<1> fresnel_conductor_average_quadrature(double eta, double k,
                                                 FresnelForm form = FresnelForm::exact,
                                                 double abs_tol = kFresnelAbsTolerance);

// Monte Carlo: mu drawn with density 2 mu (mu = sqrt(1 - u)), so the mean
// of F(mu) estimates F_avg. value = the mean, error = its standard error.
Estimate<1> fresnel_dielectric_average_mc(double eta, long long samples, std::uint64_t seed);
Estimate<1> fresnel_conductor_average_mc(double eta, double k, FresnelForm form,
                                         long long samples, std::uint64_t seed);

}  // namespace brdflut
