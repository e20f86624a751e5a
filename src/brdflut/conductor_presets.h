// Complex indices of refraction eta + i k of common metals (relative to air
// or vacuum) at three wavelengths, for R, G and B: 650, 550 and 450 nm.
//
// Values are linear interpolations in wavelength of the tabulated data of the
// refractiveindex.info database (Polyanskiy 2024, "Refractiveindex.info
// database of optical constants", Sci. Data 11, 94), data sets:
//
//   gold, silver, copper     Johnson and Christy 1972, "Optical constants of
//                            the noble metals", Phys. Rev. B 6, 4370
//   iron, chromium,          Johnson and Christy 1974, "Optical constants of
//   titanium, nickel         transition metals: Ti, V, Cr, Mn, Fe, Co, Ni, and
//                            Pd", Phys. Rev. B 9, 5056
//   aluminium                Rakic 1995, "Algorithm for the determination of
//                            intrinsic optical constants of metal films:
//                            application to aluminum", Appl. Opt. 34, 4755
//   platinum                 Rakic et al. 1998, "Optical properties of
//                            metallic films for vertical-cavity optoelectronic
//                            devices", Appl. Opt. 37, 5271 (Brendel-Bormann fit)
//   zinc                     Werner et al. 2009, "Optical constants and
//                            inelastic electron-scattering data for 17
//                            elemental metals", J. Phys. Chem. Ref. Data 38,
//                            1013 (from electron energy-loss spectra)
//
// Room-temperature bulk or thick-film values; real surfaces (oxide layers,
// roughness, alloys) differ. A single wavelength per channel is a point
// sample, not an average over a colour filter.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace brdflut {

// Wavelengths of the R, G, B channels of every preset, in nanometres.
inline constexpr std::array<double, 3> kPresetWavelengthsNm = {650.0, 550.0, 450.0};

struct ConductorPreset {
    std::string_view name;    // e.g. "gold"
    std::array<double, 3> eta;  // real part per channel R, G, B
    std::array<double, 3> k;    // extinction coefficient per channel
    std::string_view source;  // the published data set
};

const std::vector<ConductorPreset>& conductor_presets();

// The preset of that name; throws brdflut::Error listing the known names.
const ConductorPreset& conductor_preset(std::string_view name);

}  // namespace brdflut
