// brdflut metals: the RGB colours of the metal presets from their measured
// spectra (brdflut/spectral.h), per colour space.
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdflut/spectral.h"
#include "cli/commands.h"

namespace brdflut::cli {

int run_metals(const MetalsArgs& a) {
    const ColourSpace space = colour_space_from_string(a.colour_space);
    std::vector<const MetalSpectrum*> metals;
    if (a.metal.empty())
        for (const MetalSpectrum& m : metal_spectra()) metals.push_back(&m);
    else
        metals.push_back(&metal_spectrum(a.metal));
    std::vector<MetalColours> colours;
    for (const MetalSpectrum* m : metals) colours.push_back(metal_colours(*m, space));
    if (a.json) {
        nlohmann::json out = {{"colour_space", to_string(space)},
                              {"colorimetry", colour_space_description(space)},
                              {"metals", nlohmann::json::array()}};
        for (std::size_t i = 0; i < metals.size(); ++i) {
            const MetalSpectrum* m = metals[i];
            const MetalColours& c = colours[i];
            out["metals"].push_back({{"name", m->name},
                                     {"data", "src/data/metals/" + std::string(m->file)},
                                     {"f0", c.f0},
                                     {"f82_tint", c.f82_tint},
                                     {"edge_tint", c.edge_tint},
                                     {"average", c.average},
                                     {"max_error",
                                      {{"schlick", c.error_schlick},
                                       {"f82_tint", c.error_f82},
                                       {"gulbrandsen", c.error_gulbrandsen},
                                       {"three_wavelengths", c.error_three_wavelengths}}}});
        }
        std::cout << out.dump(2) << "\n";
        return 0;
    }
    std::cout << colour_space_description(space) << "\n\n";
    std::cout << "metal      F0 (R G B)             F82 tint               edge tint (g)          F_avg\n";
    char line[256];
    for (std::size_t i = 0; i < metals.size(); ++i) {
        const MetalSpectrum* m = metals[i];
        const MetalColours& c = colours[i];
        std::snprintf(line, sizeof line,
                      "%-10s %.4f %.4f %.4f  %.4f %.4f %.4f  %.4f %.4f %.4f  %.4f %.4f %.4f\n",
                      std::string(m->name).c_str(), c.f0[0], c.f0[1], c.f0[2], c.f82_tint[0], c.f82_tint[1],
                      c.f82_tint[2], c.edge_tint[0], c.edge_tint[1], c.edge_tint[2], c.average[0], c.average[1],
                      c.average[2]);
        std::cout << line;
    }
    std::cout << "\nlargest |F - spectral F| over mu and channels\n";
    std::cout << "metal      Schlick   F82 tint  Gulbrandsen  650/550/450 nm\n";
    for (std::size_t i = 0; i < metals.size(); ++i) {
        const MetalSpectrum* m = metals[i];
        const MetalColours& c = colours[i];
        std::snprintf(line, sizeof line, "%-10s %.2e  %.2e  %.2e     %.2e\n", std::string(m->name).c_str(),
                      c.error_schlick, c.error_f82, c.error_gulbrandsen, c.error_three_wavelengths);
        std::cout << line;
    }
    return 0;
}

}  // namespace brdflut::cli
