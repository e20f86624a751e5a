// libFuzzer target: every table reader (OpenEXR, DDS, KTX2, PNG, NumPy .npy,
// arrays in source files, and the brdflut metadata JSON) must turn any input
// into either a table or a brdflut::RuntimeError, never a crash, a hang or
// another exception. Built in the `sanitize` CMake preset (clang).
//
// The first input byte picks the read options, the rest is the file:
//   bits 0-1: decode none, linear, srgb, or (3) read as a source file with
//             --array lut; bit 2: a given shape (4x4:1, or 2x2x2:2 with bit 3,
//             its channels stored as planes, 2x2x2:2p, with bit 5 too);
//             bit 4 (with bits 0-1 at 0): decode rgbd.
// The seeds in tests/fuzz/corpus carry that byte: 0x00 for binary files
// (the integer encodings among them: unorm8, unorm16, rgb10a2, rgbd with its
// metadata), 0x01 for PNGs without metadata, 0x03 for source files, 0x10 for
// an rgbd dds (which has no metadata).
#include <cstddef>
#include <cstdint>

#include "brdflut/error.h"
#include "brdflut/formats.h"
#include "brdflut/lut.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return 0;
    const std::uint8_t pick = data[0];
    brdflut::ReadOptions opt;
    switch (pick & 3) {
        case 1: opt.decode = brdflut::Decode::linear; break;
        case 2: opt.decode = brdflut::Decode::srgb; break;
        case 3: opt.array = "lut"; break;
        default:
            if (pick & 16) opt.decode = brdflut::Decode::rgbd;
            break;
    }
    if (pick & 4)
        opt.shape = (pick & 8) ? brdflut::ArrayShape{2, 2, 2, 2, (pick & 32) != 0} : brdflut::ArrayShape{4, 4, 1, 1};
    try {
        const brdflut::ExrImage img =
            brdflut::read_table_image_memory(reinterpret_cast<const char*>(data + 1), size - 1, "input", opt);
        if (img.has_metadata) {
            const brdflut::LutDescription d = brdflut::describe_from_metadata(img, "input");
            brdflut::check_fits(img, d, "input");
        }
    } catch (const brdflut::RuntimeError&) {
        // The expected outcome for bad input.
    }
    return 0;
}
