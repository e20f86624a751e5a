// Which SIMD width the GGX integrands are evaluated with: ggx_split_sum's phi
// integrands and the glass albedos' ring and azimuth integrands
// (ggx_glass.cpp). 4 (AVX2, when the processor has it), 2 (SSE2) or 1 (one
// node at a time); at 4 the split sums' clipped arcs' Kronrod panel sums use
// AVX2 too. Every width computes the same operations in the same order, so
// the values are the same bits whatever it is; tests set it to check
// exactly that.
#pragma once

namespace brdflut::detail {

int ggx_phi_simd_width();
// Uses at most `width` lanes (never more than the processor has); returns
// the width now in use. Not thread-safe: call while no split sum or glass
// integral runs.
int set_ggx_phi_simd_width(int width);

}  // namespace brdflut::detail
