// Timed generation of the GGX tables at default settings, and their largest
// error against a much finer reference run.
//
//   brdflut_table_report [--reference-tol T] [--stride S] [--threads N] [--no-mc]
//
// 1. Generates ggx_dfg, ggx_albedo and ggx_albedo_avg in this order in one
//    process (as `brdflut generate ggx_dfg ggx_albedo ggx_albedo_avg` does;
//    ggx_albedo reuses ggx_dfg's split sums) and prints the wall time of each.
// 2. Recomputes every S-th texel (along each axis) with the same integrals at
//    absolute tolerance T (default 1e-12, 10,000 times tighter than the tables)
//    and prints, per table, the largest difference of the computed values and
//    of the stored float values, the metadata `error_bound`, and whether every
//    value's own error estimate covered its difference.
// 3. Unless --no-mc: generates ggx_dfg with --method mc --samples 1024 and
//    prints its wall time and largest difference to the same reference.
#include <algorithm>
#include <atomic>
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
#include "brdflut/ggx_integrals.h"
#include "brdflut/table.h"

using namespace brdflut;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// CPU time of the whole process (all threads), in seconds.
double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

struct Timed {
    Table table;
    double seconds;      // wall
    double cpu_seconds;  // all threads
};

Timed timed_generate(const std::string& id, Method method, long long samples, int threads) {
    const TableDefinition& def = find_table(id);
    TableSettings s = default_settings(def);
    s.method = method;
    s.samples = samples;
    GenerateOptions opt;
    opt.threads = threads;
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = cpu_seconds();
    Table t = generate(def, s, opt);
    const double wall = seconds_since(t0);
    return {std::move(t), wall, cpu_seconds() - c0};
}

// Runs body(k) for k in [0, n) on `threads` threads; each k writes its own slot.
template <class F>
void parallel_for_each(std::size_t n, int threads, F body) {
    std::atomic<std::size_t> next{0};
    std::vector<std::thread> pool;
    for (int i = 0; i < threads; ++i)
        pool.emplace_back([&] {
            for (std::size_t k; (k = next.fetch_add(1)) < n;) body(k);
        });
    for (auto& th : pool) th.join();
}

// Reference values of the texels sampled with `stride`, in the table's
// channel layout; unsampled texels are NaN.
std::vector<double> reference(const Table& t, double tol, int stride, int threads) {
    const Visibility vis = visibility_from_string(t.model.at("visibility").get<std::string>());
    const std::size_t nc = t.channels.size();
    std::vector<double> ref(t.values.size(), std::nan(""));
    std::vector<std::size_t> texels;
    for (std::size_t k = 0; k < t.texel_count(); ++k) {
        const int i = static_cast<int>(k % static_cast<std::size_t>(t.axes[0].count));
        const int j = static_cast<int>(k / static_cast<std::size_t>(t.axes[0].count));
        // Always include the last index of each axis (grazing, roughest).
        const bool ci = i % stride == 0 || i == t.axes[0].count - 1;
        const bool cj = t.axes.size() == 1 || j % stride == 0 || j == t.axes[1].count - 1;
        if (ci && cj) texels.push_back(k);
    }
    parallel_for_each(texels.size(), threads, [&](std::size_t n) {
        const std::size_t k = texels[n];
        const int i = static_cast<int>(k % static_cast<std::size_t>(t.axes[0].count));
        if (t.id == "ggx_albedo_avg") {
            ref[k] = ggx_albedo_average(t.axes[0].value(i), vis, tol).value[0];
            return;
        }
        const int j = static_cast<int>(k / static_cast<std::size_t>(t.axes[0].count));
        const Estimate<2> e = ggx_split_sum(t.axes[0].value(i), t.axes[1].value(j), vis, tol);
        if (nc == 2) {
            ref[k * 2] = e.value[0];
            ref[k * 2 + 1] = e.value[1];
        } else {
            ref[k] = e.value[0] + e.value[1];
        }
    });
    return ref;
}

struct Comparison {
    double max_diff = 0.0;         // computed (double) values
    double max_stored_diff = 0.0;  // values rounded to float
    double max_estimate = 0.0;     // largest per-value error estimate
    std::size_t compared = 0, uncovered = 0;  // estimate < difference
};

Comparison compare(const Table& t, const std::vector<double>& ref) {
    Comparison c;
    for (std::size_t n = 0; n < t.values.size(); ++n) {
        c.max_estimate = std::max(c.max_estimate, t.errors[n]);
        if (std::isnan(ref[n])) continue;
        const double d = std::abs(t.values[n] - ref[n]);
        c.max_diff = std::max(c.max_diff, d);
        c.max_stored_diff =
            std::max(c.max_stored_diff, std::abs(round_to_storage(t.values[n], PixelType::float32) - ref[n]));
        ++c.compared;
        if (d > t.errors[n] + 1e-15) ++c.uncovered;
    }
    return c;
}

}  // namespace

int main(int argc, char** argv) {
    double ref_tol = 1e-12;
    int stride = 1, threads = 0;
    bool mc = true;
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        auto next = [&]() -> const char* {
            if (a + 1 >= argc) {
                std::fprintf(stderr, "%s needs a value\n", arg.c_str());
                std::exit(2);
            }
            return argv[++a];
        };
        if (arg == "--reference-tol") ref_tol = std::atof(next());
        else if (arg == "--stride") stride = std::max(1, std::atoi(next()));
        else if (arg == "--threads") threads = std::max(0, std::atoi(next()));
        else if (arg == "--no-mc") mc = false;
        else {
            std::fprintf(stderr,
                         "usage: brdflut_table_report [--reference-tol T] [--stride S] "
                         "[--threads N] [--no-mc]\n");
            return 2;
        }
    }
    const int ref_threads =
        threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));

    std::printf("GGX tables at default settings, %s threads (hardware: %u)\n",
                threads > 0 ? std::to_string(threads).c_str() : "all",
                std::thread::hardware_concurrency());
    const char* ids[] = {"ggx_dfg", "ggx_albedo", "ggx_albedo_avg"};
    std::vector<Timed> runs;
    double total = 0.0, total_cpu = 0.0;
    for (const char* id : ids) {
        runs.push_back(timed_generate(id, Method::quadrature, 0, threads));
        total += runs.back().seconds;
        total_cpu += runs.back().cpu_seconds;
        std::printf("  generate %-15s %8.3f s wall %8.3f s cpu\n", id, runs.back().seconds,
                    runs.back().cpu_seconds);
    }
    std::printf("  generate all three      %8.3f s wall %8.3f s cpu\n\n", total, total_cpu);

    std::printf("Reference: the same integrals at abs tolerance %.0e, %s\n", ref_tol,
                stride == 1 ? "every texel"
                            : ("one texel in " + std::to_string(stride) + " per axis, and the last").c_str());
    std::printf("  %-15s %10s %12s %12s %12s %12s %10s\n", "table", "ref_time", "max|diff|",
                "stored|diff|", "error_bound", "max_estimate", "uncovered");
    std::vector<double> dfg_ref;
    for (const Timed& r : runs) {
        const auto t0 = std::chrono::steady_clock::now();
        std::vector<double> ref;
        if (r.table.id == "ggx_albedo" && !dfg_ref.empty()) {
            // E = A + B of the same reference split sums.
            ref.resize(dfg_ref.size() / 2);
            for (std::size_t k = 0; k < ref.size(); ++k) ref[k] = dfg_ref[2 * k] + dfg_ref[2 * k + 1];
        } else {
            ref = reference(r.table, ref_tol, stride, ref_threads);
        }
        const double ref_seconds = seconds_since(t0);
        const Comparison c = compare(r.table, ref);
        std::printf("  %-15s %9.1fs %12.3e %12.3e %12.3e %12.3e %5zu/%zu\n", r.table.id.c_str(),
                    ref_seconds, c.max_diff, c.max_stored_diff,
                    error_bound(r.table, PixelType::float32), c.max_estimate, c.uncovered, c.compared);
        if (r.table.id == "ggx_dfg") dfg_ref = ref;
    }

    if (mc) {
        const Timed m = timed_generate("ggx_dfg", Method::monte_carlo, 1024, threads);
        const Comparison c = compare(m.table, dfg_ref);
        std::printf("\nggx_dfg --method mc --samples 1024: %.3f s wall %.3f s cpu, max|diff| %.3e, "
                    "error_bound (4 standard errors + rounding) %.3e\n",
                    m.seconds, m.cpu_seconds, c.max_diff, error_bound(m.table, PixelType::float32));
    }
    return 0;
}
