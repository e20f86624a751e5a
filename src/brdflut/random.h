// Reproducible random numbers for Monte Carlo estimates. std::mt19937_64's
// output sequence is fixed by the C++ standard; the conversion to [0, 1) is
// done here (std::uniform_real_distribution is implementation-defined).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

#include "brdflut/quadrature.h"

namespace brdflut {

// SplitMix64 (Steele et al. 2014): mixes a seed and a stream index into a
// well-distributed 64-bit state for the generator of each texel.
constexpr std::uint64_t mix_seed(std::uint64_t seed, std::uint64_t stream) {
    std::uint64_t z = seed + 0x9e3779b97f4a7c15ULL * (stream + 1);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

class Rng {
public:
    Rng(std::uint64_t seed, std::uint64_t stream) : engine_(mix_seed(seed, stream)) {}
    // Uniform in [0, 1) with 53 random bits.
    double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

private:
    std::mt19937_64 engine_;
};

// Running mean and standard error (Welford), per channel.
template <int N>
struct MeanAccumulator {
    long long n = 0;
    double mean[N] = {};
    double m2[N] = {};
    void add(const double* x) {
        ++n;
        for (int i = 0; i < N; ++i) {
            const double d = x[i] - mean[i];
            mean[i] += d / static_cast<double>(n);
            m2[i] += d * (x[i] - mean[i]);
        }
    }
    double standard_error(int i) const {
        if (n < 2) return HUGE_VAL;
        return std::sqrt(m2[i] / static_cast<double>(n - 1) / static_cast<double>(n));
    }
    // value = the mean, error = its standard error.
    Estimate<N> estimate() const {
        Estimate<N> e;
        for (int i = 0; i < N; ++i) {
            e.value[static_cast<std::size_t>(i)] = mean[i];
            e.error[static_cast<std::size_t>(i)] = standard_error(i);
        }
        e.evaluations = static_cast<int>(std::min<long long>(n, 1 << 30));
        return e;
    }
};

}  // namespace brdflut
