// verify's checks of the LTC tables (ltc_checks.cpp).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "brdflut/verify.h"

namespace brdflut {
void add_ltc_checks(std::map<std::string, std::vector<ClosedFormCheck>>& m);
}  // namespace brdflut
