// The colours of the metal presets from their measured spectra: the exact
// conductor Fresnel reflectance at each wavelength, integrated over the CIE
// 1931 2-degree observer under CIE illuminant D65 and expressed in an RGB
// space (sRGB/Rec.709, ACEScg or Rec.2020), with the RGB parameters of the
// F82-tint (Hoffman 2023) and Gulbrandsen 2014 models and the error each
// reduction to three numbers leaves.
//
// Colorimetry (CIE 015:2018): a reflectance R(lambda) sampled at the 95
// wavelengths 360, 365, ..., 830 nm has the tristimulus values
//   XYZ = sum R S (xbar, ybar, zbar) / sum S ybar,
// S the D65 spectral power distribution (5 nm sums, as the CIE tabulates);
// a perfect reflector has the white point of the D65 data, Y = 1. XYZ goes to
// the space's white by the linear Bradford transform (the ACES white,
// x = 0.32168, y = 0.33767, for ACEScg; D65's published chromaticity,
// 0.3127, 0.3290, for the others), then to RGB by the matrix of the space's
// primaries and white, so that a perfect reflector is (1, 1, 1) in every
// space. Data: src/data/README.md.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace brdflut {

enum class ColourSpace { srgb, acescg, rec2020 };
std::string_view to_string(ColourSpace s);
// Throws brdflut::Error naming the allowed values.
ColourSpace colour_space_from_string(std::string_view s);
inline constexpr std::array<ColourSpace, 3> kColourSpaces = {ColourSpace::srgb, ColourSpace::acescg,
                                                             ColourSpace::rec2020};
// One line: the primaries and white of the space, and the adaptation.
std::string colour_space_description(ColourSpace s);

// The CIE data at 360, 365, ..., 830 nm.
inline constexpr int kCieSamples = 95;
inline constexpr double kCieFirstNm = 360.0, kCieStepNm = 5.0;
struct CieSample {
    double nm, xbar, ybar, zbar, d65;
};
const std::array<CieSample, kCieSamples>& cie_samples();

// Chromaticity (x, y) of a spectral power distribution sampled at the CIE
// wavelengths (the equal-energy one is 1/3, 1/3).
std::array<double, 2> chromaticity(const std::array<double, kCieSamples>& spd);

// Linear RGB of a reflectance sampled at the CIE wavelengths.
std::array<double, 3> reflectance_to_rgb(const std::array<double, kCieSamples>& reflectance, ColourSpace space);

// A metal preset's measured optical constants: rows (wavelength in um, n, k)
// of its refractiveindex.info file that cover 360 to 830 nm.
struct MetalSpectrum {
    std::string_view name;  // a --metal name, e.g. "gold"
    std::string_view file;  // src/data/metals/FILE
    std::vector<std::array<double, 3>> rows;
};
const std::vector<MetalSpectrum>& metal_spectra();
// Throws brdflut::Error listing the known names.
const MetalSpectrum& metal_spectrum(std::string_view name);
// {n, k} at `nm` nanometres, linear in wavelength between rows.
std::array<double, 2> metal_nk(const MetalSpectrum& m, double nm);

// RGB conductor Fresnel reflectance of the metal at cos(theta) = mu: the
// exact Fresnel at each wavelength, then reflectance_to_rgb.
std::array<double, 3> metal_fresnel_rgb(const MetalSpectrum& m, double mu, ColourSpace space);

// The RGB parameters of a metal in a space, and the largest difference over
// mu (at 201 mu in [0, 1] and per channel) between each reduced model's
// Fresnel and metal_fresnel_rgb.
struct MetalColours {
    std::array<double, 3> f0;         // metal_fresnel_rgb at mu = 1
    std::array<double, 3> f82_tint;   // t with F82-tint(1/7) = spectral F(1/7): spectral / Schlick(F0) at mu = 1/7
    // Gulbrandsen's g with r = F0 (held in [0, 0.9999], as his model needs
    // r < 1), matching the spectral F at mu = 1/7, clamped to [0, 1].
    std::array<double, 3> edge_tint;
    std::array<double, 3> average;    // 2 * integral of F(mu) mu dmu, spectral
    double error_schlick;             // Schlick with F0
    double error_f82;                 // F82-tint with F0 and f82_tint
    double error_gulbrandsen;         // Gulbrandsen's n, k from F0 and edge_tint, exact Fresnel
    double error_three_wavelengths;   // exact Fresnel of n, k at 650, 550, 450 nm (the --metal tables)
};
MetalColours metal_colours(const MetalSpectrum& m, ColourSpace space);

// Gulbrandsen 2014, "Artist Friendly Metallic Fresnel": the n and k of
// reflectivity r in [0, 1) and edge tint g in [0, 1].
std::array<double, 2> gulbrandsen_nk(double r, double g);

}  // namespace brdflut
