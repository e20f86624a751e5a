// Tables declared as recipes over core catalogue tables: each stored channel
// is a linear combination of channels of core tables plus an offset, or the
// ratio of two such sums, in a layout of its own (1 - x is the sum -x + 1,
// x / (1 + x) the ratio of x to x + 1, an affine range remap a sum with its
// coefficients and offset). The engine presets (preset_tables.cpp) are such
// declarations, one data entry a table.
//
// At each texel the recipe's coordinates go to each core table's axes by
// name: an axis of the same name feeds it unchanged, an axis whose
// AxisSpec::square_name is the core axis's name feeds it the square
// (alpha_from_perceptual of a perceptual roughness), one whose root_name is
// that name feeds it the square root. The core table's evaluator (prepared
// with the recipe's quality, method, samples, seed and the entry's options)
// gives the values, so every shared result and Monte Carlo seed (the texel
// index) is the core table's own.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdflut/catalogue.h"
#include "tables/registry.h"

namespace brdflut::tables {

// coef * channel `channel` of the core table `table`.
struct RecipeTerm {
    std::string table;
    int channel = 0;
    double coef = 1.0;
};

// One stored channel: its meaning (TableDefinition::channels) and its value
//   N / D,  N = sum of terms + offset,  D = sum of den_terms + den_offset
// (D = 1, the default, leaves N). Without terms N is the constant offset.
// Errors of a sum add as |coef| times each term's error; the ratio's error
// is (err N + |N / D| err D) / |D|, its first-order bound. Evaluations add.
struct ChannelRecipe {
    std::string meaning;
    std::vector<RecipeTerm> terms;
    double offset = 0.0;
    std::vector<RecipeTerm> den_terms = {};
    double den_offset = 1.0;
};

// The channel's expression over its core tables, e.g. "ggx_dfg.0 + ggx_dfg.1",
// "1 - ggx_albedo.0" or "(ggx_dfg.1) / (ggx_dfg.0 + ggx_dfg.1)": what the
// metadata records (model.recipe) and `list` shows.
std::string channel_expression(const ChannelRecipe& c);

// A core axis the recipe holds at one value instead of tabulating it: the
// value of the recipe table's option named after the axis (`--alpha 0.1`),
// for engines that tabulate one material at a time (Mitsuba 3's roughplastic
// precomputes its tables at the material's alpha and index). The option's
// value must lie in the domain of every core table's axis of that name.
struct AxisPin {
    std::string axis;  // the core axis, and the option's name
    std::string help;
    std::string default_value;
};

// A table declared as a recipe.
struct RecipeTable {
    std::string id;
    std::string description;    // one line
    std::string engine_source;  // where the convention comes from (model.engine_source)
    std::vector<AxisSpec> axes;  // the layout: counts, placement, warps, clamps
    std::vector<ChannelRecipe> channels;
    // Model options the core tables are evaluated with, e.g. visibility =
    // schlick_smith; each applies to every core table that has the option.
    std::map<std::string, std::string> options;
    nlohmann::json model;  // the table's model metadata (preset and engine_source are added)
    std::vector<ClosedFormCheck> checks;
    // The integer encoding the engine stores the texture in, if any
    // (TableDefinition::engine_storage).
    std::optional<Storage> engine_storage = std::nullopt;
    // Core axes held at one value (options of the table), fed to every core
    // table with an axis of that name that no recipe axis feeds.
    std::vector<AxisPin> pins = {};
};

// The method metadata of a group of recipe tables: the rule's description
// (the tolerance recorded is the largest of the core tables') and the Monte
// Carlo samplers'.
struct RecipeMethod {
    std::string quadrature_rule;
    std::string mc_sampler;
};

// How a recipe coordinate becomes a core table's coordinate.
enum class AxisConversion { same, square, root };

// A recipe resolved against the catalogue: for each core table it reads (in
// order of first use), its definition and, per core axis, the recipe axis
// that feeds it; per channel the terms as (core index, channel, coef).
struct RecipePlan {
    // A core axis is fed by recipe axis `axis`, or, when axis < 0, by the
    // value of pin `pin` (RecipeTable::pins).
    struct Feed {
        int axis;
        AxisConversion conversion;
        int pin = -1;
    };
    struct Core {
        const TableDefinition* def;
        std::vector<Feed> feeds;
    };
    struct Term {
        int core, channel;
        double coef;
    };
    struct Channel {
        std::vector<Term> terms;
        double offset;
        std::vector<Term> den_terms = {};
        double den_offset = 1.0;
        bool ratio() const { return !den_terms.empty() || den_offset != 1.0; }
    };
    std::vector<Core> cores;
    std::vector<Channel> channels;
};

// The most core tables one recipe table reads.
inline constexpr int kMaxRecipeCores = 4;

// Resolves a recipe; `lookup` returns the table of an id or nullptr. Throws
// brdflut::Error naming the entry and the bad table, channel, axis or
// option with what is allowed.
RecipePlan plan_recipe(const RecipeTable& entry, const std::function<const TableDefinition*(const std::string&)>& lookup);

// The catalogue definition of a recipe table of `preset`. Its checks are the
// entry's; whether it supports Monte Carlo and identify searches it is
// resolved from its core tables by resolve_recipe_tables.
TableDefinition recipe_table(const RecipeTable& entry, const std::string& preset, const RecipeMethod& method);

// Run once every family has added its tables (FamilyEntries::complete):
// checks the recipes of `entries` against the catalogue being built and
// sets their tables' supports_monte_carlo and searched_by_identify to those
// of all their core tables.
void resolve_recipe_tables(const std::vector<RecipeTable>& entries, FamilyEntries& family);

// An engine preset with the tables it declares as recipes (empty for the
// presets whose tables are fitted, not combined: ltc, hdrp_ltc).
struct PresetDeclaration {
    Preset preset;
    std::vector<RecipeTable> tables;
};
// Every preset, in `brdflut list --presets` order (preset_tables.cpp).
const std::vector<PresetDeclaration>& preset_declarations();

}  // namespace brdflut::tables
