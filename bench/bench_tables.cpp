// Google Benchmark timings of the GGX integrals behind the tables: one
// split sum (one texel of ggx_dfg / ggx_albedo) and one E_avg (one texel of
// ggx_albedo_avg) at the tables' tolerance, at representative (mu, alpha).
// These call the integrators directly (no table-level sharing). For whole
// tables at default settings, with their error, run brdflut_table_report.
//
//   ./build/bench/brdflut_bench
#include <benchmark/benchmark.h>

#include "brdflut/ggx_integrals.h"

using namespace brdflut;

namespace {

// Texel centres of the default 128 x 128 grid: mu = (i + 0.5) / 128,
// alpha = ((j + 0.5) / 128)^2.
double grid_mu(std::int64_t i) { return (static_cast<double>(i) + 0.5) / 128.0; }
double grid_alpha(std::int64_t j) {
    const double r = (static_cast<double>(j) + 0.5) / 128.0;
    return r * r;
}

void BM_GgxSplitSum(benchmark::State& state) {
    const double mu = grid_mu(state.range(0)), alpha = grid_alpha(state.range(1));
    int evaluations = 0;
    for (auto _ : state) {
        const Estimate<2> e = ggx_split_sum(mu, alpha, Visibility::height_correlated, kGgxTableTolerance);
        benchmark::DoNotOptimize(e);
        evaluations = e.evaluations;
    }
    state.counters["outer_nodes"] = evaluations;
}
// (mu index, alpha index): grazing, middle and normal view; smallest, small,
// medium and roughest alpha.
BENCHMARK(BM_GgxSplitSum)
    ->ArgsProduct({{0, 64, 127}, {0, 8, 64, 127}})
    ->Unit(benchmark::kMicrosecond);

void BM_GgxAlbedoAverage(benchmark::State& state) {
    const double alpha = grid_alpha(state.range(0));
    for (auto _ : state) {
        const Estimate<1> e = ggx_albedo_average(alpha, Visibility::height_correlated, kGgxTableTolerance);
        benchmark::DoNotOptimize(e);
    }
}
BENCHMARK(BM_GgxAlbedoAverage)->Arg(0)->Arg(8)->Arg(64)->Arg(127)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
