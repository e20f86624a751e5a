// Closed-form checks of the catalogue's tables (see the field notes of each
// model for the derivations). Each evaluates the table's own evaluator.
#include <array>
#include <cmath>
#include <map>
#include <sstream>

#include "brdflut/verify.h"

namespace brdflut {
namespace {

using Result = std::pair<double, std::string>;

// Largest |evaluate(coords)[channel] - expected| over a list of points.
template <class Points, class Expected>
Result worst_over(const TexelEvaluator& e, const Points& points, int channel, Expected expected) {
    Result r{0.0, ""};
    for (const auto& p : points) {
        const TexelValue v = e.evaluate(p.data(), 0);
        const double err = std::abs(v.value[static_cast<std::size_t>(channel)] - expected(p));
        if (err > r.first || !std::isfinite(err)) {
            std::ostringstream s;
            s.precision(6);
            for (std::size_t i = 0; i < p.size(); ++i) s << (i ? ", " : "") << p[i];
            r = {err, "at (" + s.str() + ")"};
        }
    }
    return r;
}

std::vector<std::array<double, 2>> mu_points(double alpha) {
    std::vector<std::array<double, 2>> pts;
    for (double mu : {0.5 / 128, 0.01, 0.05, 0.1, 0.25, 0.5, 0.75, 0.9, 1.0}) pts.push_back({mu, alpha});
    return pts;
}

// alpha = 1, height-correlated G2: f = 1 / (2 pi (mu_o + mu_i)), so
// E(mu) = 1 - mu ln(1 + 1/mu).
double ggx_albedo_alpha_one(double mu) { return 1.0 - mu * std::log1p(1.0 / mu); }

std::map<std::string, std::vector<ClosedFormCheck>> build() {
    std::map<std::string, std::vector<ClosedFormCheck>> m;
    m["ggx_dfg"] = {
        {"A + B at alpha = 1 vs 1 - mu ln(1 + 1/mu)", 1e-8,
         [](const TexelEvaluator& e) {
             Result r{0.0, ""};
             for (const auto& p : mu_points(1.0)) {
                 const TexelValue v = e.evaluate(p.data(), 0);
                 const double err = std::abs(v.value[0] + v.value[1] - ggx_albedo_alpha_one(p[0]));
                 if (err > r.first) r = {err, "at mu = " + std::to_string(p[0])};
             }
             return r;
         }},
        {"B at alpha = 1e-8 vs mirror limit (1 - mu)^5", 1e-6,
         [](const TexelEvaluator& e) {
             std::vector<std::array<double, 2>> pts;
             for (double mu : {0.1, 0.3, 0.6, 1.0}) pts.push_back({mu, 1e-8});
             return worst_over(e, pts, 1, [](const auto& p) { return std::pow(1.0 - p[0], 5); });
         }},
    };
    m["ggx_albedo"] = {
        {"E at alpha = 1 vs 1 - mu ln(1 + 1/mu)", 1e-8,
         [](const TexelEvaluator& e) {
             return worst_over(e, mu_points(1.0), 0, [](const auto& p) { return ggx_albedo_alpha_one(p[0]); });
         }},
        {"E at alpha = 1e-8 vs mirror limit 1", 1e-6,
         [](const TexelEvaluator& e) {
             std::vector<std::array<double, 2>> pts;
             for (double mu : {0.1, 0.3, 0.6, 1.0}) pts.push_back({mu, 1e-8});
             return worst_over(e, pts, 0, [](const auto&) { return 1.0; });
         }},
    };
    m["ggx_albedo_avg"] = {
        {"E_avg at alpha = 1 vs (4/3)(1 - ln 2)", 1e-8,
         [](const TexelEvaluator& e) {
             const std::vector<std::array<double, 1>> pts{{1.0}};
             return worst_over(e, pts, 0, [](const auto&) { return 4.0 / 3.0 * (1.0 - std::log(2.0)); });
         }},
    };
    return m;
}

}  // namespace

std::vector<ClosedFormCheck> closed_form_checks(const std::string& table_id) {
    static const std::map<std::string, std::vector<ClosedFormCheck>> all = build();
    auto it = all.find(table_id);
    return it == all.end() ? std::vector<ClosedFormCheck>{} : it->second;
}

}  // namespace brdflut
