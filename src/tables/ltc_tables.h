// What the LTC family (ltc_tables.cpp) tells the checks and the comparison
// of its tables: the lobe a table fits at a texel.
#pragma once

#include "brdflut/catalogue.h"
#include "brdflut/ltc_fit.h"
#include "brdflut/microfacet.h"

namespace brdflut {

// The lobe that the catalogue's LTC table `def` (ltc_1, ltc_sheen_charlie,
// ...) fits at the texel (roughness coordinate, cos_theta): its kind and the
// table's mapping of the roughness coordinate to the lobe's parameter; vis
// is the table's visibility option (GGX only). Throws Error for a table of
// another family.
LtcLobe ltc_table_lobe(const TableDefinition& def, double roughness, double mu,
                       Visibility vis = Visibility::height_correlated);

}  // namespace brdflut
