// Prints E_avg(alpha = 1) of GGX, read from the tables generated at build
// time: the embedded C++ header and the OpenEXR file (through the library).
// The exact value is (4/3)(1 - ln 2) = 0.4091370926.
#include <cstdio>
#include <exception>
#include <string>

#include <brdflut/catalogue.h>
#include <brdflut/exr.h>

#ifdef CONSUMER_CPP_HEADER
#include "ggx_albedo_avg.h"
#endif

int main() {
    try {
        const brdflut::TableDefinition& def = brdflut::find_table("ggx_albedo_avg");
        std::printf("table: %s: %s\n", def.id.c_str(), def.description.c_str());

#ifdef CONSUMER_CPP_HEADER
        // One row of `width` texels, one channel; the last is alpha = 1.
        namespace lut = brdflut_luts::ggx_albedo_avg;
        std::printf("header E_avg(alpha = 1) = %.9f\n", static_cast<double>(lut::data[lut::width - 1]));
#endif

        const brdflut::ExrImage image = brdflut::read_exr(CONSUMER_EXR_FILE);
        const std::size_t channels = image.channel_names.size();
        const double last = image.pixels[(static_cast<std::size_t>(image.width) - 1) * channels];
        const nlohmann::json& alpha = image.metadata.at("axes").at(0);
        std::printf("exr E_avg(alpha = %g) = %.9f (%d texels, %s)\n", alpha.at("max").get<double>(), last,
                    image.width, alpha.at("placement").get<std::string>().c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "consumer: %s\n", e.what());
        return 1;
    }
    return 0;
}
