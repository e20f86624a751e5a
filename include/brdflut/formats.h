// File formats a table can be written in, and one entry point that writes
// any of them.
//
//   exr    OpenEXR, half or float channels R, G, B, A (as many as the table
//          has); metadata in the string attribute `brdflut`.
//   cpp    C++17 header <id>.h: namespace brdflut_luts::<id> with
//          `inline constexpr` width, height, channels, data[] (float, or
//          std::uint16_t half bit patterns) and metadata[] (the JSON).
//   png16  16-bit PNG, values in [0, 1] only, stored as round(v * 65535).
//          1 channel: grey; 2 channels: RGB with B = 0 (not grey + alpha,
//          which engines expand to (R, R, R, G)); 3: RGB; 4: RGBA.
//          Metadata in the compressed iTXt chunk with keyword `brdflut`.
//   dds    DirectDraw Surface with the DX10 header extension, a 2-D texture
//          (height 1 for one-axis tables), one mip level.
//   ktx2   KTX 2.0, a 2-D texture (pixelHeight 1 for one-axis tables), one
//          level, no supercompression; metadata in the key `brdflut`.
//
// dds and ktx2 store 1, 2 or 4 channels as R16_FLOAT / R16G16_FLOAT /
// R16G16B16A16_FLOAT (half) or R32_FLOAT / R32G32_FLOAT / R32G32B32A32_FLOAT
// (float); a 3-channel table is stored as 4 channels with A = 1, because no
// 3-channel 16-bit float texture format exists in DXGI and the 3-channel
// Vulkan formats are rarely sampleable. Row 0 of every image is the first
// row of the table (index 0 of the second axis), data little-endian.
#pragma once

#include <string>
#include <string_view>

#include "brdflut/exr.h"
#include "brdflut/table.h"

namespace brdflut {

enum class Format { exr, cpp, png16, dds, ktx2 };

std::string_view to_string(Format f);                 // "exr", "cpp", ...
Format format_from_string(std::string_view s);        // throws brdflut::Error listing the allowed names
std::string file_extension(Format f);                 // "exr", "h", "png", "dds", "ktx2" (no dot)

// How the values are stored in format f with the given pixel type: png16
// always stores unorm16; the other formats store the pixel type.
Storage storage_for(Format f, PixelType pixel);

// The C++ identifier used as the namespace of a table in a cpp header:
// the id with characters outside [A-Za-z0-9_] replaced by '_', runs of '_'
// collapsed, and a prefix or suffix added where it would otherwise start
// with a digit or '_' or be a keyword.
std::string cpp_identifier(std::string_view table_id);

// Writes the table in format f atomically (nothing under `path` changes on
// failure). Refuses non-finite values (RuntimeError) and, for png16, values
// outside [0, 1] (Error), naming the table, texel, channel and value, before
// any file is created.
void write_table(const std::string& path, const Table& table, PixelType pixel, Format f);

// Reads a table file that brdflut writes in any binary format (exr, png16,
// dds, ktx2), recognised by its first bytes, into the same structure as
// read_exr(). Channels are named R, G, B, A as stored (a dds/ktx2 3-channel
// table has its A = 1 padding, a png16 2-channel table its B = 0); png16
// samples are read as q / 65535 with `pixel` float32 (the metadata's `pixel`
// says unorm16); dds files carry no metadata. Only the layouts brdflut writes
// are accepted. Throws brdflut::RuntimeError naming the file on any failure.
ExrImage read_table_image(const std::string& path);

}  // namespace brdflut
