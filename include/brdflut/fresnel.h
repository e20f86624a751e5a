// Fresnel reflectance of smooth interfaces.
//
// Born and Wolf 1999, "Principles of Optics", section 1.5 (Fresnel equations).
//
// eta is the relative index eta_t / eta_i (the medium light enters over the
// medium it comes from); cos_i is the cosine of the incident angle, in [0, 1].
#pragma once

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

}  // namespace brdflut
