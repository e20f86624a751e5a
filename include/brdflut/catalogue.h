// The catalogue: every table brdflut knows, with its axes, channels,
// defaults and the evaluator that fills a texel.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdflut/axis.h"
#include "brdflut/table.h"

namespace brdflut {

// A model option a table accepts (set with a command-line flag of the same name).
struct ModelOption {
    std::string name;                  // e.g. "visibility"
    std::string help;
    std::string default_value;
    std::vector<std::string> allowed;  // empty: free form, checked by the table
};

// The default of an axis and the values the model accepts on it.
struct AxisSpec {
    Axis axis;            // default range, count, placement and warp
    double domain_min;    // smallest value the model accepts
    double domain_max;    // largest value the model accepts
    std::string meaning;  // e.g. "cos(theta_o), cosine of the view angle"
    // The names of the square root and of the square of the parameter, where
    // engines index by either (GGX alpha = roughness^2): `identify` names a
    // grid uniform in the other one.
    std::string root_name = {};
    std::string square_name = {};
};

// Values and estimated absolute errors of one texel's channels, and the
// work spent on them: evaluations of the integrands (0 for closed forms, for
// values taken from a result shared with an earlier table, and for tables
// that do not count them).
struct TexelValue {
    std::array<double, 4> value{};
    std::array<double, 4> error{};
    long long evaluations = 0;
};

class TexelEvaluator;

// An independent check of a table: its values against a closed form, a limit
// or a second route to the same integral (never Monte Carlo, which verify
// runs for every table that has it, and never the table against itself).
// run() evaluates the table's own evaluator (default settings) and returns
// the largest absolute error and where it occurred; the check passes when
// that error is finite and at most `tolerance`.
struct ClosedFormCheck {
    std::string name;
    double tolerance;
    std::function<std::pair<double, std::string>(const TexelEvaluator&)> run;
};

class TexelEvaluator {
public:
    virtual ~TexelEvaluator() = default;
    // coords: one value per axis (x, y[, z]); texel: the linear index, which
    // seeds Monte Carlo so results do not depend on scheduling. Never throws.
    virtual TexelValue evaluate(const double* coords, std::uint64_t texel) const = 0;
};

struct PreparedTable {
    std::unique_ptr<TexelEvaluator> evaluator;
    nlohmann::json model;   // every parameter that changes the values
    nlohmann::json method;  // the rule and its settings
    // Called once after every texel is filled (optional): adds table-wide
    // figures the evaluator gathered (for example the largest fit error) to
    // the table's method metadata.
    std::function<void(Table&)> finish;
};

struct TableDefinition {
    std::string id;
    std::string description;  // one line
    // The family that declares the table (its file src/tables/FAMILY_tables.cpp);
    // set by the catalogue.
    std::string family;
    std::vector<AxisSpec> axes;
    std::vector<std::string> channels;  // meaning of R, G, B, A in order
    std::vector<ModelOption> options;
    bool supports_monte_carlo = false;
    // The engine preset the table belongs to (`generate --preset NAME`); empty
    // for the default set that `generate --all` writes.
    std::string preset;
    // For a preset table: the engine source it reproduces (repository, file,
    // commit) and, per stored channel, its expression over core tables (e.g.
    // "1 - ggx_albedo.0"); `list`, `brdflut docs` and the metadata show them.
    std::string engine_source;
    std::vector<std::string> channel_recipes;
    // For a preset table the engine stores in an integer encoding whose range
    // holds its values (Unreal's G16R16 UNORM, glTF's 8-bit PNG, Babylon's
    // RGBD): that storage. `generate` writes it when neither --pixel nor
    // --encoding is given and the format holds it (dds, ktx2, png), and the
    // preset's pixel type otherwise.
    std::optional<Storage> engine_storage;
    // Whether `identify` searches this table. Tables that cost milliseconds
    // a texel (the LTC fits; the glass averages, a 3-D integral each) are
    // left out: tabulating them for the coarse search would cost more than
    // the rest of the catalogue together.
    // `compare --as` still checks a file against them.
    bool searched_by_identify = true;
    // Whether each new value of a parameter costs a solve of its own
    // (seconds: the sheen layer's transport, a roughness at a time): tests
    // that evaluate the exact model at many scattered points (the GPU shader
    // check) evaluate a few of them only.
    bool solve_per_parameter = false;
    // How the generated shader lookup function (brdflut/shader.h) returns
    // the texel: empty = one struct member per channel; otherwise the name of
    // a result form of the shader writer (src/io/shader_writer.cpp,
    // result_forms()), e.g. "ltc_inverse", an LTC table's inverse matrix.
    std::string shader_result;
    // For shader_result "ltc_inverse": where the stored channels go in the
    // matrix, by rows (m[row][col] of the matrix acting on column vectors,
    // as ltc.h writes matrices): each element "R", "G", "B" or "A" (that
    // channel of the filtered texel) or a number (a constant element).
    std::array<std::string, 9> shader_matrix;
    // Validates settings (throws brdflut::Error) and builds the evaluator.
    std::function<PreparedTable(const TableSettings&)> prepare;
    // The table's independent checks, which `brdflut verify` runs; every
    // table of the catalogue has at least one (tests/test_checks.cpp).
    std::vector<ClosedFormCheck> checks;
};

const std::vector<TableDefinition>& catalogue();

// A family of tables, as its family file describes itself for the reference
// docs (brdflut docs).
struct TableFamily {
    std::string name;     // e.g. "beckmann": TableDefinition::family of its tables
    std::string title;    // e.g. "Beckmann microfacet"
    std::string summary;  // one or more paragraphs of Markdown: the model, its sources, what the tables hold
};
// Every family, in catalogue order.
const std::vector<TableFamily>& table_families();
// Throws brdflut::Error listing the known ids when id is unknown.
const TableDefinition& find_table(const std::string& id);

// An engine preset: the tables an engine uses, each in the engine's own layout.
struct Preset {
    std::string name;         // e.g. "filament"
    std::string description;  // one line
    PixelType pixel;          // the pixel type written unless --pixel is given
};
const std::vector<Preset>& presets();
// Throws brdflut::Error listing the known presets when name is unknown.
const Preset& find_preset(const std::string& name);
// The catalogue's tables of one preset, in catalogue order.
std::vector<const TableDefinition*> preset_tables(const std::string& name);

// Forgets the intermediate results that tables generated in one process
// share (the GGX split sums that ggx_albedo takes from ggx_dfg, the LTC fits
// and error reports that a matrix table and its _error table take from each
// other). No value depends on them; a benchmark calls this so that each run
// does all its work.
void clear_shared_results();

// The defaults of a table: its axes and the default of every option.
TableSettings default_settings(const TableDefinition& def);

// For each axis of the settings (storage order), the index of the same axis
// in the definition; throws brdflut::Error unless the settings' axes are an
// order of the definition's axes.
std::vector<int> definition_axis_order(const TableDefinition& def, const TableSettings& s);

// Checks axis names, counts, ranges against the domain, and option values;
// throws brdflut::Error naming the option, the value and what is allowed.
void validate_settings(const TableDefinition& def, const TableSettings& s);

}  // namespace brdflut
