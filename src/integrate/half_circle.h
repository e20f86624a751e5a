// The doubling trapezoidal rule over phi in [0, pi] for integrands that are
// even and 2 pi periodic in phi (exponentially convergent when smooth), with
// the cosines of the nodes taken from a table computed once.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "brdflut/math.h"
#include "brdflut/quadrature.h"

namespace brdflut::detail {

// cos(j pi / kHalfCircleSteps), j = 0..kHalfCircleSteps.
inline constexpr int kHalfCircleSteps = 8192;
inline const std::vector<double>& half_circle_cosines() {
    static const std::vector<double> table = [] {
        std::vector<double> c(kHalfCircleSteps + 1);
        for (int j = 0; j <= kHalfCircleSteps; ++j)
            c[static_cast<std::size_t>(j)] = std::cos(j * kPi / kHalfCircleSteps);
        return c;
    }();
    return table;
}

// The nodes the doubling adds, level by level: entries n .. 2n - 1 are
// cos((2k + 1) pi / (2n)), k = 0..n-1, for n = 1, 2, 4, .., kHalfCircleSteps / 2
// (the same values as half_circle_cosines(), laid out contiguously).
inline const std::vector<double>& half_circle_level_cosines() {
    static const std::vector<double> table = [] {
        const std::vector<double>& c = half_circle_cosines();
        std::vector<double> t(kHalfCircleSteps);
        for (int n = 1; n <= kHalfCircleSteps / 2; n *= 2)
            for (int k = 0; k < n; ++k)
                t[static_cast<std::size_t>(n + k)] = c[static_cast<std::size_t>((2 * k + 1) * (kHalfCircleSteps / n) / 2)];
        return t;
    }();
    return table;
}

// The nodes every run of the doubling evaluates (it stops at 8 intervals at
// the earliest): cos(0), cos(pi), then levels n = 1, 2, 4 as laid out in
// half_circle_level_cosines().
inline constexpr int kHalfCircleFirstNodes = 9;
inline const std::array<double, kHalfCircleFirstNodes>& half_circle_first_nodes() {
    static const std::array<double, kHalfCircleFirstNodes> nodes = [] {
        const std::vector<double>& level = half_circle_level_cosines();
        std::array<double, kHalfCircleFirstNodes> c{};
        c[0] = half_circle_cosines().front();
        c[1] = half_circle_cosines().back();
        for (int j = 1; j < 8; ++j) c[static_cast<std::size_t>(1 + j)] = level[static_cast<std::size_t>(j)];
        return c;
    }();
    return nodes;
}

// Integral over phi in [0, pi] of f(cos(phi)) (f returns std::array<double, N>):
// the nodes are doubled until two successive sums differ by at most tol
// (summed over channels; at least 8 intervals). Returns the N values and,
// last, that difference as the error estimate (tol if the table runs out).
// Adds the number of evaluations of f to *evaluations when given.
template <std::size_t N, class F>
std::array<double, N + 1> trapezoid_half_circle(F&& f, double tol, int* evaluations = nullptr) {
    const std::vector<double>& cosines = half_circle_cosines();
    auto sample = [&](int j) { return f(cosines[static_cast<std::size_t>(j)]); };
    // An integrand with a member batch(const double* cos_phi,
    // std::array<double, N>* y, int n) gets the nodes many at a time (to use
    // SIMD): first the nodes every run needs, then each further level in
    // chunks. It must return exactly what f(cos_phi) returns, and the sum is
    // taken in the same order either way.
    constexpr bool kBatch = requires(const double* c, std::array<double, N>* ys) { f.batch(c, ys, 1); };
    std::array<std::array<double, N>, kHalfCircleFirstNodes> first;
    if constexpr (kBatch) f.batch(half_circle_first_nodes().data(), first.data(), kHalfCircleFirstNodes);
    const std::array<double, N> ends = kBatch ? first[0] : sample(0);
    const std::array<double, N> mid = kBatch ? first[1] : sample(kHalfCircleSteps);
    std::array<double, N> sum, prev;
    for (std::size_t i = 0; i < N; ++i) {
        sum[i] = 0.5 * (ends[i] + mid[i]);
        prev[i] = HUGE_VAL;
    }
    std::array<double, N + 1> out{};
    if (evaluations) *evaluations += 2;
    for (int n = 1; n <= kHalfCircleSteps / 2; n *= 2) {
        if (evaluations) *evaluations += n;
        // Add the nodes (2k + 1) pi / (2n), halving the step to pi / (2n).
        const int stride = kHalfCircleSteps / n;
        if constexpr (kBatch) {
            constexpr int kChunk = 32;
            if (n <= 4) {  // among the first nodes, from index 2 + (n - 1)
                for (int k = 0; k < n; ++k)
                    for (std::size_t i = 0; i < N; ++i) sum[i] += first[static_cast<std::size_t>(1 + n + k)][i];
            } else {
                const double* level = half_circle_level_cosines().data() + n;
                std::array<std::array<double, N>, kChunk> ys;
                for (int k0 = 0; k0 < n; k0 += kChunk) {
                    const int m = std::min(kChunk, n - k0);
                    f.batch(level + k0, ys.data(), m);
                    for (int k = 0; k < m; ++k)
                        for (std::size_t i = 0; i < N; ++i) sum[i] += ys[static_cast<std::size_t>(k)][i];
                }
            }
        } else {
            for (int k = 0; k < n; ++k) {
                const std::array<double, N> y = sample((2 * k + 1) * stride / 2);
                for (std::size_t i = 0; i < N; ++i) sum[i] += y[i];
            }
        }
        const double h = kPi / (2.0 * n);
        double err = 0.0;
        std::array<double, N> cur;
        for (std::size_t i = 0; i < N; ++i) {
            cur[i] = sum[i] * h;
            err += std::abs(cur[i] - prev[i]);
        }
        if (n >= 4 && err <= tol) {
            for (std::size_t i = 0; i < N; ++i) out[i] = cur[i];
            out[N] = err;
            return out;
        }
        prev = cur;
    }
    for (std::size_t i = 0; i < N; ++i) out[i] = prev[i];
    out[N] = tol;
    return out;
}

}  // namespace brdflut::detail
