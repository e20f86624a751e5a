// The dipole diffusion model of subsurface scattering: radial diffuse
// reflectance profile, its closed-form integrals, and the inverse of the
// total reflectance.
//
// Jensen, Marschner, Levoy and Hanrahan 2001, "A Practical Model for
// Subsurface Light Transport" (the dipole and the measured
// coefficients).
// Jensen and Buhler 2002, "A Rapid Hierarchical Rendering Technique for
// Translucent Materials" (the total diffuse reflectance and its inversion).
// Egan and Hilgeman 1979, "Optical Properties of Inhomogeneous Materials"
// (the polynomial fit of the diffuse Fresnel reflectance).
//
// Units: sigma_s_prime (reduced scattering) and sigma_a (absorption) are in
// 1/length; r is a distance on the surface in the same length unit; R_d(r)
// is per unit area (1/length^2). Total reflectances and albedos are unitless.
//
// eta is the relative index n_medium / n_outside (1.3 for the measured
// materials). F_dr is the diffuse Fresnel reflectance seen from INSIDE the
// medium: light leaving the medium crosses an interface of relative index
// (in fresnel.h's convention, transmitted over incident) n_outside / n_medium
// = 1 / eta, so the exact F_dr is fresnel_dielectric_average(1 / eta).
// At eta = 1.3 the fit gives 0.44476 and the exact average 0.44446.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace brdflut {

// How F_dr is computed: the Egan-Hilgeman fit Jensen uses, or the exact
// hemispherical average of the dielectric Fresnel reflectance.
enum class DiffuseFresnel { fit, exact };
std::string_view to_string(DiffuseFresnel f);
DiffuseFresnel diffuse_fresnel_from_string(std::string_view s);  // throws brdflut::Error

// Range of eta each F_dr accepts. The fit is negative below eta = 1 and
// exceeds 1 near eta = 3.94; it stays within 0.002 of the exact value for
// 1 <= eta <= 2 and within 0.016 at eta = 3.
inline constexpr double kDipoleFitEtaMin = 1.0;
inline constexpr double kDipoleFitEtaMax = 3.0;
inline constexpr double kDipoleExactEtaMax = 10.0;

// Throws brdflut::Error (naming --eta, the value and the allowed range) when
// eta is not accepted by the chosen F_dr.
void validate_dipole_eta(double eta, DiffuseFresnel f);

// F_dr = -1.440 / eta^2 + 0.710 / eta + 0.668 + 0.0636 eta.
double diffuse_fresnel_reflectance_fit(double eta);
// F_dr = fresnel_dielectric_average(1 / eta), exact to ~1e-14.
double diffuse_fresnel_reflectance_exact(double eta);
double diffuse_fresnel_reflectance(double eta, DiffuseFresnel f);

// The boundary term A = (1 + F_dr) / (1 - F_dr).
double dipole_boundary_term(double F_dr);

// One dipole: a medium with reduced scattering sigma_s_prime and absorption
// sigma_a (both >= 0, sum > 0) under a boundary with term A.
class Dipole {
public:
    Dipole(double sigma_s_prime, double sigma_a, double A);
    // The dimensionless dipole: lengths in reduced mean free paths 1/sigma_t',
    // so sigma_t' = 1, sigma_s' = albedo, sigma_a = 1 - albedo.
    static Dipole from_albedo(double albedo, double A);

    double albedo() const { return albedo_; }      // a' = sigma_s' / sigma_t'
    double sigma_t() const { return sigma_t_; }    // sigma_t' = sigma_a + sigma_s'
    double sigma_tr() const { return sigma_tr_; }  // sqrt(3 sigma_a sigma_t')
    double z_r() const { return z_r_; }            // depth of the real source, 1/sigma_t'
    double z_v() const { return z_v_; }            // height of the virtual source
    double boundary_term() const { return A_; }

    // R_d(r) = (a'/4pi) [z_r (1 + s_tr d_r) e^(-s_tr d_r)/d_r^3
    //                    + z_v (1 + s_tr d_v) e^(-s_tr d_v)/d_v^3], r >= 0.
    double profile(double r) const;
    // integral of 2 pi r' R_d(r') dr' over [0, r] (r may be infinite), in
    // closed form: each term integrates to 2 pi z [e^(-s_tr z)/z - e^(-s_tr d)/d].
    double reflectance_within(double r) const;
    // The total diffuse reflectance (r -> infinity).
    double total_reflectance() const;
    // reflectance_within(r) / total_reflectance(), in [0, 1]. The albedo
    // cancels, so at albedo 0 this is the finite limit albedo -> 0.
    double cdf(double r) const;

private:
    // reflectance_within / (a'/2): the sum over both sources of
    // e^(-s_tr z) - (z/d) e^(-s_tr d), without cancellation at small r.
    double shape_within(double r) const;
    double shape_total() const;

    double albedo_, sigma_t_, sigma_tr_, z_r_, z_v_, A_;
};

// Total diffuse reflectance of the dipole for reduced albedo a' in [0, 1]:
// (a'/2) (1 + e^(-(4/3) A sqrt(3(1 - a')))) e^(-sqrt(3(1 - a'))).
// It rises monotonically from 0 at a' = 0 to 1 at a' = 1 for every A.
double dipole_total_reflectance(double albedo, double A);

// The albedo a' whose total reflectance is R, for R in [0, 1]: safeguarded
// Newton on s = sqrt(3(1 - a')), where the total is smooth with a nonzero
// slope everywhere (in a' its slope is infinite at a' = 1). Accurate to about
// 1e-15; *error (if given) receives an estimate of the absolute error in a'.
double dipole_albedo_from_reflectance(double R, double A, double* error = nullptr);

// Measured coefficients of Jensen et al. 2001, Figure 5, in 1/mm (R, G, B).
struct MeasuredMaterial {
    const char* name;
    std::array<double, 3> sigma_s_prime;
    std::array<double, 3> sigma_a;
};
const std::vector<MeasuredMaterial>& measured_materials();
// Throws brdflut::Error listing the known names when name is unknown.
const MeasuredMaterial& find_measured_material(const std::string& name);

}  // namespace brdflut
