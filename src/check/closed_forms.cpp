// Closed-form checks of the catalogue's tables (see the field notes of each
// model for the derivations). Each evaluates the table's own evaluator.
#include <array>
#include <cmath>
#include <map>
#include <sstream>

#include "brdflut/conductor_presets.h"
#include "brdflut/dipole.h"
#include "brdflut/dipole_integrals.h"
#include "brdflut/fresnel.h"
#include "brdflut/math.h"
#include "brdflut/oren_nayar.h"
#include "brdflut/verify.h"
#include "check/ltc_checks.h"

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
    add_ltc_checks(m);
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

    // Fresnel.
    const std::vector<double> etas{1.0, 1.2, 1.33, 1.5, 2.0, 2.9};
    m["fresnel_dielectric"] = {
        {"F at normal incidence vs ((eta - 1)/(eta + 1))^2", 1e-15,
         [etas](const TexelEvaluator& e) {
             std::vector<std::array<double, 2>> pts;
             for (double eta : etas) pts.push_back({1.0, eta});
             return worst_over(e, pts, 0, [](const auto& p) { return sqr((p[1] - 1) / (p[1] + 1)); });
         }},
        {"F at grazing incidence vs 1", 1e-15,
         [etas](const TexelEvaluator& e) {
             std::vector<std::array<double, 2>> pts;
             for (double eta : etas) pts.push_back({0.0, eta});
             return worst_over(e, pts, 0, [](const auto& p) { return p[1] == 1.0 ? 0.0 : 1.0; });
         }},
    };
    m["fresnel_dielectric_avg"] = {
        {"F_avg(eta) vs the exact closed form (eta > 1)", 1e-10,
         [](const TexelEvaluator& e) {
             std::vector<std::array<double, 1>> pts;
             for (double eta : {1.01, 1.33, 1.5, 2.0, 2.99}) pts.push_back({eta});
             return worst_over(e, pts, 0, [](const auto& p) { return fresnel_dielectric_average_closed_form(p[0]); });
         }},
        {"F_avg(1/eta) vs 1 - (1 - F_avg(eta))/eta^2", 1e-10,
         [](const TexelEvaluator& e) {
             std::vector<std::array<double, 1>> pts;
             for (double eta : {1.01, 1.33, 1.5, 2.0, 2.99}) pts.push_back({eta});
             return worst_over(e, pts, 1, [](const auto& p) {
                 return 1.0 - (1.0 - fresnel_dielectric_average_closed_form(p[0])) / (p[0] * p[0]);
             });
         }},
    };
    m["fresnel_conductor"] = {
        {"F at normal incidence vs ((eta - 1)^2 + k^2)/((eta + 1)^2 + k^2) (gold)", 1e-15,
         [](const TexelEvaluator& e) {
             const ConductorPreset& gold = conductor_preset("gold");
             Result r{0.0, ""};
             const double mu = 1.0;
             const TexelValue v = e.evaluate(&mu, 0);
             for (int c = 0; c < 3; ++c) {
                 const double eta = gold.eta[static_cast<std::size_t>(c)], k = gold.k[static_cast<std::size_t>(c)];
                 const double want = (sqr(eta - 1) + k * k) / (sqr(eta + 1) + k * k);
                 const double err = std::abs(v.value[static_cast<std::size_t>(c)] - want);
                 if (err >= r.first) r = {err, std::string("channel ") + "RGB"[c]};
             }
             return r;
         }},
    };
    m["fresnel_conductor_avg"] = {
        {"F_avg(eta, k = 0) vs the dielectric closed form", 1e-9,
         [](const TexelEvaluator& e) {
             std::vector<std::array<double, 2>> pts;
             for (double eta : {1.2, 1.5, 2.0, 3.5}) pts.push_back({eta, 0.0});
             return worst_over(e, pts, 0, [](const auto& p) { return fresnel_dielectric_average_closed_form(p[0]); });
         }},
    };

    // Dipole (default eta 1.3, Egan-Hilgeman F_dr).
    const double A = dipole_boundary_term(diffuse_fresnel_reflectance(1.3, DiffuseFresnel::fit));
    const std::vector<double> albedos{0.0, 0.01, 0.3, 0.7, 0.95, 0.999, 1.0};
    m["dipole_total"] = {
        {"total vs the numerical integral of 2 pi r R_d(r)", 1e-9,
         [A, albedos](const TexelEvaluator& e) {
             std::vector<std::array<double, 1>> pts;
             for (double a : albedos) pts.push_back({a});
             return worst_over(e, pts, 0, [A](const auto& p) {
                 return dipole_reflectance_quadrature(Dipole::from_albedo(p[0], A), HUGE_VAL, 1e-12).value[0];
             });
         }},
    };
    m["dipole_albedo_inverse"] = {
        {"total(inverse(R)) vs R", 1e-12,
         [A](const TexelEvaluator& e) {
             Result r{0.0, ""};
             for (double R : {0.0, 0.05, 0.3, 0.6, 0.9, 0.999}) {
                 const TexelValue v = e.evaluate(&R, 0);
                 const double err = std::abs(dipole_total_reflectance(v.value[0], A) - R);
                 if (err >= r.first) r = {err, "at reflectance " + std::to_string(R)};
             }
             return r;
         }},
    };
    m["dipole_profile"] = {
        {"CDF x total vs the numerical integral of 2 pi r R_d over [0, r]", 1e-9,
         [A](const TexelEvaluator& e) {
             Result r{0.0, ""};
             for (double a : {0.1, 0.5, 0.9, 1.0})
                 for (double radius : {1e-3, 0.1, 1.0, 10.0, 64.0}) {
                     const double c[2] = {radius, a};
                     const TexelValue v = e.evaluate(c, 0);
                     const Dipole d = Dipole::from_albedo(a, A);
                     const double want = dipole_reflectance_quadrature(d, radius, 1e-13).value[0];
                     const double err = std::abs(v.value[1] * d.total_reflectance() - want);
                     if (err >= r.first)
                         r = {err, "at radius " + std::to_string(radius) + ", albedo " + std::to_string(a)};
                 }
             return r;
         }},
    };

    // Disney diffuse (Burley 2012) per unit base colour.
    std::vector<std::array<double, 2>> rough0, normal;
    for (double mu : {0.5 / 128, 0.1, 0.5, 0.9, 1.0}) rough0.push_back({mu, 0.0});
    for (double r : {0.0, 0.25, 0.5, 1.0}) normal.push_back({1.0, r});
    m["disney_diffuse_albedo"] = {
        {"E(mu, r = 0) vs (41/42)(1 - (1 - mu)^5/2)", 1e-9,
         [rough0](const TexelEvaluator& e) {
             return worst_over(e, rough0, 0, [](const auto& p) { return 41.0 / 42.0 * (1.0 - 0.5 * std::pow(1.0 - p[0], 5)); });
         }},
        {"E(1, r) vs 41/42 + 5r/84", 1e-9,
         [normal](const TexelEvaluator& e) {
             return worst_over(e, normal, 0, [](const auto& p) { return 41.0 / 42.0 + 5.0 * p[1] / 84.0; });
         }},
    };
    m["disney_diffuse_albedo_avg"] = {
        {"E_avg(r = 0) vs (41/42)^2", 1e-9,
         [](const TexelEvaluator& e) {
             const std::vector<std::array<double, 1>> pts{{0.0}};
             return worst_over(e, pts, 0, [](const auto&) { return sqr(41.0 / 42.0); });
         }},
    };

    // Oren-Nayar family: sigma = 0 is Lambertian; FON has closed forms; EON is a white furnace.
    std::vector<std::array<double, 2>> grid;
    for (double mu : {0.5 / 128, 0.05, 0.3, 0.7, 1.0})
        for (double sigma : {0.0, 0.3, 0.7, 1.0}) grid.push_back({mu, sigma});
    m["oren_nayar_albedo"] = {
        {"E(mu, sigma = 0) vs 1 (Lambertian)", 1e-9,
         [](const TexelEvaluator& e) {
             std::vector<std::array<double, 2>> pts;
             for (double mu : {0.5 / 128, 0.3, 1.0}) pts.push_back({mu, 0.0});
             return worst_over(e, pts, 0, [](const auto&) { return 1.0; });
         }},
    };
    m["fujii_oren_nayar_albedo"] = {
        {"E(mu, sigma) vs A + (sigma A/pi) G(theta)", 1e-9,
         [grid](const TexelEvaluator& e) {
             return worst_over(e, grid, 0, [](const auto& p) { return FujiiOrenNayar{p[1]}.albedo(p[0]); });
         }},
    };
    m["fujii_oren_nayar_albedo_avg"] = {
        {"E_avg(sigma) vs A (1 + (2/3 - 28/(15 pi)) sigma)", 1e-9,
         [](const TexelEvaluator& e) {
             std::vector<std::array<double, 1>> pts;
             for (double sigma : {0.0, 0.2, 0.6, 1.0}) pts.push_back({sigma});
             return worst_over(e, pts, 0, [](const auto& p) { return FujiiOrenNayar{p[0]}.average_albedo(); });
         }},
    };
    m["eon_albedo"] = {
        {"E(mu, sigma) vs 1 (white furnace)", 1e-6,
         [grid](const TexelEvaluator& e) { return worst_over(e, grid, 0, [](const auto&) { return 1.0; }); }},
    };
    m["eon_albedo_avg"] = {
        {"E_avg(sigma) vs 1 (white furnace)", 1e-6,
         [](const TexelEvaluator& e) {
             std::vector<std::array<double, 1>> pts;
             for (double sigma : {0.0, 0.5, 1.0}) pts.push_back({sigma});
             return worst_over(e, pts, 0, [](const auto&) { return 1.0; });
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
