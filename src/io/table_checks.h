// Checks every table writer makes before it creates a file, so that a refused
// table never leaves a file (partial or stale) behind.
#pragma once

#include <cstddef>
#include <string>

#include "brdflut/table.h"

namespace brdflut {

// Names one value of a table: "texel (cos_theta index 3 = 0.27, alpha index 5
// = 0.1), channel G".
std::string describe_value(const Table& t, std::size_t value_index);

// Refuses a table with 0 or more than 4 channels, or whose value count does
// not match its axes (brdflut::Error).
void check_shape(const Table& t);

// Refuses, naming the table, texel, channel and value:
//  - a NaN or infinite value, or one that overflows the storage type (half:
//    |v| > 65504 after rounding) -> brdflut::RuntimeError (a fault of the data);
//  - for an integer encoding, a value outside its range ([0, 1], rgbd
//    [0, 255]) or more channels than it holds -> brdflut::Error (the table
//    cannot be stored that way; another can). Values are never clamped.
void check_storable(const Table& t, Storage s);

}  // namespace brdflut
