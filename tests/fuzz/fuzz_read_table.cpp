// libFuzzer target: the table reader (OpenEXR and the brdflut metadata JSON)
// must turn any input into either a table or a brdflut::RuntimeError, never a
// crash, a hang or another exception. Build with the `fuzz` CMake preset.
#include <cstddef>
#include <cstdint>

#include "brdflut/error.h"
#include "brdflut/exr.h"
#include "brdflut/lut.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const brdflut::ExrImage img = brdflut::read_exr_memory(reinterpret_cast<const char*>(data), size, "input");
        if (img.has_metadata) {
            const brdflut::LutDescription d = brdflut::describe_from_metadata(img, "input");
            brdflut::check_fits(img, d, "input");
        }
    } catch (const brdflut::RuntimeError&) {
        // The expected outcome for bad input.
    }
    return 0;
}
