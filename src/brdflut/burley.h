// Burley's normalized diffusion profile of subsurface scattering: the radial
// profile, its radial CDF and the inverse of the CDF (importance sampling of
// radii), the scaling factors s(A) of its three parametrizations, and the
// transmission through a slab as Unreal Engine defines it.
//
// Christensen and Burley 2015, "Approximate Reflectance Profiles for
// Efficient Subsurface Scattering" (the profile, its CDF and the three
// fitted scalings).
//
// Units: the profile is self-similar in x = r / d, d = l / s(A), where l is a
// mean free path (of the volume, or the diffuse mean free path on the surface
// for the third scaling); R(r) = A s (e^(-s r) + e^(-s r / 3)) / (8 pi r)
// with s = 1 / d. With d = 1 and A = 1 the profile is
// R(x) = (e^(-x) + e^(-x/3)) / (8 pi x), and 2 pi x R(x) integrates to 1.
#pragma once

#include <string>
#include <string_view>

namespace brdflut {

// R(x) d^2 / A = (e^(-x) + e^(-x/3)) / (8 pi x), x = r / d > 0 (infinite at 0).
double burley_profile(double x);
// 2 pi x R(x) d / A = (e^(-x) + e^(-x/3)) / 4: the radial density of x, finite
// at 0 (1/2), integrating to 1 over [0, inf).
double burley_radial_density(double x);
// CDF(x) = 1 - e^(-x)/4 - 3 e^(-x/3)/4 (computed with expm1, so exact to the
// last bits near 0); x = inf gives 1.
double burley_cdf(double x);
// 1 - CDF(x) = e^(-x)/4 + 3 e^(-x/3)/4, without cancellation for large x.
double burley_cdf_complement(double x);
// The x with CDF(x) = u, for u in [0, 1] (u = 1 gives +inf). In y = e^(-x/3)
// the CDF equation is the cubic y^3 + 3 y = 4 (1 - u), whose one real root is
// y = 2 sinh(asinh(2 (1 - u)) / 3) (Cardano, trigonometric form); two Newton
// steps on CDF(x) - u from there leave an error of a few ulps of x. *error (if
// given) receives an estimate of the absolute error in x.
double burley_inverse_cdf(double u, double* error = nullptr);

// The three scalings of the paper: d = l / s(A) with
//   searchlight           s = 1.85 - A + 7 |A - 0.8|^3   (l: volume mean free path, light entering
//                                                        perpendicular to the surface)
//   diffuse_transmission  s = 1.9 - A + 3.5 (A - 0.8)^2  (l: volume mean free path, diffuse
//                                                        transmission at the surface)
//   dmfp                  s = 3.5 + 100 (A - 0.33)^4     (l: diffuse mean free path on the
//                                                        surface)
enum class BurleyScaling { searchlight, diffuse_transmission, dmfp };
std::string_view to_string(BurleyScaling s);
BurleyScaling burley_scaling_from_string(std::string_view s);  // throws brdflut::Error
double burley_scaling(double albedo, BurleyScaling s);

// Transmission through a slab of thickness t as Unreal Engine defines it
// (BurleyNormalizedSSS.cpp, "integration from t to infty"): the part of the
// profile's reflectance beyond radius t, A (e^(-s t / l)/4 + 3 e^(-s t / (3 l))/4)
// = A (1 - CDF(t / d)), with t in units of l and s = burley_scaling(A, scaling).
// Unreal evaluates it with the diffuse-mean-free-path scaling, at t plus an
// offset of 0.06 (world units) "estimated from the sampling interval".
double burley_transmission(double thickness_over_l, double albedo, BurleyScaling s);

}  // namespace brdflut
