// Oren-Nayar rough diffuse models, per unit albedo (rho = 1).
//
// Oren and Nayar 1994, "Generalization of Lambert's Reflectance Model"
//   (the qualitative model, their equation 30).
// Fujii 2012, "A tiny improvement of Oren-Nayar reflectance model" (FON).
// Portsmouth, Kutz, Hill et al. 2025, "EON: A practical energy-preserving
//   rough diffuse BRDF" (the FON normalization used by OpenPBR, and EON).
//
// Directions are in the shading frame (normal +z); every BRDF is 0 below the
// horizon (wo on the horizon gives the limit value). sigma is the model's
// roughness: the standard deviation of the facet slope angle in radians for
// the qualitative model, a parameter in [0, 1] for FON and EON.
#pragma once

#include "brdflut/math.h"

namespace brdflut {

// Qualitative Oren-Nayar: f = (1/pi)(A + B max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta)),
// alpha = max(theta_i, theta_o), beta = min(theta_i, theta_o).
struct OrenNayar {
    double sigma;

    double A() const { return 1.0 - 0.5 * sqr(sigma) / (sqr(sigma) + 0.33); }
    double B() const { return 0.45 * sqr(sigma) / (sqr(sigma) + 0.09); }
    double brdf(const Vec3& wo, const Vec3& wi) const;
};

// Fujii Oren-Nayar in the OpenPBR normalization: f = (A/pi)(1 + sigma s/t),
// A = 1 / (1 + (1/2 - 2/(3 pi)) sigma), s = wi.wo - mu_i mu_o,
// s/t = s / max(mu_i, mu_o) when s > 0, s otherwise.
struct FujiiOrenNayar {
    double sigma;

    static constexpr double kC1 = 0.5 - 2.0 / (3.0 * kPi);
    static constexpr double kC2 = 2.0 / 3.0 - 28.0 / (15.0 * kPi);

    double A() const { return 1.0 / (1.0 + kC1 * sigma); }
    double brdf(const Vec3& wo, const Vec3& wi) const;

    // Exact directional albedo E(mu) = A + (sigma A / pi) G(theta), theta = acos(mu),
    // G = sin(theta)(theta - sin(theta) cos(theta))
    //     + (2/3)(tan(theta)(1 - sin^3(theta)) - sin(theta)).
    double albedo(double mu) const;
    // Exact average albedo 2 * integral of E(mu) mu dmu = A (1 + (2/3 - 28/(15 pi)) sigma).
    double average_albedo() const { return A() * (1.0 + kC2 * sigma); }
};

// EON at rho = 1: FON plus the multiple-scattering lobe
// (rho_ms/pi)(1 - E(mu_o))(1 - E(mu_i)) / (1 - E_avg) with rho_ms = 1, where E and
// E_avg are FON's exact albedo and average (not the paper's fitted
// approximations), so the total albedo is exactly 1.
struct Eon {
    FujiiOrenNayar fon;

    // The multiple-scattering lobe alone.
    double multiple_scattering_brdf(double mu_o, double mu_i) const;
    double brdf(const Vec3& wo, const Vec3& wi) const;
};

}  // namespace brdflut
