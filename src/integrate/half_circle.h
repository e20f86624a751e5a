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

// Integral over phi in [0, pi] of f(cos(phi)) (f returns std::array<double, N>):
// the nodes are doubled until two successive sums differ by at most tol
// (summed over channels; at least 8 intervals). Returns the N values and,
// last, that difference as the error estimate (tol if the table runs out).
// Adds the number of evaluations of f to *evaluations when given.
template <std::size_t N, class F>
std::array<double, N + 1> trapezoid_half_circle(F&& f, double tol, int* evaluations = nullptr) {
    const std::vector<double>& cosines = half_circle_cosines();
    auto sample = [&](int j) { return f(cosines[static_cast<std::size_t>(j)]); };
    const std::array<double, N> ends = sample(0), mid = sample(kHalfCircleSteps);
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
        // An integrand with a member batch(const double* cos_phi,
        // std::array<double, N>* y, int n) gets the nodes in chunks (to use
        // SIMD); it must return exactly what f(cos_phi) returns, and the sum
        // is taken in the same order either way.
        if constexpr (requires(const double* c, std::array<double, N>* ys) { f.batch(c, ys, 1); }) {
            constexpr int kChunk = 32;
            std::array<double, kChunk> c;
            std::array<std::array<double, N>, kChunk> ys;
            for (int k0 = 0; k0 < n; k0 += kChunk) {
                const int m = std::min(kChunk, n - k0);
                for (int k = 0; k < m; ++k)
                    c[static_cast<std::size_t>(k)] = cosines[static_cast<std::size_t>((2 * (k0 + k) + 1) * stride / 2)];
                f.batch(c.data(), ys.data(), m);
                for (int k = 0; k < m; ++k)
                    for (std::size_t i = 0; i < N; ++i) sum[i] += ys[static_cast<std::size_t>(k)][i];
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
