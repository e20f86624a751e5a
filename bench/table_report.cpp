// Timed generation of every table of the catalogue at default settings, its
// largest error against a reference-quality run, peak memory, and ggx_dfg
// against Monte Carlo.
//
//   brdflut_table_report [--threads N] [--quality draft|default|reference]
//                        [--no-reference] [--no-mc] [--mc-samples M]
//                        [--tables ID,ID,...]   (only these; implies --no-mc)
//
// 1. Generates every table of the catalogue in catalogue order in one process
//    (as `brdflut generate --all` does; ggx_albedo reuses ggx_dfg's split sums)
//    and prints the wall and CPU time of each and of all, the integrand
//    evaluations per texel (tables that count them), and the peak resident
//    memory of the process at that point.
// 2. Unless --no-reference: generates every table again with --quality
//    reference (absolute tolerance 1e-12 or tighter, at least 100 times
//    tighter than the default) and prints, per table, the largest difference
//    of the computed values and of the stored float values to it, the
//    metadata `error_bound`, and how many values' own error estimates failed
//    to cover their difference. Closed-form tables are their own reference
//    (their accuracy is checked by the tests against independent quadrature).
//    Each table's figures are also printed as one line "table id=... key=value
//    ..." that bench/readme_figures.h renders into README.md.
// 3. Unless --no-mc: generates ggx_dfg with --method mc at 1024 samples per
//    texel and at M (default 16384) and compares both with the reference;
//    the error of the mean falls as 1/sqrt(N), so the samples needed for a
//    largest error of 1e-4 and their time are extrapolated from the M run.
#include <sys/resource.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "brdflut/catalogue.h"
#include "brdflut/generate.h"
#include "brdflut/table.h"

using namespace brdflut;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// CPU time of the whole process (all threads), in seconds.
double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// Peak resident memory of the process so far, in MB.
double peak_rss_mb() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_maxrss) / 1024.0;
}

struct Timed {
    Table table;
    double seconds;      // wall
    double cpu_seconds;  // all threads
};

Timed timed_generate(const std::string& id, Method method, Quality quality, long long samples,
                     int threads) {
    const TableDefinition& def = find_table(id);
    TableSettings s = default_settings(def);
    s.method = method;
    s.quality = quality;
    s.samples = samples;
    GenerateOptions opt;
    opt.threads = threads;
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = cpu_seconds();
    Table t = generate(def, s, opt);
    const double wall = seconds_since(t0);
    return {std::move(t), wall, cpu_seconds() - c0};
}

struct Comparison {
    double max_diff = 0.0;         // computed (double) values
    double max_stored_diff = 0.0;  // values rounded to float
    double max_estimate = 0.0;     // largest per-value error estimate
    std::size_t compared = 0, uncovered = 0;  // estimate < difference
};

Comparison compare(const Table& t, const Table& ref) {
    Comparison c;
    for (std::size_t n = 0; n < t.values.size(); ++n) {
        c.max_estimate = std::max(c.max_estimate, t.errors[n]);
        const double d = std::abs(t.values[n] - ref.values[n]);
        c.max_diff = std::max(c.max_diff, d);
        c.max_stored_diff = std::max(
            c.max_stored_diff, std::abs(round_to_storage(t.values[n], PixelType::float32) - ref.values[n]));
        ++c.compared;
        if (d > t.errors[n] + 1e-15) ++c.uncovered;
    }
    return c;
}

std::string method_name(const Table& t) { return t.method.value("name", std::string("?")); }

// Integrand evaluations per texel (0 for tables that do not count them, and
// for ggx_albedo when it reuses ggx_dfg's split sums).
double evaluations_per_texel(const Table& t) {
    return static_cast<double>(t.evaluations) / static_cast<double>(t.texel_count());
}

}  // namespace

int main(int argc, char** argv) {
    int threads = 0;
    long long mc_samples = 16384;
    bool no_mc = false, no_reference = false;
    std::string quality_name = "default";
    std::vector<std::string> tables;
    CLI::App app{"Every table of the catalogue at default settings: time, evaluations per texel and errors "
                 "against --quality reference",
                 "brdflut_table_report"};
    app.add_option("--threads", threads, "Worker threads; 0 uses every core")
        ->capture_default_str()
        ->check(CLI::Range(0, 1024));
    app.add_option("--quality", quality_name, "Quality of the runs measured: draft, default or reference")
        ->capture_default_str();
    app.add_flag("--no-reference", no_reference, "Skip the reference runs (no errors)");
    app.add_flag("--no-mc", no_mc, "Skip the Monte Carlo comparison of ggx_dfg");
    app.add_option("--mc-samples", mc_samples, "Samples per texel of the Monte Carlo comparison")
        ->capture_default_str()
        ->check(CLI::Range(1024LL, 1LL << 40));
    app.add_option("--tables", tables, "Only these tables (comma-separated ids); implies --no-mc")->delimiter(',');
    CLI11_PARSE(app, argc, argv);
    Quality quality;
    try {
        quality = quality_from_string(quality_name);
        for (const std::string& id : tables) find_table(id);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 2;
    }
    const std::set<std::string> only(tables.begin(), tables.end());
    bool mc = !no_mc && only.empty(), with_reference = !no_reference;
    if (mc) with_reference = true;  // the Monte Carlo errors need the reference

    std::printf("Every table at %s quality, %s threads (hardware: %u)\n",
                std::string(to_string(quality)).c_str(),
                threads > 0 ? std::to_string(threads).c_str() : "all",
                std::thread::hardware_concurrency());
    std::vector<Timed> runs;
    double total = 0.0, total_cpu = 0.0;
    const auto t_all = std::chrono::steady_clock::now();
    for (const TableDefinition& d : catalogue()) {
        if (!only.empty() && !only.count(d.id)) continue;
        runs.push_back(timed_generate(d.id, Method::quadrature, quality, 0, threads));
        total += runs.back().seconds;
        total_cpu += runs.back().cpu_seconds;
        std::printf("  generate %-30s %8.3f s wall %8.3f s cpu %10.0f evaluations per texel\n", d.id.c_str(),
                    runs.back().seconds, runs.back().cpu_seconds, evaluations_per_texel(runs.back().table));
    }
    std::printf("  generate all %-2zu tables             %8.3f s wall %8.3f s cpu (%.3f s wall "
                "with bookkeeping)\n",
                runs.size(), total, total_cpu, seconds_since(t_all));
    std::printf("  peak resident memory so far: %.1f MB\n\n", peak_rss_mb());
    if (!with_reference) return 0;

    std::printf("Reference: every table at quality reference, every texel\n");
    std::printf("  %-30s %-12s %9s %10s %12s %12s %12s %12s %12s\n", "table", "method", "ref_wall",
                "ref_tol", "max|diff|", "stored|diff|", "error_bound", "max_estimate", "uncovered");
    std::map<std::string, Table> references;
    for (const Timed& r : runs) {
        const Timed ref = timed_generate(r.table.id, Method::quadrature, Quality::reference, 0, threads);
        const Comparison c = compare(r.table, ref.table);
        const double ref_tol = ref.table.method.value("abs_tolerance", 0.0);
        std::printf("  %-30s %-12s %8.2fs %10.0e %12.3e %12.3e %12.3e %12.3e %6zu/%zu\n",
                    r.table.id.c_str(), method_name(r.table).c_str(), ref.seconds, ref_tol, c.max_diff,
                    c.max_stored_diff, error_bound(r.table, PixelType::float32), c.max_estimate,
                    c.uncovered, c.compared);
        references.emplace(r.table.id, ref.table);
        // The same as one machine-readable line (bench/readme_figures.h).
        std::printf("table id=%s threads=%s wall_s=%.4f cpu_s=%.4f evaluations_per_texel=%.0f "
                    "max_error_stored=%.3e max_error=%.3e error_bound=%.3e uncovered=%zu\n",
                    r.table.id.c_str(), threads > 0 ? std::to_string(threads).c_str() : "all", r.seconds,
                    r.cpu_seconds, evaluations_per_texel(r.table), c.max_stored_diff, c.max_diff,
                    error_bound(r.table, PixelType::float32), c.uncovered);
    }

    if (mc) {
        const Table& ref = references.at("ggx_dfg");
        const Timed& quad = *std::find_if(runs.begin(), runs.end(),
                                          [](const Timed& t) { return t.table.id == "ggx_dfg"; });
        const Comparison cq = compare(quad.table, ref);
        std::printf("\nggx_dfg 128x128 against the reference:\n");
        std::printf("  %-28s %10s %10s %12s %12s\n", "run", "wall", "cpu", "max|diff|", "stored|diff|");
        std::printf("  %-28s %9.3fs %9.3fs %12.3e %12.3e\n", "quadrature (default)", quad.seconds,
                    quad.cpu_seconds, cq.max_diff, cq.max_stored_diff);
        std::vector<std::pair<long long, Timed>> mcs;
        for (long long n : {1024LL, mc_samples}) {
            if (!mcs.empty() && n == mcs.back().first) break;
            mcs.emplace_back(n, timed_generate("ggx_dfg", Method::monte_carlo, quality, n, threads));
            const Comparison c = compare(mcs.back().second.table, ref);
            std::printf("  %-28s %9.3fs %9.3fs %12.3e %12.3e\n",
                        ("mc, " + std::to_string(n) + " samples").c_str(), mcs.back().second.seconds,
                        mcs.back().second.cpu_seconds, c.max_diff, c.max_stored_diff);
        }
        const Timed& m1 = mcs.front().second;
        const double e1 = compare(m1.table, ref).max_diff;
        const auto& [n_big, m_big] = mcs.back();
        const double e_big = compare(m_big.table, ref).max_diff;
        const double n_needed = static_cast<double>(n_big) * (e_big / 1e-4) * (e_big / 1e-4);
        const double scale = n_needed / static_cast<double>(n_big);
        std::printf("  %-28s %9.0fs %9.0fs %12.1e %12s   (extrapolated from the %lld-sample run: "
                    "N = %.2e)\n",
                    "mc, error 1e-4", m_big.seconds * scale, m_big.cpu_seconds * scale, 1e-4, "",
                    n_big, n_needed);
        std::printf("  ratios quadrature / mc 1024: wall %.3f, cpu %.3f, error %.2e\n",
                    quad.seconds / m1.seconds, quad.cpu_seconds / m1.cpu_seconds, cq.max_diff / e1);
        std::printf("  ratios quadrature / mc 1e-4: wall %.2e, cpu %.2e\n",
                    quad.seconds / (m_big.seconds * scale), quad.cpu_seconds / (m_big.cpu_seconds * scale));
    }
    return 0;
}
