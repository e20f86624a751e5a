// OpenEXR input and output of tables. Channels are named R, G, B, A (as many
// as the table has); the string attribute `brdflut` holds the metadata JSON.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdflut/table.h"

namespace brdflut {

inline constexpr const char* kMetadataAttribute = "brdflut";

// Writes atomically: a temporary file in the destination folder is renamed
// into place only when complete. Refuses NaN or infinite values.
// Throws brdflut::RuntimeError on failure.
void write_exr(const std::string& path, const Table& table, PixelType pixel);

struct ExrImage {
    int width = 0, height = 0;
    std::vector<std::string> channel_names;  // in file order (R, G, B, A first)
    std::vector<double> pixels;              // row-major, channels interleaved
    // Slices of a 3-D texture (dds, ktx2) or array (npy, source): height
    // counts the rows of all of them, row = z * (height / depth) + y.
    int depth = 1;
    PixelType pixel = PixelType::float32;
    // How the file stores the values: half or float32 (pixel), or an integer
    // encoding (PNG, npy u1/u2, dds and ktx2 UNORM formats), which pixels
    // holds decoded.
    Storage storage = Storage::float32;
    // The spacing of the encoding around each value (layout of pixels) where
    // it varies from texel to texel (rgbd); empty otherwise.
    std::vector<double> steps;
    bool is_unorm8() const { return storage == Storage::unorm8; }
    bool is_unorm16() const { return storage == Storage::unorm16; }
    // The name of the stored type: the integer encoding's, or the pixel type's.
    std::string_view stored_as() const { return is_integer(storage) ? to_string(storage) : to_string(pixel); }
    // Numbers printed in a source file in fixed point, all with the same
    // count of decimals: the unit of the last digit (1e-6 for "0.998773f");
    // 0 otherwise.
    double printed_step = 0.0;
    bool has_metadata = false;
    nlohmann::json metadata;
};

// Throws brdflut::RuntimeError naming the file on any failure: a missing,
// truncated or corrupt file, another format, or metadata that is not JSON.
ExrImage read_exr(const std::string& path);
// The same for a file's bytes in memory (name is used in messages).
ExrImage read_exr_memory(const char* data, std::size_t size, const std::string& name);

}  // namespace brdflut
