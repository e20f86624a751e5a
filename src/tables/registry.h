// Each family of tables adds its definitions to the catalogue here.
#pragma once

#include <functional>
#include <vector>

#include "brdflut/burley.h"
#include "brdflut/catalogue.h"
#include "brdflut/furnace.h"
#include "brdflut/microfacet.h"
#include "brdflut/quadrature.h"
#include "brdflut/skin.h"

namespace brdflut {

// What one family file gives the catalogue: its tables, each with its
// independent checks, and the white-furnace models built on them.
struct FamilyEntries {
    std::vector<TableDefinition> tables;
    std::vector<FurnaceModel> furnace_models;
    // Each family adds its own description (title and summary; the name is
    // set by the catalogue).
    std::vector<TableFamily> families;
    // Run once every family has added its entries, in the order added: for
    // entries resolved against other families' tables (recipe.h).
    std::vector<std::function<void(FamilyEntries&)>> complete;
};

// A family file src/tables/NAME_tables.cpp defines
//   void register_NAME_family(FamilyEntries& out);
// which adds its entries; the build finds the file and the catalogue calls
// it (CMakeLists.txt, families.inc).

// Every family's entries, registered once (catalogue() and furnace_models()
// read them).
const FamilyEntries& families();

// Helpers shared by the table families.
namespace tables {

// The standard axes: view cosine, GGX alpha.
AxisSpec cos_theta_axis(int count = 128);
AxisSpec alpha_axis(int count = 128);

// The GGX shadowing-masking option (`--visibility`), one help text for every
// table that takes it; `allowed` narrows the values a table accepts.
ModelOption visibility_option(std::vector<std::string> allowed = {"height_correlated", "separable",
                                                                  "schlick_smith"});

// The option value of `name`, which validate_settings has checked.
const std::string& param(const TableSettings& s, const std::string& name);
// The value of a numeric option; throws brdflut::Error ("--OPTION 'S' is not
// a finite number") unless s is one finite number.
double parse_number(const std::string& option, const std::string& s);

// The absolute tolerance of a table family at each quality.
struct Tolerances {
    double draft, standard, reference;
    double at(Quality q) const {
        return q == Quality::draft ? draft : q == Quality::reference ? reference : standard;
    }
};

// The draft and reference tolerances shared by the integrated (non-Fresnel)
// tables, around a table's own default.
constexpr Tolerances quadrature_tolerances(double standard) { return {1e-5, standard, 1e-12}; }

// The glass tables' tolerances: the reference quality is 1e-10, not 1e-12,
// because the nested glass quadrature reaches 1e-12 only at hundreds of
// milliseconds per texel (it is still 200 times tighter than the default).
inline constexpr Tolerances kGlassTolerances{1e-5, 5e-8, 1e-10};

// Method metadata of the adaptive quadrature and of the Monte Carlo route.
nlohmann::json quadrature_method(const std::string& rule, double abs_tol);
nlohmann::json monte_carlo_method(const std::string& sampler, const TableSettings& s);

// The glass tables' index axis and model metadata
// (glass_tables.cpp), shared with the engine presets.
AxisSpec ior_axis(int count = 16);
nlohmann::json glass_model(Visibility vis, bool inside);
// {E_R avg, E_T avg} of index n >= 1 seen from outside (eta = n) or inside
// (eta = 1/n), for the glass tables and the presets: the outside
// transmission of each (alpha, n, visibility, tolerance), which gives both
// sides (ggx_glass_average_of_parts), is integrated once per process and
// shared (its evaluations are counted where it is computed).
Estimate<2> glass_average(double alpha, double n, bool inside, Visibility vis, double abs_tol);

// The GGX tables' absolute tolerance at a quality (ggx_tables.cpp), which
// every table of the same integrals (the presets) takes.
double ggx_table_tolerance(Quality q);
// {A, B} of the GGX split sum, integrated once per process for each (mu,
// alpha, visibility, tolerance) and shared by every table that needs it
// (ggx_dfg, ggx_albedo, the presets); *computed (if given) says whether this
// call integrated it.
Estimate<2> ggx_split_sum_shared(double mu, double alpha, Visibility vis, double abs_tol, bool* computed = nullptr);

// Model metadata of the Charlie sheen lobe (sheen_tables.cpp).
nlohmann::json charlie_sheen_model();

// The Burley profile's `--scaling` option (burley_tables.cpp), one help text
// for every table that takes it.
ModelOption burley_scaling_option();

// "r,g,b": three finite numbers in [lo, hi] (lo excluded when open_lo);
// throws brdflut::Error naming the option, the value and `allowed`.
std::array<double, 3> parse_rgb(const std::string& option, const std::string& s, double lo, bool open_lo, double hi,
                                const std::string& allowed);

// Burley's profile per colour channel (skin_tables.cpp), for every table
// that takes one: the options --surface-albedo, --dmfp (mm) and --scaling,
// their values, the profiles (d = l / s(A) per channel) and their model
// metadata.
struct BurleyRgb {
    std::array<double, 3> albedo, dmfp;
    BurleyScaling scaling;
};
std::vector<ModelOption> burley_rgb_options();
BurleyRgb burley_rgb(const TableSettings& s);
SkinProfile burley_rgb_profile(const BurleyRgb& b);
nlohmann::json burley_rgb_model(const BurleyRgb& b);

// Number of standard errors a Monte Carlo texel's error estimate spans.
inline constexpr double kMcErrorSigmas = 4.0;

}  // namespace tables
}  // namespace brdflut
