// The sheen tables: the time of the whole sheen set (every catalogue table
// of a sheen or cloth model, default settings, 2 threads, in catalogue order
// after one clear_shared_results(), as one `brdflut generate` of them all
// runs them: an error table takes its lobe's fits from its matrix table),
// and the verdict on Cycles' table_sheen_ltc
// (tests/fixtures/cycles/shader_gen_schlick.tables): its albedo plane
// against the layer's albedo (every order, R) and the talk's cut walk
// (R16), and every fitted texel's integrated-light error on the layer's BRDF
// (SheenVolumeLobe; the error report's polygon lights, ltc_report.h, at the
// draft light tolerance), for Cycles' fit as shipped (its own magnitude),
// for its matrices with the layer's albedo, and for brdflut's
// cycles_sheen_ltc.
//
//   brdflut_sheen_report [--no-timing]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "bench_util.h"
#include "brdflut/catalogue.h"
#include "brdflut/formats.h"
#include "brdflut/generate.h"
#include "brdflut/ltc_fit.h"
#include "brdflut/ltc_report.h"
#include "brdflut/sheen_volume.h"

using namespace brdflut;
using brdflut::bench::cpu_seconds;
using brdflut::bench::load_average;
using brdflut::bench::quantile;

namespace {
bool in_sheen_set(const TableDefinition& d) {
    for (const char* f : {"sheen", "cloth", "sheen_charlie", "sheen_zeltner", "sheen_volume"})
        if (d.family == f) return true;
    for (const char* w : {"sheen", "charlie", "cloth"})
        if (d.id.find(w) != std::string::npos) return true;
    return false;
}
// Cycles' table_sheen_ltc, its three planes read interleaved: (A, B, R) per
// texel, cos(theta) fastest.
std::vector<double> cycles_sheen_ltc() {
    ReadOptions opt;
    opt.array = "table_sheen_ltc";
    opt.shape = parse_array_shape("32x32:3p");
    return read_table_image(std::string(BRDFLUT_SOURCE_DIR) + "/tests/fixtures/cycles/shader_gen_schlick.tables", opt)
        .pixels;
}
}  // namespace

int main(int argc, char** argv) {
    const bool timing = !(argc > 1 && std::string(argv[1]) == "--no-timing");
    std::printf("load average before: %s\n", load_average().c_str());
    Table ltc;
    const TableDefinition& ltc_def = find_table("cycles_sheen_ltc");
    if (timing) {
        double total_wall = 0.0, total_cpu = 0.0;
        clear_shared_results();
        for (const TableDefinition& d : catalogue()) {
            if (!in_sheen_set(d)) continue;
            GenerateOptions o;
            o.threads = 2;
            const double c0 = cpu_seconds();
            const auto w0 = std::chrono::steady_clock::now();
            const Table t = generate(d, default_settings(d), o);
            const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
            const double cpu = cpu_seconds() - c0;
            total_wall += wall;
            total_cpu += cpu;
            std::printf("  %-32s %s: wall %7.2f s, CPU %7.2f s\n", d.id.c_str(), d.preset.empty() ? "default" : d.preset.c_str(),
                        wall, cpu);
            if (d.id == "cycles_sheen_ltc") ltc = t;
        }
        std::printf("sheen set, 2 threads: wall %.1f s, CPU %.1f s\n", total_wall, total_cpu);
        std::printf("load average after: %s\n", load_average().c_str());
    } else {
        ltc = generate(ltc_def, default_settings(ltc_def));
    }

    const std::vector<double> cycles = cycles_sheen_ltc();
    if (cycles.size() != 3072u) {
        std::fprintf(stderr, "cannot read Cycles' table_sheen_ltc from tests/fixtures/cycles\n");
        return 1;
    }
    // The albedo plane: against R16 (the talk's walk, 2e6 walks a texel,
    // rounded to 5 decimals) and R (the layer).
    const TableDefinition& albedo_def = find_table("sheen_volume_albedo");
    TableSettings as = default_settings(albedo_def);
    for (Axis& a : as.axes) {
        a.count = 32;
        a.placement = Placement::endpoints;
        a.clamp_lo = 0.01;
        a.clamp_hi = 1.0;
    }
    const Table albedo = generate(albedo_def, as);
    double z2 = 0.0, zmax = 0.0, ratio_max = 0.0, diff_max = 0.0;
    std::size_t zmax_at = 0, ratio_at = 0, diff_at = 0, beyond3 = 0;
    for (std::size_t k = 0; k < 1024; ++k) {
        const double shipped = cycles[3 * k + 2], r = albedo.at(k, 0), r16 = albedo.at(k, 1);
        const double noise = std::sqrt(r16 * (1.0 - r16) / 2e6 + 5e-6 * 5e-6 / 3.0);
        const double z = (shipped - r16) / noise;
        z2 += z * z;
        beyond3 += std::abs(z) > 3.0;
        if (std::abs(z) > zmax) {
            zmax = std::abs(z);
            zmax_at = k;
        }
        if (shipped > 1e-3 && r / shipped > ratio_max) {
            ratio_max = r / shipped;
            ratio_at = k;
        }
        if (r - shipped > diff_max) {
            diff_max = r - shipped;
            diff_at = k;
        }
    }
    auto where = [](std::size_t k) {
        char buf[96];
        std::snprintf(buf, sizeof buf, "mu = %.4g, alpha = %.4g", std::max(0.01, static_cast<double>(k % 32) / 31.0),
                      std::max(0.01, static_cast<double>(k / 32) / 31.0));
        return std::string(buf);
    };
    std::printf("Cycles' R plane vs R16: mean z^2 %.3f over 1024 texels, |z| > 3 at %zu, largest |z| %.2f (%s)\n",
                z2 / 1024.0, beyond3, zmax, where(zmax_at).c_str());
    std::printf("Cycles' R plane vs the layer's R: largest R - shipped %.4f (%s: R %.4f, shipped %.4f); largest ratio "
                "R / shipped (shipped > 1e-3) %.2f (%s)\n",
                diff_max, where(diff_at).c_str(), albedo.at(diff_at, 0), cycles[3 * diff_at + 2], ratio_max,
                where(ratio_at).c_str());

    // The fits, on the layer's BRDF.
    std::vector<std::size_t> fitted;
    for (std::size_t k = 0; k < 1024; ++k)
        if (cycles[3 * k] != 0.0) fitted.push_back(k);
    std::vector<double> shipped(fitted.size()), shape(fitted.size()), ours(fitted.size());
    std::vector<std::shared_ptr<const SheenVolumeLobe>> lobes(32);
    parallel_for_index(32, 2, [&](std::size_t j) {
        lobes[j] = std::make_shared<const SheenVolumeLobe>(std::max(0.01, static_cast<double>(j) / 31.0));
    });
    const auto w0 = std::chrono::steady_clock::now();
    parallel_for_index(fitted.size(), 2, [&](std::size_t n) {
        const std::size_t k = fitted[n], i = k % 32, j = k / 32;
        const double mu = std::max(0.01, static_cast<double>(i) / 31.0), alpha = std::max(0.01, static_cast<double>(j) / 31.0);
        LtcLobe l(lobes[j], mu, alpha, 1, 1e-7);
        l.known_n0 = albedo.at(k, 2) + lobes[j]->multiple_scattering_albedo(mu);
        const Mat3 talk{{{{cycles[3 * k], 0.0, cycles[3 * k + 1]}, {0.0, cycles[3 * k], 0.0}, {0.0, 0.0, 1.0}}}};
        const Mat3 mine{{{{ltc.at(k, 0), 0.0, ltc.at(k, 1)}, {0.0, ltc.at(k, 0), 0.0}, {0.0, 0.0, 1.0}}}};
        // Both fits with the layer's albedo, and Cycles' as shipped.
        const auto rep =
            ltc_texel_reports(l, {{talk, cycles[3 * k + 2]}, {talk, albedo.at(k, 0)}, {mine, albedo.at(k, 0)}}, ltc_fit_options(0));
        shipped[n] = rep[0].light_max;
        shape[n] = rep[1].light_max;
        ours[n] = rep[2].light_max;
    });
    std::size_t lower = 0, lower_shape = 0;
    for (std::size_t n = 0; n < fitted.size(); ++n) {
        lower += ours[n] < shipped[n];
        lower_shape += ours[n] < shape[n];
    }
    std::printf("integrated-light error on the layer's BRDF (fraction of its albedo), %zu fitted texels (%.0f s):\n",
                fitted.size(), std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count());
    std::printf("  %-36s median %.4f, 90th percentile %.4f, worst %.4f\n", "Cycles as shipped (its R plane)",
                quantile(shipped, 0.5), quantile(shipped, 0.9), quantile(shipped, 1.0));
    std::printf("  %-36s median %.4f, 90th percentile %.4f, worst %.4f\n", "Cycles' matrices, the layer's albedo",
                quantile(shape, 0.5), quantile(shape, 0.9), quantile(shape, 1.0));
    std::printf("  %-36s median %.4f, 90th percentile %.4f, worst %.4f\n", "brdflut's matrices, the layer's albedo", quantile(ours, 0.5),
                quantile(ours, 0.9), quantile(ours, 1.0));
    std::printf("  brdflut lower than Cycles as shipped at %zu, than its matrices with the layer's albedo at %zu\n", lower,
                lower_shape);
    return 0;
}
