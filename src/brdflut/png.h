// PNG output (libpng): 8-bit RGB pictures (plots) and 16-bit data images
// (tables whose values lie in [0, 1]).
//
// Both writers are atomic like write_exr: the file is written to a temporary
// file in the destination folder and renamed into place only when complete,
// so a failure never leaves a partial or stale file under the final name.
// Rows are stored in the order given: row 0 is the top row of the image.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace brdflut {

// Text chunks to store in the file (keyword, text). Keywords are 1 to 79
// printable Latin-1 characters; text is UTF-8 (stored as compressed iTXt).
using PngText = std::vector<std::pair<std::string, std::string>>;

// An 8-bit sRGB picture: rgb holds width * height * 3 bytes, row-major.
// Throws brdflut::Error for inconsistent sizes, brdflut::RuntimeError when
// the file cannot be written.
void write_png_rgb8(const std::string& path, int width, int height,
                    const std::vector<std::uint8_t>& rgb, const PngText& text = {});

// A 16-bit image of data values in [0, 1]: channels 1 (grey), 2 (grey, alpha),
// 3 (RGB) or 4 (RGBA), interleaved, row-major. Each value v is stored as
// round(v * 65535); no colour-space chunk is written (the samples are data,
// not colours). Refuses, before creating any file, a value that is NaN or
// outside [0, 1], naming the first offending index, pixel, channel and value
// (brdflut::Error). Throws brdflut::RuntimeError when the file cannot be written.
void write_png16(const std::string& path, int width, int height, int channels,
                 const std::vector<double>& values_0_1, const PngText& text = {});

// An 8- or 16-bit image of integer samples (`bits` 8 or 16), channels as
// write_png16, no colour-space chunk. Throws brdflut::Error for inconsistent
// sizes or a sample that does not fit, RuntimeError when the file cannot be
// written.
void write_png_samples(const std::string& path, int width, int height, int channels, int bits,
                       const std::vector<std::uint16_t>& samples, const PngText& text = {});

// The 16-bit sample stored for a value v in [0, 1]: round(v * 65535).
std::uint16_t png16_sample(double v);

}  // namespace brdflut
