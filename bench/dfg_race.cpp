// ggx_dfg (quadrature, every stored float within 1e-7) against the estimator
// engines ship (Karis 2013 / Filament's DFG, 1024 Hammersley samples per
// texel, karis_dfg.h), on the same 128 x 128 grid, in one process, back to
// back, on 1 and 2 threads.
//
//   brdflut_dfg_race [--rounds R] [--samples N] [--quality Q]
//
// Each round times, per thread count, ggx_dfg (brdflut::generate, after
// clear_shared_results so that no split sum is reused) and the baseline in
// float and in double arithmetic, the order alternating between rounds so a
// drift of the machine's speed hits all alike; the medians and their ratio
// are printed, and the same for the process's CPU time (all threads). Then
// every table is compared with ggx_dfg at --quality reference: largest and
// rms difference of the values as stored in float. The lines starting with a
// keyword and key=value fields are the machine-readable output that
// brdflut_readme_figures (readme_figures.cpp) renders into README.md.
#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/partitioner.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <thread>
#include <vector>

#include "brdflut/catalogue.h"
#include "brdflut/generate.h"
#include "brdflut/table.h"
#include "karis_dfg.h"

using namespace brdflut;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// CPU time of the whole process (every thread), in seconds: on a loaded
// machine it compares the programs' work where wall times only add noise.
double cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The baseline's table on ggx_dfg's grid (mu along x, alpha along y), as
// float pairs, one row (one alpha) per task.
template <class Real>
std::vector<float> karis_table(const std::vector<double>& mu, const std::vector<double>& alpha,
                               std::uint32_t samples, int threads) {
    const std::size_t w = mu.size(), h = alpha.size();
    std::vector<float> out(2 * w * h);
    oneapi::tbb::global_control limit(oneapi::tbb::global_control::max_allowed_parallelism,
                                      static_cast<std::size_t>(threads));
    oneapi::tbb::parallel_for(
        oneapi::tbb::blocked_range<std::size_t>(0, h, 1),
        [&](const oneapi::tbb::blocked_range<std::size_t>& rows) {
            for (std::size_t j = rows.begin(); j != rows.end(); ++j)
                for (std::size_t i = 0; i < w; ++i) {
                    const bench::KarisDfg<Real> r = bench::karis_integrate_brdf<Real>(
                        static_cast<Real>(mu[i]), static_cast<Real>(alpha[j]), samples);
                    out[2 * (j * w + i)] = static_cast<float>(r.a);
                    out[2 * (j * w + i) + 1] = static_cast<float>(r.b);
                }
        },
        oneapi::tbb::simple_partitioner());
    return out;
}

struct Errors {
    double max = 0.0, rms = 0.0;
};

Errors errors(const std::vector<double>& stored, const Table& ref) {
    Errors e;
    double sum2 = 0.0;
    for (std::size_t n = 0; n < stored.size(); ++n) {
        const double d = std::abs(stored[n] - ref.values[n]);
        e.max = std::max(e.max, d);
        sum2 += d * d;
    }
    e.rms = std::sqrt(sum2 / static_cast<double>(stored.size()));
    return e;
}

}  // namespace

int main(int argc, char** argv) {
    int rounds = 9;
    std::uint32_t samples = 1024;
    std::string quality_name = "default";
    CLI::App app{"ggx_dfg against the 1024-sample estimator engines ship, back to back on 1 and 2 threads",
                 "brdflut_dfg_race"};
    app.add_option("--rounds", rounds, "Rounds of the three programs (alternating their order)")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000));
    app.add_option("--samples", samples, "Samples per texel of the estimator")
        ->capture_default_str()
        ->check(CLI::Range(1u, 1u << 24));
    app.add_option("--quality", quality_name, "Quadrature quality of ggx_dfg: draft, default or reference")
        ->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    Quality quality;
    try {
        quality = quality_from_string(quality_name);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 2;
    }

    const TableDefinition& def = find_table("ggx_dfg");
    TableSettings settings = default_settings(def);
    settings.quality = quality;
    std::vector<double> mu, alpha;
    for (int i = 0; i < settings.axes[0].count; ++i) mu.push_back(settings.axes[0].value(i));
    for (int j = 0; j < settings.axes[1].count; ++j) alpha.push_back(settings.axes[1].value(j));
    const std::size_t texels = mu.size() * alpha.size();

    std::printf("race table=ggx_dfg size=%zux%zu quality=%s samples=%u rounds=%d hardware_threads=%u\n",
                mu.size(), alpha.size(), std::string(to_string(quality)).c_str(), samples, rounds,
                std::thread::hardware_concurrency());

    const std::vector<int> thread_counts = {1, 2};
    const char* names[] = {"ggx_dfg", "karis_float", "karis_double"};
    // walls[threads index][program] = one entry per round
    std::vector<std::vector<std::vector<double>>> walls(thread_counts.size(),
                                                        std::vector<std::vector<double>>(3));
    auto cpus = walls;  // the same for the process's CPU time
    Table quad;
    std::vector<float> kf, kd;
    for (int r = 0; r < rounds; ++r)
        for (std::size_t ti = 0; ti < thread_counts.size(); ++ti) {
            const int threads = thread_counts[ti];
            auto run = [&](int program) {
                const auto t0 = Clock::now();
                const double c0 = cpu_seconds();
                if (program == 0) {
                    clear_shared_results();
                    GenerateOptions opt;
                    opt.threads = threads;
                    quad = generate(def, settings, opt);
                } else if (program == 1) {
                    kf = karis_table<float>(mu, alpha, samples, threads);
                } else {
                    kd = karis_table<double>(mu, alpha, samples, threads);
                }
                walls[ti][static_cast<std::size_t>(program)].push_back(seconds_since(t0));
                cpus[ti][static_cast<std::size_t>(program)].push_back(cpu_seconds() - c0);
            };
            if (r % 2 == 0)
                for (int p = 0; p < 3; ++p) run(p);
            else
                for (int p = 2; p >= 0; --p) run(p);
        }

    for (std::size_t ti = 0; ti < thread_counts.size(); ++ti) {
        for (std::size_t p = 0; p < 3; ++p) {
            const std::vector<double>& w = walls[ti][p];
            std::printf("time program=%s threads=%d median_s=%.4f min_s=%.4f max_s=%.4f median_cpu_s=%.4f\n",
                        names[p], thread_counts[ti], median(w), *std::min_element(w.begin(), w.end()),
                        *std::max_element(w.begin(), w.end()), median(cpus[ti][p]));
        }
        const double q = median(walls[ti][0]), qc = median(cpus[ti][0]);
        std::printf("ratio threads=%d ggx_dfg_over_karis_float=%.3f ggx_dfg_over_karis_double=%.3f "
                    "cpu_ggx_dfg_over_karis_float=%.3f cpu_ggx_dfg_over_karis_double=%.3f\n",
                    thread_counts[ti], q / median(walls[ti][1]), q / median(walls[ti][2]), qc / median(cpus[ti][1]),
                    qc / median(cpus[ti][2]));
    }

    // Accuracy against the reference-quality table.
    TableSettings ref_settings = settings;
    ref_settings.quality = Quality::reference;
    const Table ref = generate(def, ref_settings);
    std::vector<double> stored(quad.values.size());
    for (std::size_t n = 0; n < stored.size(); ++n)
        stored[n] = round_to_storage(quad.values[n], PixelType::float32);
    const Errors eq = errors(stored, ref);
    std::printf("accuracy program=ggx_dfg evaluations_per_texel=%.0f max_error=%.2e rms_error=%.2e "
                "error_bound=%.2e\n",
                static_cast<double>(quad.evaluations) / static_cast<double>(texels), eq.max, eq.rms,
                error_bound(quad, PixelType::float32));
    for (int p = 1; p < 3; ++p) {
        const std::vector<float>& k = p == 1 ? kf : kd;
        for (std::size_t n = 0; n < stored.size(); ++n) stored[n] = k[n];
        const Errors e = errors(stored, ref);
        std::printf("accuracy program=%s evaluations_per_texel=%u max_error=%.2e rms_error=%.2e\n", names[p],
                    samples, e.max, e.rms);
    }
    return 0;
}
