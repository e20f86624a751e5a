// The 64x64 GGX LTC fit with its per-texel error report (ltc_1 and
// ltc_ggx_error at default quality, generated one after the other as
// `brdflut generate ltc_1 ltc_ggx_error` does, the second taking the fits
// and reports from the first): wall and CPU time at 1 and 2 threads, and
// every texel's integrated-light error against Heitz's
// published table (the three.js copy in tests/fixtures/ltc), as shipped (its
// own n0) and with the exact n0 (its matrices against the refit's), and the
// load average, since the machine may be shared.
//
//   brdflut_ltc_report [FIXTURE_DIR]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <string>
#include <vector>

#include "bench_util.h"
#include "brdflut/catalogue.h"
#include "brdflut/generate.h"
#include "brdflut/ltc.h"
#include "brdflut/ltc_fit.h"
#include "brdflut/ltc_report.h"

using namespace brdflut;
using brdflut::bench::cpu_seconds;
using brdflut::bench::load_average;
using brdflut::bench::quantile;

namespace {
std::vector<double> read_numbers(const std::string& path) {
    std::ifstream in(path);
    std::vector<double> v;
    double x;
    while (in >> x) v.push_back(x);
    return v;
}
}  // namespace

int main(int argc, char** argv) {
    const std::string dir = argc > 1 ? argv[1] : std::string(BRDFLUT_SOURCE_DIR) + "/tests/fixtures/ltc";
    const TableDefinition& def = find_table("ltc_1");
    const TableDefinition& report_def = find_table("ltc_ggx_error");
    const TableSettings s = default_settings(def);
    Table t, report;
    std::printf("load average before: %s\n", load_average().c_str());
    for (int threads : {1, 2}) {
        GenerateOptions o;
        o.threads = threads;
        clear_shared_results();  // every run fits every texel
        const double c0 = cpu_seconds();
        const auto w0 = std::chrono::steady_clock::now();
        t = generate(def, s, o);
        const auto w1 = std::chrono::steady_clock::now();
        report = generate(report_def, default_settings(report_def), o);
        const auto w2 = std::chrono::steady_clock::now();
        const double wall = std::chrono::duration<double>(w2 - w0).count();
        std::printf("ltc_1 + ltc_ggx_error 64x64, %d thread(s): wall %.2f s (ltc_1 %.2f s, ltc_ggx_error %.2f s), "
                    "CPU %.2f s\n",
                    threads, wall, std::chrono::duration<double>(w1 - w0).count(),
                    std::chrono::duration<double>(w2 - w1).count(), cpu_seconds() - c0);
    }
    std::printf("load average after the fits: %s\n", load_average().c_str());
    const nlohmann::json& fe = t.method["fit_error"];
    std::printf("fit objective: max %.4g, median %.4g; LTC mass below the horizon: max %.4g\n",
                fe["objective_max"].get<double>(), fe["objective_median"].get<double>(),
                fe["below_horizon_max"].get<double>());
    std::printf("metadata (exact light to %.0e of n0): light error max %.4g, median %.4g; relative L3 max %.4g, "
                "median %.4g\n",
                fe["light_tolerance"].get<double>(), fe["light_error_max"].get<double>(),
                fe["light_error_median"].get<double>(), fe["relative_l3_max"].get<double>(),
                fe["relative_l3_median"].get<double>());

    const std::vector<double> t1 = read_numbers(dir + "/three_ltc_1.txt");
    const std::vector<double> t2 = read_numbers(dir + "/three_ltc_2.txt");
    if (t1.size() != 64u * 64u * 4u || t2.size() != t1.size()) {
        std::fprintf(stderr, "cannot read the fixture in %s\n", dir.c_str());
        return 1;
    }
    const std::size_t n = 64 * 64;
    std::vector<double> mine(n), heitz(n), heitz_exact(n), mine_l3(n), heitz_l3(n), grazing_mine, grazing_heitz;
    const auto w0 = std::chrono::steady_clock::now();
    parallel_for_index(n, 0, [&](std::size_t k) {
        const int a = static_cast<int>(k % 64), row = static_cast<int>(k / 64);
        const double r = s.axes[0].value(a), mu = s.axes[1].value(row), alpha = alpha_from_perceptual(r);
        const LtcInverse pub{t1[4 * k], t1[4 * k + 2], t1[4 * k + 1], t1[4 * k + 3]};
        const LtcLobe lobe(mu, alpha, Visibility::height_correlated);
        const double n0 = ltc_norms(lobe).n0;
        const std::vector<LtcTexelReport> rep = ltc_texel_reports(lobe, {{pub.matrix(), t2[4 * k]}, {pub.matrix(), n0}});
        const LtcTexelReport& rh = rep[0];
        const LtcTexelReport& rx = rep[1];
        mine[k] = report.at(k, 2);  // the refit's report, as ltc_ggx_error stores it
        mine_l3[k] = report.at(k, 0);
        heitz[k] = rh.light_max;
        heitz_exact[k] = rx.light_max;
        heitz_l3[k] = rh.relative_l3;
    });
    std::size_t better = 0, much_worse = 0, much_worse_1e2 = 0, better_exact = 0, much_worse_exact = 0;
    double worst_ratio = 0.0, worst_excess = 0.0;
    std::size_t worst_at = 0, excess_at = 0, excess_1e2 = 0, excess_5e2 = 0;
    for (std::size_t k = 0; k < n; ++k) {
        better += mine[k] < heitz[k];
        const double ratio = mine[k] / std::max(heitz[k], 1e-3);
        if (ratio > 2.0) ++much_worse;
        if (mine[k] > 2.0 * std::max(heitz[k], 1e-2)) ++much_worse_1e2;
        better_exact += mine[k] < heitz_exact[k];
        if (mine[k] > 2.0 * std::max(heitz_exact[k], 1e-3)) ++much_worse_exact;
        if (ratio > worst_ratio) {
            worst_ratio = ratio;
            worst_at = k;
        }
        excess_1e2 += mine[k] - heitz[k] > 1e-2;
        excess_5e2 += mine[k] - heitz[k] > 5e-2;
        if (mine[k] - heitz[k] > worst_excess) {
            worst_excess = mine[k] - heitz[k];
            excess_at = k;
        }
        if (k / 64 >= 56) {
            grazing_mine.push_back(mine[k]);
            grazing_heitz.push_back(heitz[k]);
        }
    }
    std::printf("error report: %.1f s wall\n",
                std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count());
    std::printf("integrated-light error (max over the bank, fraction of n0):\n");
    std::printf("  refit:  median %.4g, 90%% %.4g, worst %.4g\n", quantile(mine, 0.5), quantile(mine, 0.9),
                quantile(mine, 1.0));
    std::printf("  Heitz:  median %.4g, 90%% %.4g, worst %.4g\n", quantile(heitz, 0.5), quantile(heitz, 0.9),
                quantile(heitz, 1.0));
    std::printf("  grazing rows (sqrt(1 - cos) >= 56/63): refit median %.4g worst %.4g; Heitz median %.4g worst %.4g\n",
                quantile(grazing_mine, 0.5), quantile(grazing_mine, 1.0), quantile(grazing_heitz, 0.5),
                quantile(grazing_heitz, 1.0));
    std::printf("  refit lower at %zu of %zu texels; more than twice Heitz's (floor 1e-3) at %zu; "
                "worst ratio %.3g at roughness index %zu, row %zu (refit %.4g, Heitz %.4g)\n",
                better, n, much_worse, worst_ratio, worst_at % 64, worst_at / 64, mine[worst_at], heitz[worst_at]);
    std::printf("  more than twice Heitz's with a floor of 1e-2: %zu texels\n", much_worse_1e2);
    std::printf("  above Heitz's by more than 0.01 of n0 (roughness index, row: refit, Heitz):");
    for (std::size_t k = 0; k < n; ++k)
        if (mine[k] - heitz[k] > 1e-2) std::printf(" (%zu, %zu: %.3g, %.3g)", k % 64, k / 64, mine[k], heitz[k]);
    std::printf("\n");
    std::printf("  more than twice Heitz's (floor 1e-3), texels per row (row: count):");
    for (std::size_t row = 0; row < 64; ++row) {
        std::size_t c = 0;
        for (std::size_t a = 0; a < 64; ++a) {
            const std::size_t k = 64 * row + a;
            c += mine[k] / std::max(heitz[k], 1e-3) > 2.0;
        }
        if (c > 0) std::printf(" %zu: %zu", row, c);
    }
    std::printf("\n");
    std::printf("  refit error above Heitz's by more than 0.01 of n0 at %zu texels, by more than 0.05 at %zu; "
                "largest excess %.4g at roughness index %zu, row %zu (refit %.4g, Heitz %.4g)\n",
                excess_1e2, excess_5e2, worst_excess, excess_at % 64, excess_at / 64, mine[excess_at], heitz[excess_at]);
    std::printf("  Heitz's matrices with the exact n0: median %.4g, worst %.4g; refit lower at %zu, "
                "more than twice (floor 1e-3) at %zu\n",
                quantile(heitz_exact, 0.5), quantile(heitz_exact, 1.0), better_exact, much_worse_exact);
    std::printf("relative L3 error of the lobe: refit median %.4g worst %.4g; Heitz median %.4g worst %.4g\n",
                quantile(mine_l3, 0.5), quantile(mine_l3, 1.0), quantile(heitz_l3, 0.5), quantile(heitz_l3, 1.0));
    std::printf("load average at the end: %s\n", load_average().c_str());
    return 0;
}
