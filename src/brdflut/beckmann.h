// Beckmann microfacet distribution and its exact Smith masking.
//
// Beckmann and Spizzichino 1963, "The Scattering of Electromagnetic Waves
//             from Rough Surfaces"
// Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces"
// Heitz 2014, "Understanding the Masking-Shadowing Function in
//             Microfacet-Based BRDFs"
//
// Conventions as for GGX (microfacet.h): isotropic, directions in the shading
// frame with the normal along +z, alpha = perceptual_roughness^2. The slopes
// of the microfacets are Gaussian with standard deviation alpha / sqrt(2) per
// axis (alpha = sqrt(2) times the RMS slope along one axis; the RMS of the
// slope's length is alpha):
//
//   D(m) = exp(-tan^2(theta_m) / alpha^2) / (pi alpha^2 cos^4(theta_m)).
//
// Smith Lambda for a direction at angle theta, a = 1 / (alpha tan(theta)):
//
//   Lambda(a) = (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)),
//
// computed here as (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2, which loses no
// absolute accuracy for large a (both terms are below 1e-300 past a = 27,
// where Lambda is 0 in double) and behaves as 1 / (2 a sqrt(pi)) - 1/2 as
// a -> 0 (grazing directions).
#pragma once

#include <cmath>

#include "brdflut/generic_lobe.h"
#include "brdflut/math.h"
#include "brdflut/microfacet.h"

namespace brdflut {

struct Beckmann {
    double alpha;

    // D from tan^2(theta_m) and cos^2(theta_m) (pass values computed without
    // cancellation, e.g. from the half vector's components: near the normal
    // 1 - cos^2 loses the digits the exponent needs).
    double D_from_tan2(double tan2, double cos2) const {
        const double a2 = alpha * alpha;
        return std::exp(-tan2 / a2) / (kPi * a2 * cos2 * cos2);
    }
    // D(m) at cos(theta_m); 0 below the surface.
    double D(double cos_theta_m) const {
        if (cos_theta_m <= 0.0) return 0.0;
        const double c2 = cos_theta_m * cos_theta_m;
        return D_from_tan2((1.0 - c2) / c2, c2);
    }

    // a = 1 / (alpha tan(theta)) = mu / (alpha sqrt(1 - mu^2)); +inf at mu = 1.
    double a_of(double mu) const {
        const double s = std::sqrt((1.0 - mu) * (1.0 + mu));
        return mu / (alpha * s);
    }

    // Lambda as a function of a >= 0 (+inf at a = 0).
    static double lambda_of_a(double a);

    // Smith Lambda at cos(theta) = mu (+inf for mu <= 0, 0 at mu = 1).
    double lambda(double mu) const {
        if (mu <= 0.0) return HUGE_VAL;
        if (mu >= 1.0) return 0.0;
        return lambda_of_a(a_of(mu));
    }

    double G1(double mu) const {
        if (mu <= 0.0) return 0.0;
        return 1.0 / (1.0 + lambda(mu));
    }

    // Schlick's approximation of the Beckmann G1 (Schlick 1994):
    // mu / (mu (1 - k) + k) with k = alpha sqrt(2 / pi).
    double G1_schlick(double mu) const {
        if (mu <= 0.0) return 0.0;
        const double k = alpha * std::sqrt(2.0 / kPi);
        return mu / (mu * (1.0 - k) + k);
    }
    // height_correlated: 1 / (1 + Lambda(o) + Lambda(i)); separable:
    // G1(o) G1(i); schlick_smith: G1_schlick(o) G1_schlick(i).
    double G2(double mu_o, double mu_i, Visibility vis) const {
        if (mu_o <= 0.0 || mu_i <= 0.0) return 0.0;
        if (vis == Visibility::separable) return G1(mu_o) * G1(mu_i);
        if (vis == Visibility::schlick_smith) return G1_schlick(mu_o) * G1_schlick(mu_i);
        return 1.0 / (1.0 + lambda(mu_o) + lambda(mu_i));
    }

    // Single-scattering BRDF with F = 1, f = D(h) G2 / (4 mu_o mu_i), for
    // unit wo, wi (0 unless both are above the surface). The half vector's
    // tangent is taken from its components, so D keeps its relative accuracy
    // for alpha down to 1e-7 and below.
    double brdf(const Vec3& wo, const Vec3& wi, Visibility vis) const;

    // The same with Cook and Torrance's V-cavity shadowing-masking in place
    // of Smith's: G = min(1, 2 (n.h) min(n.o, n.i) / (o.h)) (o.h = i.h), the
    // Cook-Torrance BRDF that HDRP's Cook-Torrance LTC layer fits.
    double brdf_v_cavity(const Vec3& wo, const Vec3& wi) const;

    // A normal drawn with density D(m) cos(theta_m) from two uniform numbers
    // in [0, 1): tan^2(theta_m) = -alpha^2 ln(1 - u1), phi = 2 pi u2.
    Vec3 sample_normal(double u1, double u2) const;
};

// The single-scattering Beckmann BRDF (F = 1) as a generic lobe
// (generic_lobe.h): f = D G2 / (4 mu_o mu_i); peak at the mirror direction,
// width 2 alpha in the plane of incidence (wi turns twice as far as the half
// vector) and about mu_o + alpha times that across it; sampler: half vectors
// from D cos(theta_h), reflected.
class BeckmannLobe final : public GenericLobe {
public:
    BeckmannLobe(double alpha, Visibility vis) : model_{alpha}, vis_(vis) {}
    // The Cook-Torrance lobe: Beckmann D with the V-cavity G (brdf_v_cavity).
    static BeckmannLobe v_cavity(double alpha) {
        BeckmannLobe l(alpha, Visibility::height_correlated);
        l.v_cavity_ = true;
        return l;
    }
    double f(const Vec3& wo, const Vec3& wi) const override {
        return v_cavity_ ? model_.brdf_v_cavity(wo, wi) : model_.brdf(wo, wi, vis_);
    }
    LobeHints hints(const Vec3& wo) const override;
    bool has_sampler() const override { return true; }
    LobeSample sample(const Vec3& wo, double u1, double u2) const override;
    const Beckmann& model() const { return model_; }

private:
    Beckmann model_;
    Visibility vis_;
    bool v_cavity_ = false;
};

}  // namespace brdflut
