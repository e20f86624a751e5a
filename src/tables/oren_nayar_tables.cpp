// Directional albedo of the Oren-Nayar rough diffuse models, per unit albedo.
//
// Oren and Nayar 1994, "Generalization of Lambert's Reflectance Model"
// Fujii 2012, "A tiny improvement of Oren-Nayar reflectance model"
// Portsmouth et al. 2025, "EON: A practical energy-preserving rough diffuse BRDF"
#include "brdflut/oren_nayar.h"
#include "tables/checks.h"
#include "tables/lobe_table.h"
#include "tables/registry.h"

namespace brdflut {

namespace oren_nayar_family {  // this family's own names, apart from the other families' in a unity build
namespace {

// The qualitative model's albedo in closed form:
// E = A + (2B/pi)((tan_o/3)(1 - sin_o^3) + sin_o (theta_o - sin_o mu_o)/2).
double oren_nayar_albedo_closed_form(double mu, double sigma) {
    const OrenNayar on{sigma};
    const double t = std::acos(mu), s = std::sin(t);
    // mu > 0: the callers' points and the quadrature's nodes.
    return on.A() + 2.0 * on.B() / kPi * ((s / mu) / 3.0 * (1.0 - s * s * s) + 0.5 * s * (t - s * mu));
}

// 2 * integral of the closed-form E(mu) mu dmu (E is bounded: the mu in the
// weight cancels tan_o's pole).
double oren_nayar_average_of_closed_form(double sigma) {
    AdaptiveOptions opt;
    opt.abs_tol = 1e-14;
    opt.max_intervals = 400;
    opt.rule = KronrodRule::k31;
    return integrate_adaptive<1>(
               [&](double mu) { return std::array<double, 1>{2.0 * oren_nayar_albedo_closed_form(mu, sigma) * mu}; },
               0.0, 1.0, opt)
        .value[0];
}

}  // namespace
}  // namespace oren_nayar_family

void register_oren_nayar_family(FamilyEntries& family) {
    using namespace oren_nayar_family;
    family.families.push_back(
        {"", "Rough diffuse: Oren-Nayar, Fujii and EON",
        "The albedo and its average of three rough diffuse models at rho = 1: the qualitative Oren-Nayar "
        "model (sigma in radians), Fujii's improved form as OpenPBR uses it (FON), and EON (Portsmouth et "
        "al. 2025), FON plus the multiple-scattering lobe built with FON's exact albedo, so that EON is a "
        "white furnace (1 everywhere). The azimuth is integrated in closed form; what remains is one "
        "integral over theta_i, split at theta_o."});
    std::vector<TableDefinition>& out = family.tables;
    using namespace tables;
    const AxisSpec sigma_rad = unit_axis(
        "sigma", "Oren-Nayar roughness: standard deviation of the facet slope angle, radians");
    const AxisSpec sigma_fon = unit_axis("sigma", "Fujii/OpenPBR roughness sigma in [0, 1]");
    const nlohmann::json on = {
        {"brdf", "(rho/pi)(A + B max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta)), "
                 "A = 1 - sigma^2/(2(sigma^2 + 0.33)), B = 0.45 sigma^2/(sigma^2 + 0.09), "
                 "alpha = max(theta_i, theta_o), beta = min(theta_i, theta_o)"},
        {"paper", "Oren and Nayar 1994 (qualitative model)"},
        {"rho", 1.0}};
    const nlohmann::json fon = {
        {"brdf", "(rho/pi) A (1 + sigma s/t), A = 1/(1 + (1/2 - 2/(3 pi)) sigma), "
                 "s = wi.wo - mu_i mu_o, s/t = s/max(mu_i, mu_o) if s > 0 else s"},
        {"paper", "Fujii 2012, normalization of Portsmouth et al. 2025 (OpenPBR)"},
        {"rho", 1.0}};
    const nlohmann::json eon = {
        {"brdf", "FON + (rho_ms/pi)(1 - E_FON(mu_o))(1 - E_FON(mu_i))/(1 - E_FON_avg), rho_ms = 1 "
                 "at rho = 1"},
        {"E_FON", "exact closed form A + (sigma A/pi) G(theta_o) and average A (1 + (2/3 - "
                  "28/(15 pi)) sigma), not the paper's fitted approximation"},
        {"paper", "Portsmouth et al. 2025, EON: A practical energy-preserving rough diffuse BRDF"},
        {"rho", 1.0}};

    const char* e = "E: integral of f cos(theta_i) dw_i";
    const char* e_avg = "E_avg: 2 * integral of E(mu) mu dmu";
    // The checks allow the table's tolerance and 1e-12 for the reference.
    const double tol = kLobeAbsTolerance + 1e-12;
    const auto grid = grid_points({0.5 / 128, 0.05, 0.3, 0.7, 1.0}, {0.0, 0.3, 0.7, 1.0});

    TableDefinition on_e = lobe_table(Lobe::oren_nayar, LobeTableKind::albedo, "oren_nayar_albedo",
                                      "Oren-Nayar (qualitative) directional albedo E(mu, sigma), rho = 1",
                                      {cos_theta_axis(), sigma_rad}, e, on);
    on_e.checks.push_back({"E(mu, sigma) vs A + (2B/pi)((tan_o/3)(1 - sin_o^3) + sin_o (theta_o - sin_o mu_o)/2)",
                           tol, [grid](const TexelEvaluator& ev) {
                               return worst_over(ev, grid, 0,
                                                 [](const auto& p) { return oren_nayar_albedo_closed_form(p[0], p[1]); });
                           }});
    out.push_back(std::move(on_e));

    TableDefinition on_avg = lobe_table(Lobe::oren_nayar, LobeTableKind::albedo_average, "oren_nayar_albedo_avg",
                                        "Oren-Nayar average albedo E_avg(sigma)", {sigma_rad}, e_avg, on);
    on_avg.checks.push_back({"E_avg(sigma) vs 2 * integral of the closed-form E(mu) mu dmu", tol,
                             [](const TexelEvaluator& ev) {
                                 return worst_over(ev, points_1d({0.0, 0.3, 0.7, 1.0}), 0, [](const auto& p) {
                                     return oren_nayar_average_of_closed_form(p[0]);
                                 });
                             }});
    out.push_back(std::move(on_avg));

    TableDefinition fon_e = lobe_table(Lobe::fujii_oren_nayar, LobeTableKind::albedo, "fujii_oren_nayar_albedo",
                                       "Fujii Oren-Nayar (FON) directional albedo E(mu, sigma), rho = 1",
                                       {cos_theta_axis(), sigma_fon}, e, fon);
    fon_e.checks.push_back({"E(mu, sigma) vs A + (sigma A/pi) G(theta)", tol, [grid](const TexelEvaluator& ev) {
                                return worst_over(ev, grid, 0,
                                                  [](const auto& p) { return FujiiOrenNayar{p[1]}.albedo(p[0]); });
                            }});
    out.push_back(std::move(fon_e));

    TableDefinition fon_avg = lobe_table(Lobe::fujii_oren_nayar, LobeTableKind::albedo_average,
                                         "fujii_oren_nayar_albedo_avg", "Fujii Oren-Nayar average albedo",
                                         {sigma_fon}, e_avg, fon);
    fon_avg.checks.push_back({"E_avg(sigma) vs A (1 + (2/3 - 28/(15 pi)) sigma)", tol, [](const TexelEvaluator& ev) {
                                  return worst_over(ev, points_1d({0.0, 0.2, 0.6, 1.0}), 0, [](const auto& p) {
                                      return FujiiOrenNayar{p[0]}.average_albedo();
                                  });
                              }});
    out.push_back(std::move(fon_avg));

    // EON at rho = 1 is a white furnace: its albedo is 1 up to the
    // quadrature of the FON part and of the multiple-scattering lobe.
    TableDefinition eon_e = lobe_table(Lobe::eon, LobeTableKind::albedo, "eon_albedo",
                                       "EON directional albedo at rho = 1: a white furnace (1 everywhere)",
                                       {cos_theta_axis(), sigma_fon}, e, eon);
    eon_e.checks.push_back({"E(mu, sigma) vs 1 (white furnace)", tol, [grid](const TexelEvaluator& ev) {
                                return worst_over(ev, grid, 0, [](const auto&) { return 1.0; });
                            }});
    out.push_back(std::move(eon_e));

    TableDefinition eon_avg = lobe_table(Lobe::eon, LobeTableKind::albedo_average, "eon_albedo_avg",
                                         "EON average albedo at rho = 1 (1 everywhere)", {sigma_fon}, e_avg, eon);
    eon_avg.checks.push_back({"E_avg(sigma) vs 1 (white furnace)", tol, [](const TexelEvaluator& ev) {
                                  return worst_over(ev, points_1d({0.0, 0.5, 1.0}), 0, [](const auto&) { return 1.0; });
                              }});
    out.push_back(std::move(eon_avg));

    family.furnace_models.insert(
        family.furnace_models.end(),
        {{"oren_nayar", "Oren-Nayar 1994, qualitative model", "oren_nayar_albedo", "oren_nayar_albedo_avg", {},
          false, false, 0},
         {"fujii_oren_nayar", "Fujii Oren-Nayar (OpenPBR normalization)", "fujii_oren_nayar_albedo",
          "fujii_oren_nayar_albedo_avg", {}, false, false, 0},
         {"eon", "EON, energy-preserving Oren-Nayar (Portsmouth et al. 2025)", "eon_albedo", "eon_albedo_avg", {},
          false, true, 1e-6}});
}

}  // namespace brdflut
