// Fresnel reflectance of smooth interfaces.
//
// Born and Wolf 1999, "Principles of Optics", section 1.5 (Fresnel equations)
// and section 14.2 (conductors: the same equations with a complex index).
//
// eta is the relative index eta_t / eta_i (the medium light enters over the
// medium it comes from); k is the extinction coefficient of a conductor,
// whose complex relative index is eta + i k. cos_i is the cosine of the
// incident angle, in [0, 1].
#pragma once

#include <string_view>

namespace brdflut {

// Unpolarized reflectance of a dielectric interface: (Rs + Rp) / 2. For
// eta < 1 beyond the critical angle (total internal reflection) it is 1.
double fresnel_dielectric(double cos_i, double eta);

// The s- and p-polarized amplitude reflectances (signed) of a dielectric
// interface; both are 1 in magnitude under total internal reflection.
struct FresnelAmplitudes {
    double rs, rp;
};
FresnelAmplitudes fresnel_dielectric_amplitudes(double cos_i, double eta);

// Hemispherical average F_avg(eta) = 2 * integral of F(mu) mu dmu over [0, 1],
// by adaptive quadrature (split at the critical angle when eta < 1).
double fresnel_dielectric_average(double eta);

// The same average in closed form, valid for eta >= 1 (throws brdflut::Error
// otherwise). Inside the denser medium use F_avg(1/n) = 1 - (1 - F_avg(n)) / n^2.
// Relative accuracy about 1e-13 for eta >= 1.01; closer to 1 the terms cancel
// (about 1e-16 / (eta - 1)^2 relative).
double fresnel_dielectric_average_closed_form(double eta);

// Unpolarized reflectance of a conductor with complex relative index
// eta + i k (eta > 0, k >= 0), exact: cos(theta_t) is complex. With k = 0 it
// equals fresnel_dielectric, total internal reflection included.
double fresnel_conductor(double cos_i, double eta, double k);

// The real-valued approximation used by several renderers (pbrt-v2 FrCond,
// Mitsuba 0.5 fresnelConductorApprox):
//   r_par^2  = ((eta^2 + k^2) cos^2 - 2 eta cos + 1) / ((eta^2 + k^2) cos^2 + 2 eta cos + 1)
//   r_perp^2 = ((eta^2 + k^2) - 2 eta cos + cos^2) / ((eta^2 + k^2) + 2 eta cos + cos^2)
// Exact only at normal incidence (and at grazing, where both give 1).
double fresnel_conductor_approx(double cos_i, double eta, double k);

// Which conductor formula a table uses.
enum class FresnelForm { exact, approx };
std::string_view to_string(FresnelForm f);
FresnelForm fresnel_form_from_string(std::string_view s);  // throws brdflut::Error
double fresnel_conductor(double cos_i, double eta, double k, FresnelForm form);

}  // namespace brdflut
