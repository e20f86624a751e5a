#include "brdflut/conductor_presets.h"

#include "brdflut/error.h"

namespace brdflut {

// See the header for the data sets; values interpolated to 650, 550, 450 nm.
const std::vector<ConductorPreset>& conductor_presets() {
    static const std::vector<ConductorPreset> all = {
        {"gold", {0.1556, 0.4241, 1.3831}, {3.6024, 2.4721, 1.9155},
         "Johnson and Christy 1972, Phys. Rev. B 6, 4370"},
        {"silver", {0.0522, 0.0596, 0.0400}, {4.4094, 3.5974, 2.6484},
         "Johnson and Christy 1972, Phys. Rev. B 6, 4370"},
        {"copper", {0.2378, 1.0066, 1.2404}, {3.6264, 2.5823, 2.3929},
         "Johnson and Christy 1972, Phys. Rev. B 6, 4370"},
        {"aluminium", {1.5580, 1.0152, 0.6332}, {7.7124, 6.6273, 5.4544},
         "Rakic 1995, Appl. Opt. 34, 4755"},
        {"iron", {2.9114, 2.9497, 2.5845}, {3.0893, 2.9318, 2.7670},
         "Johnson and Christy 1974, Phys. Rev. B 9, 5056"},
        {"chromium", {3.1071, 3.1812, 2.3230}, {3.3314, 3.3291, 3.1350},
         "Johnson and Christy 1974, Phys. Rev. B 9, 5056"},
        {"titanium", {2.7407, 2.5418, 2.2670}, {3.8143, 3.4345, 3.0385},
         "Johnson and Christy 1974, Phys. Rev. B 9, 5056"},
        {"nickel", {1.9900, 1.9212, 1.7290}, {4.2086, 3.6158, 2.9435},
         "Johnson and Christy 1974, Phys. Rev. B 9, 5056"},
        {"platinum", {2.3757, 2.0847, 1.8453}, {4.2655, 3.7153, 3.1365},
         "Rakic et al. 1998, Appl. Opt. 37, 5271 (Brendel-Bormann fit)"},
        {"zinc", {1.2338, 0.9294, 0.6777}, {5.8730, 4.9751, 4.0122},
         "Werner et al. 2009, J. Phys. Chem. Ref. Data 38, 1013"},
    };
    return all;
}

const ConductorPreset& conductor_preset(std::string_view name) {
    for (const ConductorPreset& p : conductor_presets())
        if (p.name == name) return p;
    std::string known;
    for (const ConductorPreset& p : conductor_presets())
        known += (known.empty() ? "" : ", ") + std::string(p.name);
    throw Error("--metal '" + std::string(name) + "' is not a known conductor; allowed: " + known);
}

}  // namespace brdflut
