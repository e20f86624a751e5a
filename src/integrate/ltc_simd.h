// Which path the LTC fit's objective sums its grid with: 4 (AVX2, when the
// processor has it: four nodes per register), 2 (SSE2, two) or 1 (one node
// at a time). All compute the same operations in the same order, so the
// fits are the same bits whichever runs; tests set it to check exactly that.
#pragma once

namespace brdflut::detail {

int ltc_objective_simd_width();
// Uses at most `width` lanes (4, 2 or 1; never more than the build and the
// processor have); returns the width now in use. Not thread-safe: call
// while no fit runs.
int set_ltc_objective_simd_width(int width);

}  // namespace brdflut::detail
