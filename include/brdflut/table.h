// A generated table: its axes, channels and values, and the settings that
// produced it.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdflut/axis.h"

namespace brdflut {

enum class Method { quadrature, monte_carlo };
std::string_view to_string(Method m);
Method method_from_string(std::string_view s);  // throws brdflut::Error

// How hard the quadrature works. Each table family maps a quality to its own
// absolute tolerance (recorded in the metadata's `method`): `draft` about 1e-5
// (previews), `standard` (spelled "default") 1e-8 to 1e-11, so that every
// stored float is within 1e-7 of the exact integral, `reference` 1e-12 or
// tighter (checking the others). Closed-form tables ignore it.
enum class Quality { draft, standard, reference };
std::string_view to_string(Quality q);
Quality quality_from_string(std::string_view s);  // throws brdflut::Error

// What a user may change about a table. Start from default_settings(def).
struct TableSettings {
    // The axes in storage order (x, y[, z]): any order of the table's axes,
    // matched by name (a transposed table lists them the other way round).
    std::vector<Axis> axes;
    std::map<std::string, std::string> params;  // model options, e.g. visibility
    Method method = Method::quadrature;
    Quality quality = Quality::standard;        // quadrature only
    long long samples = 4096;                   // per texel, Monte Carlo only
    std::uint64_t seed = 1;                     // Monte Carlo only
    // Stored channel c holds the sum of the table channels channel_map[c]
    // (e.g. {{0, 1}} stores A + B alone); empty: channel c holds channel c.
    std::vector<std::vector<int>> channel_map;
};

// "R+G,B" style names of a channel map (table channels as letters R, G, B, A).
std::string channel_map_to_string(const std::vector<std::vector<int>>& map);
// Parses "R=G,G=R+G" (file channel = sum of table channels, both as letters);
// throws Error naming the bad item.
std::vector<std::vector<int>> parse_channel_map(const std::string& spec, int table_channels);

struct Table {
    std::string id;
    std::vector<Axis> axes;             // in storage order, as TableSettings::axes
    std::vector<std::string> channels;  // meaning of R, G, B, A in order (1 to 4), as stored
    std::vector<std::vector<int>> channel_map;  // as TableSettings::channel_map
    nlohmann::json model;               // every parameter that changes the values
    nlohmann::json method;              // integration rule and its settings
    std::map<std::string, std::string> options;  // the model options it was made with
    // Texel values in storage order, x fastest, then y, then z; channels
    // interleaved.
    std::vector<double> values;
    // Estimated absolute integration error of each value (same layout).
    std::vector<double> errors;
    // Integrand evaluations spent on the values (the sum of the texels'
    // TexelValue::evaluations; not written to files).
    long long evaluations = 0;

    int width() const { return axes.empty() ? 0 : axes[0].count; }
    // Rows of the image: the second axis, with z slices stacked vertically.
    int height() const;
    int channel_count() const { return static_cast<int>(channels.size()); }
    std::size_t texel_count() const;
    double at(std::size_t texel, int channel) const {
        return values[texel * channels.size() + static_cast<std::size_t>(channel)];
    }
};

enum class PixelType { half, float32 };
std::string_view to_string(PixelType p);
PixelType pixel_type_from_string(std::string_view s);  // throws brdflut::Error

// How a value is stored in a file: as a float pixel type, or as integers.
// The integer encodings round to nearest (ties away from zero), as D3D and
// Vulkan specify for the conversion of a float to UNORM, computed in double:
//   unorm8, unorm16  q = round(v * (2^bits - 1)), read as q / (2^bits - 1);
//                    values in [0, 1];
//   rgb10a2          R10G10B10A2 UNORM: R, G, B as 10-bit q = round(v * 1023)
//                    (bits 0-9, 10-19, 20-29 of a 32-bit word), A = 3 (1.0);
//                    tables of 1 to 3 channels, values in [0, 1];
//   rgbd             Babylon.js's RGBD in RGBA8 (its toRGBD/fromRGBD): with m
//                    the largest of the texel's values (at least 1e-7),
//                    a = min(floor(max(255 / m, 1)), 255), q = round(255 *
//                    (v * a / 255)^(1 / 2.2)) in R, G, B and a in A; read as
//                    v = (q / 255)^2.2 / (a / 255). Tables of 1 to 3
//                    channels, values in [0, 255].
// Values outside an encoding's range are refused, never clamped; a value
// within 1e-12 (relative, at the top) of an end, the rounding of a computed
// value such as 1 - E at E = 1, is stored as that end.
enum class Storage { half, float32, unorm16, unorm8, rgb10a2, rgbd };
Storage storage_of(PixelType p);
std::string_view to_string(Storage s);  // "half", "float", "unorm16", "unorm8", "rgb10a2", "rgbd"
// The names of to_string; throws brdflut::Error naming the text and the allowed names.
Storage storage_from_string(std::string_view s);
std::string storage_names();  // "half, float, unorm16, unorm8, rgb10a2, rgbd"
bool is_integer(Storage s);
int max_channels(Storage s);  // 4, or 3 for rgb10a2 and rgbd
// The values an integer encoding holds ([0, 1], or [0, 255] for rgbd).
double storage_min(Storage s);
double storage_max(Storage s);
// How a stored integer reads back as a value (recorded in the metadata as
// `decode`); empty for the float types.
std::string_view decode_rule(Storage s);

// An integer encoding of one texel: `n` values (1 to max_channels(s)) to the
// four stored integers q (unused colour channels 0, A = 1.0 for unorm and
// rgb10a2, the divisor for rgbd); values must be in range.
void encode_texel(Storage s, const double* v, int n, std::uint32_t q[4]);
// The values of the stored integers: 4 for unorm and rgb10a2 (A included),
// 3 for rgbd (infinite when its A is 0).
int decoded_channels(Storage s);
void decode_texel(Storage s, const std::uint32_t q[4], double* v);
// The spacing of the encoding's values around stored channel c of a texel:
// 1 / (2^bits - 1) for unorm; for rgbd the gap to the next code above (the
// larger of the two, the decode being convex), so that a value rounded to
// nearest lies within half a step of its code.
double encoding_step(Storage s, const std::uint32_t q[4], int c);

// Rounds a value to the storage type and back (an rgbd value as alone in its
// texel); round_texel rounds a texel of n values together.
double round_to_storage(double v, PixelType p);
double round_to_storage(double v, Storage s);
void round_texel(Storage s, const double* v, int n, double* out);

// Largest estimated absolute error of any stored value: integration error
// plus the rounding of each value to the storage type.
double error_bound(const Table& t, PixelType p);
double error_bound(const Table& t, Storage s);

// The `brdflut` metadata of a table stored with pixel type p (or storage s):
// its `pixel` names the storage and its `error_bound` includes the rounding.
nlohmann::json metadata_json(const Table& t, PixelType p);
nlohmann::json metadata_json(const Table& t, Storage s);

// A number in metadata JSON: infinite values (an open IOR axis) as "inf".
nlohmann::json number_to_json(double v);
double number_from_json(const nlohmann::json& j);  // throws RuntimeError

// Rebuilds axes from metadata; throws brdflut::RuntimeError on malformed input.
std::vector<Axis> axes_from_json(const nlohmann::json& axes);

}  // namespace brdflut
