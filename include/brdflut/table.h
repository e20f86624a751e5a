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

// How a value is stored in a file: as a float pixel type, or (16-bit PNG) as
// a 16-bit unsigned normalised integer round(v * 65535) read back as q / 65535.
enum class Storage { half, float32, unorm16 };
Storage storage_of(PixelType p);
std::string_view to_string(Storage s);  // "half", "float", "unorm16"

// Rounds a value to the storage type and back.
double round_to_storage(double v, PixelType p);
double round_to_storage(double v, Storage s);

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
