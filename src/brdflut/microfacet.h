// GGX (Trowbridge-Reitz) microfacet distribution and Smith masking.
//
// Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces"
// Heitz 2014, "Understanding the Masking-Shadowing Function in
//             Microfacet-Based BRDFs"
// Heitz 2018, "Sampling the GGX Distribution of Visible Normals"
//
// Conventions: isotropic, alpha is the GGX width (alpha = roughness^2 when
// roughness is the perceptual roughness used by engines), directions are in
// the shading frame with the normal along +z.
#pragma once

#include <string>
#include <string_view>

#include "brdflut/math.h"

namespace brdflut {

// Engines expose a perceptual roughness r and use alpha = r^2.
constexpr double alpha_from_perceptual(double roughness) { return roughness * roughness; }

// Which shadowing-masking term a microfacet BRDF uses.
enum class Visibility {
    height_correlated,  // G2 = 1 / (1 + Lambda(o) + Lambda(i))       (Heitz 2014)
    separable,          // G2 = G1(o) G1(i)
    schlick_smith,      // G2 = G1_s(o) G1_s(i), G1_s(mu) = mu / (mu (1 - k) + k), k = alpha / 2
                        // (Karis 2013, "Real Shading in Unreal Engine 4", for image lighting)
    smith_joint_approx, // G2 = 2 mu_o mu_i / (mu_i (mu_o (1 - a) + a) + mu_o (mu_i (1 - a) + a)), a = alpha:
                        // Unreal's Vis_SmithJointApprox (a linear approximation of the height-correlated
                        // G2, Heitz 2014), with which UE4 and UE5 build their PreintegratedGF texture
};
std::string_view to_string(Visibility v);
Visibility visibility_from_string(std::string_view s);  // throws brdflut::Error

struct Ggx {
    double alpha;

    // Normal distribution D(m), density of microfacet normals per unit
    // projected area: integral of D(m) cos(theta_m) dw_m = 1.
    double D(double cos_theta_m) const {
        if (cos_theta_m <= 0.0) return 0.0;
        const double a2 = alpha * alpha;
        const double c2 = cos_theta_m * cos_theta_m;
        const double t = c2 * (a2 - 1.0) + 1.0;
        return a2 / (kPi * t * t);
    }

    // Smith Lambda for a direction at cos(theta) = mu:
    // Lambda = (-1 + sqrt(1 + alpha^2 tan^2(theta))) / 2, written as
    // (sqrt(mu^2 + alpha^2 (1 - mu^2)) - mu) / (2 mu), which stays accurate
    // for small alpha and grazing mu.
    double lambda(double mu) const {
        if (mu <= 0.0) return HUGE_VAL;
        const auto [num, den] = lambda_parts(mu);
        return num / den;
    }

    // Lambda(mu) = num / den for mu > 0, both positive: num = alpha^2 (1 -
    // mu^2), den = 2 mu (r + mu), r = sqrt(mu^2 + alpha^2 (1 - mu^2))
    // (r - mu = num / (r + mu) avoids cancellation).
    struct LambdaParts {
        double num, den;
    };
    LambdaParts lambda_parts(double mu) const {
        const double mu2 = mu * mu;
        const double r = std::sqrt(mu2 + alpha * alpha * (1.0 - mu2));
        return {alpha * alpha * (1.0 - mu2), (r + mu) * 2.0 * mu};
    }

    double G1(double mu) const {
        if (mu <= 0.0) return 0.0;
        return 1.0 / (1.0 + lambda(mu));
    }

    // Schlick's approximation of G1 with k = alpha / 2 (Karis 2013): not a
    // Smith term of any distribution, but UE4's split-sum table uses it.
    double G1_schlick(double mu) const {
        if (mu <= 0.0) return 0.0;
        const double k = 0.5 * alpha;
        return mu / (mu * (1.0 - k) + k);
    }

    // Unreal's Vis_SmithJointApprox as a G2 (Vis = G2 / (4 mu_o mu_i)):
    // equal to the height-correlated G2 at alpha = 0 and alpha = 1.
    double G2_joint_approx(double mu_o, double mu_i) const {
        if (mu_o <= 0.0 || mu_i <= 0.0) return 0.0;
        const double a = alpha;
        return 2.0 * mu_o * mu_i / (mu_i * (mu_o * (1.0 - a) + a) + mu_o * (mu_i * (1.0 - a) + a));
    }

    double G2(double mu_o, double mu_i, Visibility vis) const {
        if (mu_o <= 0.0 || mu_i <= 0.0) return 0.0;
        if (vis == Visibility::separable) return G1(mu_o) * G1(mu_i);
        if (vis == Visibility::schlick_smith) return G1_schlick(mu_o) * G1_schlick(mu_i);
        if (vis == Visibility::smith_joint_approx) return G2_joint_approx(mu_o, mu_i);
        return 1.0 / (1.0 + lambda(mu_o) + lambda(mu_i));
    }

    // Visible normal for direction wo (wo.z > 0) from two uniform numbers
    // (Heitz 2018). Density: G1(wo) max(0, wo.m) D(m) / wo.z.
    Vec3 sample_visible_normal(const Vec3& wo, double u1, double u2) const;
};

}  // namespace brdflut
