// The analytic volumetric sheen of Zeltner, Burley and Chiang 2022,
// "Practical Multiple-Scattering Sheen Using Linearly Transformed Cosines"
// (the "approx" reference BRDF the talk fits its LTC to, besides the
// simulated layer): a unit-thickness, unit-density, non-absorbing layer of
// fibre-like SGGX microflakes (Heitz et al. 2015, "The SGGX Microflake
// Distribution") standing along the normal, with cross-section ratio
// sigma = alpha^2 and the specular microflake phase function.
//
// SGGX of a fibre along z: S = diag(1, 1, sigma^2), so for a unit w the
// projected area and the distribution of flake normals are
//   s(w) = sqrt(w.x^2 + w.y^2 + sigma^2 w.z^2)
//   D(m) = sigma^3 / (pi (sigma^2 (1 - m.z^2) + m.z^2)^2),
// and the phase function is p(wo, wi) = D(h) / (4 s(wo)), h = normalize(wo + wi).
//
// Single scattering, exact for the layer (Beer-Lambert along both paths,
// optical depths lambda(w) = s(w) / cos(theta)):
//   f_ss = D(h) (1 - exp(-(lambda_o + lambda_i))) / (4 (s_o mu_i + s_i mu_o)).
// Multiple scattering, the talk's empirical fit to random walks:
//   f_ms = exp(b - m sqrt(mu_o^2 + mu_i^2)) T(mu_o) T(mu_i),
//   T(c) = beta + (1 - beta) (1 - (1 - c)^12), beta = max(0.55, 0.44 + 0.42 sigma),
// with m(sigma) and b(sigma) Catmull-Rom interpolations of the fitted values
// at sigma = 0, 0.1, ..., 1 (the end tangents by linear extrapolation):
//   m: 20, 10.2, 6.14, 4.30, 3.30, 2.55, 2.02, 1.63, 1.33, 1.1, 0.95
//   b: 3.7, 2.23, 1.06, 0.293, -0.212, -0.641, -0.952, -1.2, -1.4, -1.55, -1.65
// (tizian/ltc-sheen fitting/src/bsdfs/sheen_approx.h @92624114, Apache-2.0).
// f = f_ss + f_ms is reciprocal; no Fresnel.
#pragma once

#include <array>

#include "brdflut/generic_lobe.h"
#include "brdflut/math.h"

namespace brdflut {

// The fibre SGGX of cross-section ratio sigma in (0, 1].
struct FibreSggx {
    double sigma;
    double projected_area(const Vec3& w) const;
    double D(double cos_theta_m) const;
    // integral of D over the sphere: 2 (sigma + atan(sqrt(1 - sigma^2) / sigma) / sqrt(1 - sigma^2)).
    double total() const;
    // A flake normal's cos(theta) drawn with density 2 pi D(z) / total() on
    // [-1, 1] (inverting the closed-form distribution by bisection).
    double sample_cos_theta(double u) const;
};

// m(sigma), b(sigma) of the multiple-scattering fit, sigma in [0, 1].
std::array<double, 2> zeltner_ms_fit(double sigma);

class ZeltnerApproxSheenLobe final : public GenericLobe {
public:
    // alpha in (0, 1]: sigma = alpha^2.
    explicit ZeltnerApproxSheenLobe(double alpha);
    double f(const Vec3& wo, const Vec3& wi) const override;
    // The two terms apart: {f_ss, f_ms}.
    std::array<double, 2> terms(const Vec3& wo, const Vec3& wi) const;
    // An equal mixture of the cosine-weighted hemisphere and the mirror
    // directions of flake normals drawn from D (the single scattering's
    // shape: it is concentrated near the horizon for small alpha).
    bool has_sampler() const override { return true; }
    LobeSample sample(const Vec3& wo, double u1, double u2) const override;
    double alpha() const { return alpha_; }

private:
    double alpha_;
    FibreSggx sggx_;
    double m_, b_, beta_;
};

}  // namespace brdflut
