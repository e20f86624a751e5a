// verify's checks of the LTC tables: the norms and the sphere channel
// against closed forms, each fit against its own objective, and the error
// maxima in the matrix tables' metadata against a recomputation.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "brdflut/catalogue.h"
#include "brdflut/generate.h"
#include "brdflut/ggx_integrals.h"
#include "brdflut/ltc.h"
#include "brdflut/ltc_compare.h"
#include "brdflut/ltc_fit.h"
#include "brdflut/ltc_report.h"
#include "brdflut/verify.h"
#include "check/ltc_checks.h"
#include "tables/ltc_tables.h"

namespace brdflut {

namespace {
// Generates the matrix table `id` on a 5x4 grid and recomputes each texel's
// error report from the stored matrix, with the exact light at a tolerance
// 1000 times finer than the metadata's: the row is the largest difference
// between the metadata's maxima (light error, relative L3 error, mass below
// the horizon) and the recomputed ones.
std::pair<double, std::string> metadata_maxima_error(const std::string& id) {
    const TableDefinition& def = find_table(id);
    TableSettings s = default_settings(def);
    s.axes[0].count = 5;
    s.axes[1].count = 4;
    const Table t = generate(def, s);
    const nlohmann::json& fe = t.method.at("fit_error");
    LtcFitOptions fine;
    fine.light_tolerance = 1e-3 * fe.at("light_tolerance").get<double>();
    double light = 0.0, l3 = 0.0, below = 0.0;
    for (std::size_t k = 0; k < t.texel_count(); ++k) {
        const int ix = static_cast<int>(k % 5), iy = static_cast<int>(k / 5);
        const LtcLobe lobe = ltc_table_lobe(def, s.axes[0].value(ix), s.axes[1].value(iy));
        const double v[4] = {t.at(k, 0), t.at(k, 1), t.at(k, 2), t.at(k, 3)};
        // The matrix by the table's packing, as a shader unpacks it.
        const Mat3 minv = stored_ltc_inverse(def, v);
        const LtcTexelReport rep = ltc_texel_report(lobe, minv, ltc_norms(lobe).n0, fine);
        light = std::max(light, rep.light_max);
        l3 = std::max(l3, rep.relative_l3);
        below = std::max(below, rep.below_horizon);
    }
    const double d[3] = {std::abs(fe.at("light_error_max").get<double>() - light),
                         std::abs(fe.at("relative_l3_max").get<double>() - l3),
                         std::abs(fe.at("below_horizon_max").get<double>() - below)};
    const char* names[3] = {"light_error_max", "relative_l3_max", "below_horizon_max"};
    const int w = static_cast<int>(std::max_element(d, d + 3) - d);
    std::ostringstream where;
    where << names[w] << " " << fe.at(names[w]).get<double>() << " against " << (w == 0 ? light : w == 1 ? l3 : below)
          << " recomputed (5x4 grid)";
    return {d[w], where.str()};
}
}  // namespace

// The fit at a spread of texels is a local minimum: no parameter moved by
// 1e-3 (theta by 1e-3 of the lobe's width) lowers the objective. The row is
// the relative drop (0 when none).
ClosedFormCheck ltc_local_minimum_check(const std::string& id, const std::string& parameter) {
    return ClosedFormCheck{
        "fit is a local minimum of its objective (relative drop under perturbation)", 1e-9,
        [id, parameter](const TexelEvaluator& e) {
            const TableDefinition& def = find_table(id);
            std::pair<double, std::string> r{0.0, ""};
            for (double rough : {0.1, 0.5, 0.9})
                for (double mu : {1.0, 0.5, 0.05}) {
                    const double c[2] = {rough, mu};
                    const TexelValue v = e.evaluate(c, 0);
                    const LtcLobe lobe = ltc_table_lobe(def, rough, mu);
                    const LtcFit fit = fit_ltc(lobe);
                    // The table holds this fit: its matrix, unpacked as a
                    // shader unpacks it and scaled to a middle element of 1,
                    // is the fit's.
                    const Mat3 stored = stored_ltc_inverse(def, v.value.data());
                    const Mat3 want = fit.minv.matrix();
                    double held = 0.0;
                    for (int i = 0; i < 3; ++i)
                        for (int j = 0; j < 3; ++j)
                            held += std::abs(stored.m[i][j] / stored.m[1][1] - want.m[i][j]);
                    if (!std::isfinite(held)) held = HUGE_VAL;
                    const double drop = std::max(held, ltc_local_minimum_drop(lobe, fit));
                    if (drop > r.first || r.second.empty()) {
                        std::ostringstream s;
                        s << "at " << parameter << " " << rough << ", mu " << mu;
                        r = {std::max(drop, 0.0), s.str()};
                    }
                }
            return r;
        }};
}

// The light errors differ by the exact light's own error, at most the
// metadata's tolerance per light (ltc_fit_options at default quality, the
// quality metadata_maxima_error generates at).
ClosedFormCheck ltc_metadata_maxima_check(const std::string& id) {
    return ClosedFormCheck{"metadata error maxima (light, L3, below horizon) vs recomputation",
                           ltc_fit_options(1).light_tolerance,
                           [id](const TexelEvaluator&) { return metadata_maxima_error(id); }};
}

// An error report table's light errors at a spread of texels against the
// report of the same fit with every exact light taken 1000 times finer: they
// differ by the coarse lights' errors, at most the tolerance per light.
ClosedFormCheck ltc_report_check(const std::string& id, const std::string& parameter) {
    const LtcFitOptions opt = ltc_fit_options(1);
    return ClosedFormCheck{
        "light errors (largest, mean) vs the report with the exact light 1000 times finer", opt.light_tolerance,
        [id, parameter, opt](const TexelEvaluator& e) {
            LtcFitOptions fine = opt;
            fine.light_tolerance = 1e-3 * opt.light_tolerance;
            const TableDefinition& def = find_table(id);
            std::pair<double, std::string> r{0.0, ""};
            for (double rough : {0.2, 0.8})
                for (double mu : {0.9, 0.1}) {
                    const double c[2] = {rough, mu};
                    const TexelValue v = e.evaluate(c, 0);
                    const LtcLobe lobe = ltc_table_lobe(def, rough, mu);
                    const LtcFit fit = fit_ltc(lobe, opt);
                    const LtcTexelReport rep = ltc_texel_report(lobe, fit.minv.matrix(), fit.n0, fine);
                    const double d = std::max(std::abs(v.value[2] - rep.light_max), std::abs(v.value[3] - rep.light_mean));
                    if (!std::isfinite(d)) return std::pair<double, std::string>{HUGE_VAL, "not finite"};
                    if (d > r.first || r.second.empty()) {
                        std::ostringstream s;
                        s << "at " << parameter << " " << rough << ", mu " << mu;
                        r = {d, s.str()};
                    }
                }
            return r;
        }};
}

}  // namespace brdflut
