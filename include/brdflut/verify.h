// Checks of the catalogue: closed forms, and an independent Monte Carlo
// estimate at a spread of texels. `brdflut verify` prints these rows and the
// tests assert them.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "brdflut/catalogue.h"

namespace brdflut {

struct CheckRow {
    std::string table;
    std::string check;
    double max_error = 0.0;   // largest error found
    double tolerance = 0.0;   // what the check allows there
    bool pass = false;
    std::string where;        // parameters of the worst point
};

// The independent checks of a table (TableDefinition::checks); throws
// brdflut::Error when the id is not in the catalogue.
const std::vector<ClosedFormCheck>& closed_form_checks(const std::string& table_id);

struct VerifyOptions {
    long long mc_samples = 100000;  // per texel for the Monte Carlo check
    std::uint64_t seed = 20260101;
};

// Every check of one table, in a fixed order.
std::vector<CheckRow> verify_table(const TableDefinition& def, const VerifyOptions& opt = {});

// Texels the Monte Carlo check visits: every combination of the first,
// middle and last index of each default axis (grazing angles and the
// smallest roughness included).
std::vector<std::vector<int>> verify_texels(const TableDefinition& def);

}  // namespace brdflut
