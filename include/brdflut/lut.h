// Reading back a LUT: which table it is, how its texels map to parameters,
// and how it compares with exact values. Used by `brdflut compare`,
// `inspect` and `sample`.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "brdflut/catalogue.h"
#include "brdflut/exr.h"
#include "brdflut/math.h"

namespace brdflut {

// How a file's texels and channels relate to a catalogue table: the table
// and the settings whose generated table has the file's layout (axes in
// storage order with their placement, warp, flip and clamps, and the
// channel map).
// What the file's values are of the table's: the values themselves, or
// (srgb) the exact sRGB EOTF of each, as a linear table reads when it is
// decoded or sampled as sRGB (channels R, G, B; A stays linear).
enum class ValueTransform { none, srgb };
std::string_view to_string(ValueTransform t);             // "none", "srgb"
ValueTransform value_transform_from_string(std::string_view s);  // throws brdflut::Error


// Applies t to a table's values in place; the error estimates are scaled by
// the slope of the EOTF.
void apply_value_transform(Table& t, ValueTransform transform);

struct LutDescription {
    const TableDefinition* def = nullptr;
    TableSettings settings;
    ValueTransform values = ValueTransform::none;
};

// Understands a brdflut file from its metadata. Throws RuntimeError when the
// file has no brdflut metadata or it does not describe a known table.
LutDescription describe_from_metadata(const ExrImage& img, const std::string& path);

// Throws RuntimeError when the image's size or channels do not fit.
void check_fits(const ExrImage& img, const LutDescription& d, const std::string& path);

// Whether img is a flat array: one row of one slice, as a source array or
// .npy of one dimension reads.
bool is_flat(const ExrImage& img);
// Gives a flat array the shape of `axes` (storage order): width the first
// axis's count, rows the product of the others, with 1 channel or, when its
// length is the texel count times `table_channels`, that many interleaved.
// Throws RuntimeError naming the file, its length and what the layout needs.
void reshape_flat(ExrImage& img, const std::vector<Axis>& axes, int table_channels, const std::string& path);

struct ChannelError {
    std::string channel;  // file channel name
    double max_abs = 0.0;
    double rms = 0.0;
    // Largest |stored - exact| / |exact| over the values the file's pixel
    // type resolves to 0.1% (one storage step at most 1e-3 |exact|: not the
    // subnormal or coarsely quantized ones), and the axis values (storage
    // order) where it occurs; 0 and empty when there is none.
    double max_rel = 0.0;
    std::vector<double> max_rel_params;
};

struct TexelError {
    std::size_t texel;            // linear index in storage order
    std::vector<double> params;   // axis values (storage order)
    std::string channel;
    double stored, exact, error;  // error = stored - exact
};

// What a stored value may differ from the exact one by: abs + rel |exact|
// + steps storage steps at the exact value (one step: the spacing of the
// stored type there, e.g. 2^-23 |v| for float, 1/65535 for unorm16), plus
// the estimated error of the exact value itself.
struct Tolerance {
    double abs = 0.0;
    double rel = 0.0;
    double steps = 0.0;
    std::string source;  // how it was chosen, for the report
};

// Parses --tolerance: "X" (absolute) or "X%" (relative to the exact value);
// throws Error naming the value and the allowed forms.
Tolerance parse_tolerance(const std::string& s);
// The default: one step of the encoding for a file of integers (unorm8,
// unorm16, rgb10a2, rgbd: brdflut's or foreign); a brdflut file's claimed
// error_bound for float storage; for a foreign file one storage step of its
// pixel type.
Tolerance default_tolerance(const ExrImage& img);
// The spacing of the stored type of img at value v; with the index of the
// value in img.pixels, the spacing there for encodings whose step varies
// (rgbd).
double storage_step(const ExrImage& img, double v);
double storage_step(const ExrImage& img, std::size_t index, double v);

struct CompareReport {
    std::vector<ChannelError> channels;
    std::vector<TexelError> worst;        // largest |error| first
    std::vector<double> max_error_map;    // per texel (storage order), largest |error| over channels
    double exact_error_bound = 0.0;       // estimated error of the exact values themselves
    Tolerance tolerance;
    std::size_t failed_values = 0;        // stored values outside the tolerance
    std::vector<TexelError> first_failures;  // the worst values outside it (up to worst_count)
    bool pass() const { return failed_values == 0; }
};

CompareReport compare_lut(const ExrImage& img, const LutDescription& d, int threads, std::size_t worst_count,
                          const Tolerance& tolerance);

// The file's values against an exact table of the same layout (storage
// order, channel c of the file against channel c of the table).
CompareReport compare_values(const ExrImage& img, const Table& exact, std::size_t worst_count,
                             const Tolerance& tolerance);

struct ChannelStats {
    std::string channel;
    double min = 0.0, max = 0.0, mean = 0.0;
    long long non_finite = 0;
};
std::vector<ChannelStats> channel_stats(const ExrImage& img);

// The value of one file channel at a parameter point (one value per axis, in
// storage order), interpolated as a GPU does with linear filtering and
// clamp-to-edge addressing: linear, bilinear or trilinear. The texture
// coordinate of each axis is (Axis::position_of_value(p) + 0.5) / count.
double sample_lut(const ExrImage& img, const LutDescription& d, const std::vector<double>& params,
                  int file_channel);

}  // namespace brdflut
