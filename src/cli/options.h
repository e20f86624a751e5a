// Command-line options shared by the subcommands that describe a table:
// grid size, per-axis overrides and model options.
#pragma once

#include <CLI/CLI.hpp>

#include <map>
#include <set>
#include <string>
#include <vector>

#include "brdflut/catalogue.h"

namespace brdflut::cli {

inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;

struct TableArgs {
    std::string size;  // "N" or "NxM"
    std::vector<std::string> ranges, counts, placements, warps;
    // The layout: storage order of the axes, reversed axes, clamps of the
    // parameter, and what each stored channel holds.
    std::string order;                 // --order alpha,cos_theta
    std::vector<std::string> flips;    // --flip AXIS
    std::vector<std::string> clamps;   // --clamp AXIS=LO:HI
    std::vector<std::string> shifts;   // --shift AXIS=TEXELS
    std::string channels;              // --channels R=G,G=R+G
    bool layout_given() const {
        return !size.empty() || !ranges.empty() || !counts.empty() || !placements.empty() || !warps.empty() ||
               !order.empty() || !flips.empty() || !clamps.empty() || !shifts.empty() || !channels.empty() || !params.empty();
    }
    std::string method = "quadrature";
    std::string quality = "default";  // draft | default | reference
    long long samples = 4096;
    unsigned long long seed = 1;
    std::map<std::string, std::string> option_values;  // every model option's flag
    std::map<std::string, std::string> params;         // those given on the command line
};

// Adds --size, --range, --count, --placement, --warp, --order, --flip,
// --clamp, --channels and a --<name> flag for
// every model option of the catalogue. With methods, also --method,
// --quality, --samples and --seed.
void add_table_options(CLI::App& app, TableArgs& a, bool methods);

// After parsing: collects the model options given on the command line.
void collect_params(const CLI::App& app, TableArgs& a);

// Settings of one table from its defaults and the command line; `used`
// collects which options applied, for check_all_used().
TableSettings settings_for(const TableDefinition& def, const TableArgs& a, std::set<std::string>& used);

// Throws Error for an option that no requested table accepts.
void check_all_used(const TableArgs& a, const std::set<std::string>& used);

// "N", "NxM" or "NxMxK".
std::vector<int> parse_size(const std::string& s);
double parse_double(const std::string& option, const std::string& s);
// A number as printed in reports: "%.2e".
std::string sci(double v);
// As parse_double, also accepting "inf" and "-inf" (range and clamp limits).
double parse_limit(const std::string& option, const std::string& s);
std::pair<std::string, std::string> split_assignment(const std::string& option, const std::string& s);

}  // namespace brdflut::cli
