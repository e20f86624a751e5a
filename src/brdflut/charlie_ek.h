// Charlie sheen with the Estevez-Kulla shadowing, as a lobe of the generic
// path (generic_lobe.h).
//
// Estevez and Kulla 2017, "Production Friendly Microfacet Sheen BRDF"
//
// f(wo, wi) = D(h) G(wo, wi) / (4 mu_o mu_i), no Fresnel, with the Charlie
// D of sheen.h, D = (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi), and
//   G = 1 / (1 + Lambda(mu_o) + Lambda_l(mu_i))
//   Lambda(mu) = exp(L(mu))                   for mu < 1/2
//              = exp(2 L(1/2) - L(1 - mu))   otherwise
//   L(x) = a / (1 + b x^c) + d x + e,
// the five coefficients interpolated between the paper's fits at alpha = 0
// and alpha = 1 with weight t = (1 - alpha)^2 on the alpha = 0 set:
//   alpha = 0: a = 25.3245, b = 3.32435, c = 0.16801, d = -1.27393, e = -4.85967
//   alpha = 1: a = 21.5473, b = 3.82987, c = 0.19823, d = -1.97760, e = -4.32054
// (the constants and the interpolation as the glTF KHR_materials_sheen
// specification and HDRP's BSDF.hlsl CharlieL write them). Lambda_l is
// Lambda, or with the paper's terminator softening
//   Lambda_l(mu_i) = Lambda(mu_i)^(1 + 2 (1 - mu_i)^8)
// on the light (incident) direction only, which makes f non-reciprocal.
// Lambda is C1 at mu = 1/2 (the second branch reflects L about 1/2) but not
// C2: the lobe declares the cone mu_i = 1/2 as a kink to the generic path,
// and the mirror direction (D's |theta_h|^(1/alpha)) and the normal (the
// (1 - mu_i)^c of Lambda's second branch) as point kinks.
//
// The same lobe with Neubelt's visibility V = 1/(4 (mu_i + mu_o - mu_i mu_o))
// in place of G / (4 mu_o mu_i) is the lobe of sheen_charlie_albedo (sheen.h)
// through the generic path, for the tables that need its moments.
#pragma once

#include <cmath>
#include <string>

#include "brdflut/generic_lobe.h"
#include "brdflut/math.h"
#include "brdflut/sheen.h"

namespace brdflut {

// The shadowing (visibility) of a Charlie lobe.
enum class SheenShadowing {
    estevez_kulla,       // G of the Lambda fit, no softening (HDRP, glTF)
    estevez_kulla_soft,  // with the terminator softening on the light direction (the paper)
    neubelt,             // Neubelt and Pettineo's V (Filament, Unreal)
};
const char* to_string(SheenShadowing s);
// Throws brdflut::Error naming the allowed values.
SheenShadowing sheen_shadowing_from_string(const std::string& name);

// The fit at roughness alpha in [0, 1], its coefficients and L(1/2)
// computed once.
class EstevezKullaFit {
public:
    explicit EstevezKullaFit(double alpha);
    double L(double x) const;         // the fitted L(x)
    double lambda(double mu) const;   // Lambda(mu), mu in [0, 1]
    // Lambda of the light direction: Lambda(mu)^(1 + 2 (1 - mu)^8) when soft.
    double lambda_light(double mu, bool soft) const;

private:
    double a_, b_, c_, d_, e_, l_half_;
};

class CharlieLobe final : public GenericLobe {
public:
    CharlieLobe(double alpha, SheenShadowing shadowing) : charlie_{alpha}, shadowing_(shadowing), fit_(alpha) {}
    double f(const Vec3& wo, const Vec3& wi) const override;
    LobeHints hints(const Vec3& wo) const override;
    // Lambda(mu_o) is pieced together at mu_o = 1/2 (Estevez-Kulla).
    std::vector<double> view_kinks() const override {
        return shadowing_ == SheenShadowing::neubelt ? std::vector<double>{} : std::vector<double>{0.5};
    }
    // An equal mixture of the cosine-weighted hemisphere and the reflection
    // of normals drawn from D cos(theta_m) (sheen.h's sampler).
    bool has_sampler() const override { return true; }
    LobeSample sample(const Vec3& wo, double u1, double u2) const override;
    // sheen_charlie_moments, over the half vector.
    bool own_moments(double mu_o, double abs_tol, Estimate<2>& out) const override;
    double alpha() const { return charlie_.alpha; }
    SheenShadowing shadowing() const { return shadowing_; }

private:
    Charlie charlie_;
    SheenShadowing shadowing_;
    EstevezKullaFit fit_;
};

// The albedo E and the Fresnel moment F (f weighted by (1 - wo.h)^5) of
// the Charlie lobe with any of the shadowings, at mu_o in (0, 1] (clamped to
// at least 1e-12) and alpha in (0, 1], by quadrature over the half vector
// (src/integrate/sheen_albedo.cpp): the rule of sheen_charlie_albedo with
// the azimuth integrated numerically, since G has no closed form there.
// {value, estimated error, evaluations of G}. The same moments as
// generic_moments of the CharlieLobe with weights 1 and (1 - c)^5, by
// another route.
Estimate<2> sheen_charlie_moments(double mu_o, double alpha, SheenShadowing shadowing, double abs_tol);

// HDRP's fabric Lambert: f = (1 - alpha/2) / pi (HDRP's FabricLambert, an
// empirical diffuse term of its fabric material), whose albedo is 1 - alpha/2.
class FabricLambertLobe final : public GenericLobe {
public:
    explicit FabricLambertLobe(double alpha) : alpha_(alpha) {}
    double f(const Vec3& wo, const Vec3& wi) const override {
        return wo.z > 0.0 && wi.z > 0.0 ? (1.0 - 0.5 * alpha_) * kInvPi : 0.0;
    }

private:
    double alpha_;
};

}  // namespace brdflut
