// verify's checks of the LTC tables: the norms and the sphere channel
// against closed forms, and each fit against its own objective.
#include <cmath>
#include <sstream>

#include "brdflut/ltc.h"
#include "brdflut/verify.h"
#include "check/ltc_checks.h"

namespace brdflut {

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
    // The fit at a spread of texels is a local minimum: no parameter moved
    // by 1e-3 (theta by 1e-3 of the lobe's width) lowers the objective. The
    // row is the relative drop (0 when none).
    m["ltc_1"] = {
        {"fit is a local minimum of its objective (relative drop under perturbation)", 1e-9,
         [](const TexelEvaluator& e) {
             Result r{0.0, ""};
             for (double rough : {0.1, 0.5, 0.9})
                 for (double mu : {1.0, 0.5, 0.05}) {
                     const double c[2] = {rough, mu};
                     const TexelValue v = e.evaluate(c, 0);
                     const double alpha = alpha_from_perceptual(rough);
                     const LtcFit fit = fit_ggx_ltc(mu, alpha, Visibility::height_correlated);
                     // The table holds this fit.
                     double drop = std::abs(v.value[0] - fit.minv.a) + std::abs(v.value[3] - fit.minv.d);
                     const double width = std::min(std::exp(fit.params[1]), 1.0);
                     const double steps[4] = {1e-3 * width, 1e-3, 1e-3, 1e-3};
                     for (int k = 0; k < 4; ++k)
                         for (double sgn : {-1.0, 1.0}) {
                             std::array<double, 4> p = fit.params;
                             p[static_cast<std::size_t>(k)] += sgn * steps[k];
                             const double j = ltc_objective(mu, alpha, Visibility::height_correlated, p);
                             drop = std::max(drop, (fit.objective - j) / fit.objective);
                         }
                     if (drop > r.first || r.second.empty()) {
                         std::ostringstream s;
                         s << "at roughness " << rough << ", mu " << mu;
                         r = {std::max(drop, 0.0), s.str()};
                     }
                 }
             return r;
         }},
    };
}

}  // namespace brdflut
