// Reading back a LUT: which table it is, how its texels map to parameters,
// and how it compares with exact values. Used by `brdflut compare`,
// `inspect` and `sample`.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "brdflut/catalogue.h"
#include "brdflut/exr.h"

namespace brdflut {

// How a file's texels and channels relate to a catalogue table.
struct LutDescription {
    const TableDefinition* def = nullptr;
    TableSettings settings;  // the axes of the file's grid and the model options
    // For each file channel, the table channels whose sum it holds
    // (identity by default: file channel c holds table channel c).
    std::vector<std::vector<int>> channel_map;
    // flip[a]: index i of axis a is stored at position count - 1 - i.
    std::vector<bool> flip;
};

// Understands a brdflut file from its metadata. Throws RuntimeError when the
// file has no brdflut metadata or it does not describe a known table.
LutDescription describe_from_metadata(const ExrImage& img, const std::string& path);

// Parses "R=G,G=R+G" (file channel = sum of table channels, both as letters
// R, G, B, A) into a channel map; throws Error naming the bad item.
std::vector<std::vector<int>> parse_channel_map(const std::string& spec, int table_channels);

// Throws RuntimeError when the image's size or channels do not fit.
void check_fits(const ExrImage& img, const LutDescription& d, const std::string& path);

struct ChannelError {
    std::string channel;  // file channel name
    double max_abs = 0.0;
    double rms = 0.0;
};

struct TexelError {
    std::size_t texel;            // linear index in table order
    std::vector<double> params;   // axis values
    std::string channel;
    double stored, exact, error;  // error = stored - exact
};

struct CompareReport {
    std::vector<ChannelError> channels;
    std::vector<TexelError> worst;        // largest |error| first
    std::vector<double> max_error_map;    // per texel (table order), largest |error| over channels
    double exact_error_bound = 0.0;       // estimated error of the exact values themselves
};

CompareReport compare_lut(const ExrImage& img, const LutDescription& d, int threads, std::size_t worst_count);

struct ChannelStats {
    std::string channel;
    double min = 0.0, max = 0.0, mean = 0.0;
    long long non_finite = 0;
};
std::vector<ChannelStats> channel_stats(const ExrImage& img);

// The value of one file channel at a parameter point, interpolated as a GPU
// does with bilinear filtering and clamp-to-edge addressing (1-D: linear).
double sample_lut(const ExrImage& img, const LutDescription& d, const std::vector<double>& params,
                  int file_channel);

}  // namespace brdflut
