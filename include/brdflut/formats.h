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
//   png    the same for the encodings unorm16 (= png16), unorm8 (8-bit
//          samples) and rgbd (8-bit RGBA, brdflut/table.h says how).
//   dds    DirectDraw Surface with the DX10 header extension, a 2-D texture
//          (height 1 for one-axis tables), one mip level.
//   ktx2   KTX 2.0, a 2-D texture (pixelHeight 1 for one-axis tables), one
//          level, no supercompression; metadata in the key `brdflut`.
//
// dds and ktx2 store 1, 2 or 4 channels as R16_FLOAT / R16G16_FLOAT /
// R16G16B16A16_FLOAT (half) or R32_FLOAT / R32G32_FLOAT / R32G32B32A32_FLOAT
// (float), the same in R8/R16 UNORM (unorm8, unorm16), R10G10B10A2_UNORM
// (rgb10a2, Vulkan A2B10G10R10_UNORM_PACK32) and R8G8B8A8_UNORM (rgbd)
// (io/gpu_formats.cpp lists them); a 3-channel table is stored as 4 channels with A = 1, because no
// 3-channel 16-bit float texture format exists in DXGI and the 3-channel
// Vulkan formats are rarely sampleable. Row 0 of every image is the first
// row of the table (index 0 of the second axis), data little-endian.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "brdflut/exr.h"
#include "brdflut/table.h"

namespace brdflut {

enum class Format { exr, cpp, png16, png, dds, ktx2 };

std::string_view to_string(Format f);                 // "exr", "cpp", ...
Format format_from_string(std::string_view s);        // throws brdflut::Error listing the allowed names
std::string file_extension(Format f);                 // "exr", "h", "png", "dds", "ktx2" (no dot)

// How the values are stored in format f with the given pixel type: the
// pixel type where f holds it, else f's own (png16 and png: unorm16).
Storage storage_for(Format f, PixelType pixel);
// Whether format f can hold storage s (exr, cpp: half, float; png16:
// unorm16; png: unorm16, unorm8, rgbd; dds, ktx2: all); the list for f.
bool format_holds(Format f, Storage s);
// The formats that hold storage s, in the order of the format list.
std::vector<Format> formats_holding(Storage s);
std::string format_storages(Format f);
// Throws brdflut::Error naming the encoding, the format and what it allows.
void check_format_holds(Format f, Storage s);

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
// The same with a storage type (an integer encoding, say): Error when f
// cannot hold it, or for values outside its range or too many channels.
void write_table(const std::string& path, const Table& table, Storage storage, Format f);

// How a file that is not brdflut's own is to be read (the command-line
// options --array, --shape and --decode).
enum class Decode {
    none,    // brdflut files; a PNG without brdflut metadata is refused
    linear,  // integer samples q as q / (2^bits - 1)
    srgb,    // the same, then the exact sRGB EOTF (channels 1 to 3; a 4th is alpha, linear)
    rgbd,    // 8-bit RGBA as Babylon.js's RGBD: (q / 255)^2.2 / (a / 255), 3 channels
};
std::string_view to_string(Decode d);           // "none", "linear", "srgb", "rgbd"
Decode decode_from_string(std::string_view s);  // "linear", "srgb" or "rgbd"; throws brdflut::Error otherwise

// How the numbers of an array or a .npy file form an image: width x height
// texels (x fastest), `depth` slices stacked as rows (row = z * height + y)
// and `channels` interleaved values per texel. width 0: inferred.
struct ArrayShape {
    long long width = 0, height = 1, depth = 1, channels = 1;
    // The channels stored as planes, one whole image after another (":Cp",
    // Cycles' table_sheen_ltc), instead of interleaved.
    bool planar = false;
    bool given() const { return width > 0; }
};
// "W", "WxH" or "WxHxD", optionally followed by ":C" (1 to 4 channels,
// interleaved) or ":Cp" (stored as planes), e.g. "32x32", "16x16x16",
// "64x64:2", "32x32:3p". Throws brdflut::Error naming the text.
ArrayShape parse_array_shape(std::string_view s);
std::string to_string(const ArrayShape& s);  // "WxH[xD]:C"

struct ReadOptions {
    // The name of an array in a source file (C, C++, GLSL, HLSL,
    // JavaScript); required for source files, refused for binary ones.
    std::string array;
    // The image the numbers form (source arrays and .npy); not given: from
    // the declared dimensions, the nesting of the initializer or the .npy
    // shape.
    ArrayShape shape;
    Decode decode = Decode::none;
};

// Reads a table file, recognised by its first bytes, into the same structure
// as read_exr():
//   exr, dds, ktx2, png16 and png as brdflut writes them, in every
//       encoding (an rgbd ktx2 or png by its metadata; an rgbd dds, which
//       has no metadata, with options.decode rgbd) (dds and ktx2 also as
//       3-D textures: DX10 TEXTURE3D with DDSD_DEPTH, KTX2 pixelDepth > 0,
//       read with depth = the slice count, slices stacked as rows);
//   any PNG libpng reads (8 or 16 bits, grey, grey + alpha, RGB, RGBA,
//       palette expanded to RGB or RGBA): samples q read as q / 255 or
//       q / 65535 (unorm8 / unorm16). One without brdflut metadata needs
//       options.decode (linear, srgb, or rgbd for 8-bit RGBA);
//   NumPy .npy, versions 1 to 3, dtypes f2, f4, f8, u1, u2 (u1 and u2 read
//       as q / 255 and q / 65535), either byte order, C order, shape (W),
//       (H, W), (H, W, C) with C <= 4, (D, H, W) or (D, H, W, C);
//   a source file with options.array: the initializer of that array
//       (source_array.cpp describes the syntax and the shape rules).
// Channels are named R, G, B, A as stored (a dds/ktx2 3-channel table has
// its A = 1 padding, a png16 2-channel table its B = 0). Only regular files
// are read (not FIFOs, devices or directories), binary files up to
// kMaxBinaryFileBytes, source files up to kMaxTextFileBytes (io/image_limits.h),
// and the format is decided from the first bytes before the rest is read.
// Throws brdflut::RuntimeError naming the file on any failure.
ExrImage read_table_image(const std::string& path, const ReadOptions& options = {});
// The same for a file's bytes in memory (name is used in messages).
ExrImage read_table_image_memory(const char* data, std::size_t size, const std::string& name,
                                 const ReadOptions& options = {});

}  // namespace brdflut
