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
#include "brdflut/verify.h"
#include "check/ltc_checks.h"

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
        const LtcLobe lobe = ltc_table_lobe(id, s.axes[0].value(ix), s.axes[1].value(iy));
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

void add_ltc_checks(std::map<std::string, std::vector<ClosedFormCheck>>& m) {
    using Result = std::pair<double, std::string>;
    m["ltc_2"] = {
        {"n0 at roughness 1 vs 1 - mu ln(1 + 1/mu) (height-correlated G2)", 1e-8,
         [](const TexelEvaluator& e) {
             Result r{0.0, ""};
             for (double mu : {0.05, 0.25, 0.5, 0.75, 1.0}) {
                 const double c[2] = {1.0, mu};
                 const double err = std::abs(e.evaluate(c, 0).value[0] - (1.0 - mu * std::log1p(1.0 / mu)));
                 if (err > r.first) r = {err, "at mu = " + std::to_string(mu)};
             }
             return r;
         }},
        {"sphere channel at len = 0 (cos_theta = 1) vs max(z, 0), z = 2 r - 1", 1e-15,
         [](const TexelEvaluator& e) {
             Result r{0.0, ""};
             for (double rough : {0.0, 0.3, 0.5, 0.8, 1.0}) {
                 const double c[2] = {rough, 1.0};
                 const double err = std::abs(e.evaluate(c, 0).value[3] - std::max(2.0 * rough - 1.0, 0.0));
                 if (err > r.first) r = {err, "at roughness = " + std::to_string(rough)};
             }
             return r;
         }},
    };
    m["ltc_eon_norm"] = {
        {"n0 vs 1 (EON conserves energy at rho = 1)", 1e-8,
         [](const TexelEvaluator& e) {
             Result r{0.0, ""};
             for (double sigma : {0.0, 0.3, 0.7, 1.0})
                 for (double mu : {1.0, 0.5, 0.05, 0.0}) {
                     const double c[2] = {sigma, mu};
                     const double err = std::abs(e.evaluate(c, 0).value[0] - 1.0);
                     if (err > r.first || r.second.empty())
                         r = {err, "at sigma = " + std::to_string(sigma) + ", mu = " + std::to_string(mu)};
                 }
             return r;
         }},
    };
    m["ltc_sheen_charlie_norm"] = {
        {"n0 at cos_theta = 1 vs 2^(1 - n/2) / (n + 2), n = 2 + 1/alpha", 1e-9,
         [](const TexelEvaluator& e) {
             Result r{0.0, ""};
             for (double rough : {0.2, 0.5, 0.8, 1.0}) {
                 const double c[2] = {rough, 1.0};
                 const double n = 2.0 + 1.0 / (rough * rough);
                 const double err = std::abs(e.evaluate(c, 0).value[0] - std::pow(2.0, 1.0 - 0.5 * n) / (n + 2.0));
                 if (err > r.first || r.second.empty()) r = {err, "at roughness = " + std::to_string(rough)};
             }
             return r;
         }},
    };
    // The fit at a spread of texels is a local minimum: no parameter moved
    // by 1e-3 (theta by 1e-3 of the lobe's width) lowers the objective. The
    // row is the relative drop (0 when none).
    auto local_minimum = [](const std::string& id) {
        return ClosedFormCheck{
            "fit is a local minimum of its objective (relative drop under perturbation)", 1e-9,
            [id](const TexelEvaluator& e) {
                Result r{0.0, ""};
                for (double rough : {0.1, 0.5, 0.9})
                    for (double mu : {1.0, 0.5, 0.05}) {
                        const double c[2] = {rough, mu};
                        const TexelValue v = e.evaluate(c, 0);
                        const LtcLobe lobe = ltc_table_lobe(id, rough, mu);
                        const LtcFit fit = fit_ltc(lobe);
                        // The table holds this fit.
                        const double drop =
                            std::max(std::abs(v.value[0] - fit.minv.a) + std::abs(v.value[3] - fit.minv.d),
                                     ltc_local_minimum_drop(lobe, fit));
                        if (drop > r.first || r.second.empty()) {
                            std::ostringstream s;
                            s << "at " << (id == "ltc_eon" ? "sigma " : "roughness ") << rough << ", mu " << mu;
                            r = {std::max(drop, 0.0), s.str()};
                        }
                    }
                return r;
            }};
    };
    // The light errors differ by the exact light's own error, at most the
    // metadata's tolerance per light (ltc_fit_options at default quality,
    // the quality metadata_maxima_error generates at).
    auto maxima = [](const std::string& id) {
        return ClosedFormCheck{"metadata error maxima (light, L3, below horizon) vs recomputation",
                               ltc_fit_options(1).light_tolerance,
                               [id](const TexelEvaluator&) { return metadata_maxima_error(id); }};
    };
    for (const char* id : {"ltc_1", "ltc_sheen_charlie", "ltc_eon"}) m[id] = {local_minimum(id), maxima(id)};
    m["hdrp_ltc_ggx"] = {maxima("hdrp_ltc_ggx")};
}

}  // namespace brdflut
