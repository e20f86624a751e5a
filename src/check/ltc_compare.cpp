// `compare` on an LTC matrix table: the light its matrices give for the
// bank of polygon lights against the exact light, next to a refit's.
#include <algorithm>

#include "brdflut/catalogue.h"
#include "brdflut/error.h"
#include "brdflut/exr.h"
#include "brdflut/generate.h"
#include "brdflut/ggx_integrals.h"
#include "brdflut/ltc.h"
#include "brdflut/ltc_compare.h"
#include "brdflut/ltc_fit.h"
#include "brdflut/ltc_report.h"
#include "brdflut/lut.h"
#include "tables/ltc_tables.h"

namespace brdflut {

bool is_ltc_matrix_table(const std::string& id) {
    for (const TableDefinition& d : catalogue())
        if (d.id == id) return d.shader_result == "ltc_inverse";
    return false;
}

Mat3 stored_ltc_inverse(const TableDefinition& def, const double* channels) {
    Mat3 m;
    for (std::size_t e = 0; e < 9; ++e) {
        const std::string& el = def.shader_matrix[e];
        const std::size_t letter = std::string("RGBA").find(el);
        m.m[e / 3][e % 3] = el.size() == 1 && letter != std::string::npos ? channels[letter] : std::stod(el);
    }
    return m;
}

namespace {
double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}
}  // namespace

LtcComparison compare_ltc_light(const ExrImage& img, const LutDescription& d, int threads) {
    const std::string& id = d.def->id;
    if (!is_ltc_matrix_table(id)) throw Error("table '" + id + "' is not an LTC matrix table");
    if (!d.settings.channel_map.empty())
        throw Error("the integrated-light comparison of '" + id + "' needs the table's own channels (no --channels)");
    const auto& axes = d.settings.axes;
    int ir = -1, imu = -1;
    for (std::size_t i = 0; i < axes.size(); ++i) {
        if (axes[i].name == d.def->axes[0].axis.name) ir = static_cast<int>(i);  // roughness (EON: sigma)
        if (axes[i].name == d.def->axes[1].axis.name) imu = static_cast<int>(i);  // the view cosine
    }
    if (ir < 0 || imu < 0 || axes.size() != 2)
        throw Error("an LTC table has the axes " + d.def->axes[0].axis.name + " and " + d.def->axes[1].axis.name);
    const std::size_t nc = img.channel_names.size();
    const std::size_t w = static_cast<std::size_t>(axes[0].count);
    const std::size_t n = w * static_cast<std::size_t>(axes[1].count);
    if (nc < 4 || img.pixels.size() < n * nc) throw Error("an LTC matrix table has 4 channels");
    LtcComparison out;
    out.texels = n;
    out.stored_light.assign(n, 0.0);
    out.refit_light.assign(n, 0.0);
    std::vector<double> below(n, 0.0);
    parallel_for_index(n, threads, [&](std::size_t k) {
        const int pos[2] = {static_cast<int>(k % w), static_cast<int>(k / w)};
        const double r = axes[static_cast<std::size_t>(ir)].value(pos[ir]);
        const double mu = axes[static_cast<std::size_t>(imu)].value(pos[imu]);
        const double* p = &img.pixels[k * nc];
        const Mat3 minv = stored_ltc_inverse(*d.def, p);
        const LtcLobe lobe = ltc_table_lobe(*d.def, r, mu, d.settings.params);  // as the table fits it
        const LtcFit fit = fit_ltc(lobe);
        const std::vector<LtcTexelReport> rep = ltc_texel_reports(lobe, {{minv, fit.n0}, {fit.minv.matrix(), fit.n0}});
        const LtcTexelReport& stored = rep[0];
        const LtcTexelReport& refit = rep[1];
        out.stored_light[k] = stored.light_max;
        out.refit_light[k] = refit.light_max;
        below[k] = stored.below_horizon;
    });
    for (std::size_t k = 0; k < n; ++k) {
        out.stored_light_max = std::max(out.stored_light_max, out.stored_light[k]);
        out.refit_light_max = std::max(out.refit_light_max, out.refit_light[k]);
        out.stored_below_horizon_max = std::max(out.stored_below_horizon_max, below[k]);
        if (out.refit_light[k] < out.stored_light[k] - 1e-6) ++out.refit_better;  // beyond rounding
    }
    out.stored_light_median = median(out.stored_light);
    out.refit_light_median = median(out.refit_light);
    return out;
}

}  // namespace brdflut
