// LTC area-light tables as a family declares them (ltc_tables.cpp builds
// them): a table is its lobe at each texel, its layout and its texts; the
// fit, the error report, the checks every LTC table gets and the metadata
// are the same for every lobe. The LTC family (ltc_tables.cpp) declares the
// GGX, Charlie sheen and EON tables this way; any other family declares the
// LTC of a lobe of its own (a GenericLobe, LtcLobe's generic kind) the same
// way, e.g. the Beckmann family's HDRP Cook-Torrance layer.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdflut/catalogue.h"
#include "brdflut/ltc_fit.h"
#include "brdflut/microfacet.h"

namespace brdflut {

// How a table stores a texel's fit (or the lobe's norms).
enum class LtcLayout {
    heitz_matrix,  // ltc_1: (m00, m02, m20, m22) of M^-1 / M^-1[1][1], glm m[col][row]
    heitz_norms,   // ltc_2: (n0, n1, 0, sphere form factor)
    norm,          // n0 alone (the lobes without a Fresnel moment)
    hdrp_matrix,   // (m00, m20, m11, m02) of M^-1 / M^-1[2][2], HLSL _mRC
    report,        // the per-texel error figures of the fit (an _error table)
};

// The lobe a table fits at a texel: (roughness coordinate, cos_theta) and
// the table's model options (every option of the table, defaults filled in).
using LtcTexelLobe =
    std::function<LtcLobe(double roughness, double mu, const std::map<std::string, std::string>& options)>;

struct LtcTableSpec {
    std::string id, preset, description;
    LtcLayout layout = LtcLayout::heitz_matrix;
    std::string layout_text;  // the layout in the metadata (what a shader does with the channels)
    std::vector<std::string> channels;
    AxisSpec roughness;  // the first axis; the second is the rows in sqrt(1 - cos theta) of every LTC table
    std::vector<ModelOption> options;
    // The model metadata for the table's options (the layout, frame, preset
    // and engine source are added).
    std::function<nlohmann::json(const std::map<std::string, std::string>& options)> model;
    std::string engine_source;
    std::string norms_rule;    // how n0 (and n1) are computed, e.g. "n0 by the eon_albedo quadrature"
    std::string report_table;  // the id of the error table on this lobe's grid (for the metadata's text)
    LtcTexelLobe lobe;
    // Checks beyond the ones every table of its layout gets (the local
    // minimum and metadata maxima of a matrix table, the report check of an
    // error table): the closed forms of the norms.
    std::vector<ClosedFormCheck> checks;
};

// The catalogue table of a spec, with the checks of its layout. Records the
// spec's lobe for ltc_table_lobe.
TableDefinition ltc_table(LtcTableSpec spec);

// An LTC layer of a lobe fitted through the generic path, on the 64x64 grid
// HDRP and Heitz share (roughness r = i/63 at end points, the lobe's
// alpha = max(r^2, its floor); rows cos(theta) = 1 - (j/63)^2).
struct LtcLayer {
    std::string name;                // the ids' stem, e.g. "cook_torrance"
    std::string matrix_description;  // the matrix table's one line
    std::string error_description;   // the error table's one line
    std::string norm_description;    // the norm table's one line (Heitz's layout)
    std::string roughness_meaning;   // the roughness axis's text, with the alpha floor
    std::function<nlohmann::json(const std::map<std::string, std::string>& options)> model;
    std::string engine_source;
    std::string norms_rule;
    LtcTexelLobe lobe;
    // Checks of the norm table (Heitz's layout): its closed forms or an
    // independent rule.
    std::vector<ClosedFormCheck> norm_checks;
};
// HDRP's layer: the matrix table hdrp_ltc_<name> in HDRP's packing and its
// per-texel error table hdrp_ltc_<name>_error, in the hdrp_ltc preset.
std::vector<TableDefinition> hdrp_ltc_layer(const LtcLayer& layer);
// Heitz's layer (ltc_1's packing, as three.js, EEVEE and Godot load it): the
// matrix table ltc_<name>, its norm ltc_<name>_norm (n0: the lobe's albedo)
// and its error table ltc_<name>_error, in the ltc preset.
std::vector<TableDefinition> heitz_ltc_layer(const LtcLayer& layer);

// The lobe that the catalogue's LTC table `def` fits at the texel
// (roughness coordinate, cos_theta), with the table's options (missing ones
// take their defaults). Throws Error for a table that is not an LTC table.
LtcLobe ltc_table_lobe(const TableDefinition& def, double roughness, double mu,
                       const std::map<std::string, std::string>& options = {});

// A key for LtcLobe's generic constructor from the lobe's name.
std::uint64_t ltc_lobe_key(const std::string& name);

}  // namespace brdflut
