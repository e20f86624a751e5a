// The subcommands of the brdflut tool. Each returns the exit code; library
// errors propagate as exceptions to main().
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdflut/formats.h"
#include "cli/options.h"

namespace brdflut::cli {

int run_list(bool presets_only, bool json);

// brdflut metals: F0, F82 tint, edge tint and average of the metal presets
// from their measured spectra in an RGB space, and each reduction's error.
struct MetalsArgs {
    std::string colour_space = "srgb";
    std::string metal;  // empty: every metal
    bool json = false;
};
int run_metals(const MetalsArgs& a);

// The `--help` text of each command, in the order `brdflut --help` lists
// them (name, text).
using CommandHelp = std::vector<std::pair<std::string, std::string>>;

// The reference pages of docs/reference (file name -> Markdown), rendered
// from the catalogue and the command line's own help, and the catalogue as
// JSON (`list --json`).
std::map<std::string, std::string> reference_pages(const CommandHelp& help);
nlohmann::json catalogue_json();
// Writes the pages to `output`, or with check compares them with the files
// there (exit 1 naming the stale pages).
int run_docs(const std::string& output, bool check, const CommandHelp& help);

struct GenerateArgs {
    std::vector<std::string> ids;
    bool all = false;
    std::string output = ".";
    std::string pixel = "float";
    std::string format = "exr";  // exr, cpp, png16, png, dds, ktx2 (brdflut/formats.h)
    std::string encoding;        // --encoding: a storage type (brdflut/table.h); empty: from --pixel and --format
    std::vector<std::string> shaders;  // --shader glsl|hlsl (repeatable): lookup functions beside each table
    bool pixel_given = false;  // --pixel on the command line (else a preset's own)
    std::string preset;        // --preset NAME
    int threads = 0;
    bool quiet = false;
    TableArgs table;
};
int run_generate(const GenerateArgs& a);

struct VerifyArgs {
    std::vector<std::string> ids;
    bool json = false;
    long long samples = 100000;
};
int run_verify(const VerifyArgs& a);

// How a file that is not brdflut's own is read: --array NAME (an array in a
// source file), --shape WxH[xD][:C], --decode linear|srgb|rgbd (formats.h).
struct ReadArgs {
    std::string array, shape, decode;
};
ReadOptions read_options(const ReadArgs& a);  // throws brdflut::Error on a bad --shape or --decode

// How a file is described: its metadata, or --as with the table options.
struct DescribeArgs {
    std::string file;
    ReadArgs read;
    std::string as;
    TableArgs table;  // axes, layout and model options of a foreign file
};

struct CompareArgs {
    DescribeArgs describe;
    bool json = false;
    int worst = 10;
    int threads = 0;
    std::string plot;
    std::string tolerance;  // --tolerance X or X%; empty: the file's own default
    std::string transform;  // --transform none|srgb
    bool relative = false;  // --relative: the largest relative error per channel too
};
int run_compare(const CompareArgs& a);

struct IdentifyArgs {
    std::string file;
    ReadArgs read;  // as compare reads the file
    int top = 3;
    bool json = false;
    int threads = 0;
};
int run_identify(const IdentifyArgs& a);

// member: a JSON pointer into the metadata; when given, only that member is
// printed (as JSON).
int run_inspect(const std::string& file, const ReadArgs& read, bool json, const std::string& member = {});

struct SampleArgs {
    DescribeArgs describe;
    std::string at;  // name=value,name=value
};
int run_sample(const SampleArgs& a);

struct FurnaceArgs {
    std::vector<std::string> models;
    bool json = false;
    int size = 64;
    int threads = 0;
    double tolerance = -1;
    std::string plot;  // folder for PNG heatmaps
};
int run_furnace(const FurnaceArgs& a);

bool stderr_is_terminal();

}  // namespace brdflut::cli
