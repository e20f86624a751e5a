// The LTC tables' checks that fit or generate (ltc_checks.cpp); the LTC
// family (src/tables/ltc_tables.cpp) declares which table runs which.
#pragma once

#include <string>
#include <vector>

#include "brdflut/catalogue.h"

namespace brdflut {
// Checks of the LTC table `id`, whose roughness coordinate is named
// `parameter` in the rows' text: the fit at a spread of texels is a local
// minimum of its objective; the error maxima in a matrix table's metadata
// match a recomputation; an error report table's light errors match a
// report with finer exact lights.
ClosedFormCheck ltc_local_minimum_check(const std::string& id, const std::string& parameter);
ClosedFormCheck ltc_metadata_maxima_check(const std::string& id);
ClosedFormCheck ltc_report_check(const std::string& id, const std::string& parameter);
}  // namespace brdflut
