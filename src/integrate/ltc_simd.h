// Which path the LTC fit's objective sums its grid with: 2 (SSE2, two
// nodes per register) or 1 (one node at a time). Both compute the same
// operations in the same order, so the fits are the same bits whichever
// runs; tests set it to check exactly that.
#pragma once

namespace brdflut::detail {

int ltc_objective_simd_width();
// Uses at most `width` lanes (never more than the build has); returns the
// width now in use. Not thread-safe: call while no fit runs.
int set_ltc_objective_simd_width(int width);

}  // namespace brdflut::detail
