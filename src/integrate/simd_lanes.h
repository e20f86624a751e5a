// The lane types of the SIMD integrand kernels: V::width doubles with the
// correctly rounded IEEE operations (+ - * /, sqrt), lane masks (gt) and
// bitwise selection (band, bor, bandnot = ~a & b), V::set1, V::load, store
// and store_pairs. simd::scalar::V (1 lane) everywhere; simd::sse2::V (2
// lanes) wherever the build targets SSE2; simd::avx2::V (4 lanes) on x86-64
// with GCC or Clang whatever the build's target, compiled for AVX2 and to be
// called only when the processor has it (BRDFLUT_HAVE_AVX2_KERNELS; code
// for AVX2 goes between BRDFLUT_AVX2_BEGIN and BRDFLUT_AVX2_END). AVX2 alone
// implies no fused multiply-add, so the lanes of every type round exactly
// as one double at a time: a kernel written once over V gives the same bits
// at every width.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace brdflut::simd::scalar {
struct V {
    double v;
    static constexpr int width = 1;
    static V set1(double x) { return {x}; }
    static V load(const double* p) { return {*p}; }
};
inline V operator+(V a, V b) { return {a.v + b.v}; }
inline V operator-(V a, V b) { return {a.v - b.v}; }
inline V operator*(V a, V b) { return {a.v * b.v}; }
inline V operator/(V a, V b) { return {a.v / b.v}; }
inline V sqrt(V a) { return {std::sqrt(a.v)}; }
inline std::uint64_t bits(V a) { return std::bit_cast<std::uint64_t>(a.v); }
inline V from_bits(std::uint64_t b) { return {std::bit_cast<double>(b)}; }
inline V gt(V a, V b) { return from_bits(a.v > b.v ? ~std::uint64_t{0} : 0); }
inline V band(V a, V b) { return from_bits(bits(a) & bits(b)); }
inline V bor(V a, V b) { return from_bits(bits(a) | bits(b)); }
inline V bandnot(V a, V b) { return from_bits(~bits(a) & bits(b)); }
inline void store(double* y, V a) { *y = a.v; }
inline void store_pairs(double* y, V a, V b) {
    y[0] = a.v;
    y[1] = b.v;
}
}  // namespace brdflut::simd::scalar

#if defined(__SSE2__)
namespace brdflut::simd::sse2 {
struct V {
    __m128d v;
    static constexpr int width = 2;
    static V set1(double x) { return {_mm_set1_pd(x)}; }
    static V load(const double* p) { return {_mm_loadu_pd(p)}; }
};
inline V operator+(V a, V b) { return {_mm_add_pd(a.v, b.v)}; }
inline V operator-(V a, V b) { return {_mm_sub_pd(a.v, b.v)}; }
inline V operator*(V a, V b) { return {_mm_mul_pd(a.v, b.v)}; }
inline V operator/(V a, V b) { return {_mm_div_pd(a.v, b.v)}; }
inline V sqrt(V a) { return {_mm_sqrt_pd(a.v)}; }
inline V gt(V a, V b) { return {_mm_cmpgt_pd(a.v, b.v)}; }
inline V band(V a, V b) { return {_mm_and_pd(a.v, b.v)}; }
inline V bor(V a, V b) { return {_mm_or_pd(a.v, b.v)}; }
inline V bandnot(V a, V b) { return {_mm_andnot_pd(a.v, b.v)}; }
inline void store(double* y, V a) { _mm_storeu_pd(y, a.v); }
// {a_j, b_j} at y + 2 j for the lanes j.
inline void store_pairs(double* y, V a, V b) {
    _mm_storeu_pd(y, _mm_unpacklo_pd(a.v, b.v));
    _mm_storeu_pd(y + 2, _mm_unpackhi_pd(a.v, b.v));
}
}  // namespace brdflut::simd::sse2
#endif

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define BRDFLUT_HAVE_AVX2_KERNELS 1
#if defined(__clang__)
#define BRDFLUT_AVX2_BEGIN _Pragma("clang attribute push(__attribute__((target(\"avx2\"))), apply_to = function)")
#define BRDFLUT_AVX2_END _Pragma("clang attribute pop")
#else
#define BRDFLUT_AVX2_BEGIN _Pragma("GCC push_options") _Pragma("GCC target(\"avx2\")")
#define BRDFLUT_AVX2_END _Pragma("GCC pop_options")
#endif
BRDFLUT_AVX2_BEGIN
namespace brdflut::simd::avx2 {
struct V {
    __m256d v;
    static constexpr int width = 4;
    static V set1(double x) { return {_mm256_set1_pd(x)}; }
    static V load(const double* p) { return {_mm256_loadu_pd(p)}; }
};
inline V operator+(V a, V b) { return {_mm256_add_pd(a.v, b.v)}; }
inline V operator-(V a, V b) { return {_mm256_sub_pd(a.v, b.v)}; }
inline V operator*(V a, V b) { return {_mm256_mul_pd(a.v, b.v)}; }
inline V operator/(V a, V b) { return {_mm256_div_pd(a.v, b.v)}; }
inline V sqrt(V a) { return {_mm256_sqrt_pd(a.v)}; }
inline V gt(V a, V b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_GT_OQ)}; }
inline V band(V a, V b) { return {_mm256_and_pd(a.v, b.v)}; }
inline V bor(V a, V b) { return {_mm256_or_pd(a.v, b.v)}; }
inline V bandnot(V a, V b) { return {_mm256_andnot_pd(a.v, b.v)}; }
inline void store(double* y, V a) { _mm256_storeu_pd(y, a.v); }
inline void store_pairs(double* y, V a, V b) {
    const __m256d lo = _mm256_unpacklo_pd(a.v, b.v);  // {a0, b0, a2, b2}
    const __m256d hi = _mm256_unpackhi_pd(a.v, b.v);  // {a1, b1, a3, b3}
    _mm256_storeu_pd(y, _mm256_permute2f128_pd(lo, hi, 0x20));
    _mm256_storeu_pd(y + 4, _mm256_permute2f128_pd(lo, hi, 0x31));
}
}  // namespace brdflut::simd::avx2
BRDFLUT_AVX2_END
#endif

// Plain loops that the compiler vectorizes (dense matrix products and
// eliminations), compiled twice, for AVX2 and for the build's target, the
// one the processor has chosen when the program loads (target_clones).
// Neither clone fuses a multiply and an add, and a vectorized loop keeps
// each element's operations in their order, so both give the same bits.
#if defined(BRDFLUT_HAVE_AVX2_KERNELS) && defined(__has_attribute)
#if __has_attribute(target_clones)
#define BRDFLUT_WIDEST_CLONES __attribute__((target_clones("avx2", "default")))
#endif
#endif
#if !defined(BRDFLUT_WIDEST_CLONES)
#define BRDFLUT_WIDEST_CLONES
#endif
