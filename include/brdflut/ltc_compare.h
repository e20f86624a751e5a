// Comparing a stored LTC matrix table (ltc_1, hdrp_ltc_ggx, ...) with the
// lobe it stands for: the integrated-light error of its matrices next to
// brdflut's refit (src/check/ltc_compare.cpp), which `compare` reports
// beside the comparison of values (lut.h).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "brdflut/ltc.h"

namespace brdflut {

struct ExrImage;
struct LutDescription;
struct TableDefinition;

// True for the tables whose channels are an LTC matrix (ltc_1, hdrp_ltc_ggx):
// those whose shader lookup returns it (TableDefinition::shader_result).
bool is_ltc_matrix_table(const std::string& id);

// The stored inverse matrix of such a table from one texel's channels
// (R, G, B, A), by the table's packing (TableDefinition::shader_matrix, the
// same that the generated shader functions follow). Scaled as stored.
Mat3 stored_ltc_inverse(const TableDefinition& def, const double* channels);

struct LtcComparison {
    std::size_t texels = 0;
    // Over the texels: the largest integrated-light error (over the light
    // bank, as a fraction of n0) of the stored matrices, with the exact n0,
    // and of brdflut's refit at the same texels; and their medians.
    double stored_light_max = 0, stored_light_median = 0;
    double refit_light_max = 0, refit_light_median = 0;
    std::size_t refit_better = 0;  // texels where the refit's error is lower by more than 1e-6
    double stored_below_horizon_max = 0;
    std::vector<double> stored_light;  // per texel, storage order
    std::vector<double> refit_light;
};

// Reads each texel's matrix from the file (in the layout of its table),
// and reports its integrated-light error against the exact light of the
// lobe, next to the refit's. Throws Error for a file with a channel map.
LtcComparison compare_ltc_light(const ExrImage& img, const LutDescription& d, int threads);

}  // namespace brdflut
