// Directional albedo of the Disney lobes and of the Oren-Nayar family:
//
//   E(mu_o, p) = integral over the upper hemisphere of f(wo, wi; p) cos(theta_i) dw_i
//   E_avg(p)   = 2 * integral of E(mu) mu dmu over [0, 1]
//
// per unit base colour, p the lobe's parameter (roughness, clearcoat gloss or
// sigma; ignored by the sheen lobe). Two independent routes: deterministic
// quadrature (the default) and a seeded Monte Carlo estimate.
#pragma once

#include <cstdint>
#include <string_view>

#include "brdflut/math.h"
#include "brdflut/quadrature.h"

namespace brdflut {

enum class Lobe {
    disney_diffuse,     // p = perceptual roughness r in [0, 1]
    disney_subsurface,  // p = perceptual roughness r in [0, 1]
    disney_sheen,       // no parameter
    disney_clearcoat,   // p = clearcoat gloss g in [0, 1]
    oren_nayar,         // p = sigma in radians, >= 0
    fujii_oren_nayar,   // p = sigma in [0, 1]
    eon,                // p = sigma in [0, 1]
};
std::string_view to_string(Lobe lobe);

// The lobe's BRDF f(wo, wi; p) per unit base colour, evaluated pointwise
// (disney.h, oren_nayar.h): the value the Monte Carlo route and the tables'
// independent checks integrate.
double lobe_brdf(Lobe lobe, const Vec3& wo, const Vec3& wi, double p);

// Absolute tolerance of the quadrature at default settings.
inline constexpr double kLobeAbsTolerance = 1e-9;

// Deterministic quadrature; error = the estimated absolute error. mu_o in [0, 1].
Estimate<1> lobe_albedo(Lobe lobe, double mu_o, double p, double abs_tol = kLobeAbsTolerance);
Estimate<1> lobe_albedo_average(Lobe lobe, double p, double abs_tol = kLobeAbsTolerance);

// Monte Carlo: value = the mean, error = its standard error. wi is drawn from
// the cosine-weighted hemisphere (the clearcoat: from the GTR1 half-vector
// distribution); the average draws mu with density 2 mu first. The estimator
// evaluates the BRDFs of disney.h and oren_nayar.h pointwise, independently
// of the quadrature's reduced integrands. Reproducible for a given seed.
Estimate<1> lobe_albedo_mc(Lobe lobe, double mu_o, double p, long long samples, std::uint64_t seed);
Estimate<1> lobe_albedo_average_mc(Lobe lobe, double p, long long samples, std::uint64_t seed);

}  // namespace brdflut
