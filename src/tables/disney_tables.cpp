// Directional albedo of the Disney principled BRDF's lobes, per unit base
// colour, for energy-consistent layering.
//
// Burley 2012, "Physically-Based Shading at Disney"
#include "brdflut/disney.h"
#include "tables/checks.h"
#include "tables/lobe_table.h"
#include "tables/registry.h"

namespace brdflut {

namespace disney_family {  // this family's own names, apart from the other families' in a unity build
namespace {

// E_avg of the subsurface lobe at r = 0, where F_ss90 = 0 and f depends on
// mu_i and mu_o alone: 2.5 (F(mu_i) F(mu_o)(1/(mu_i + mu_o) - 1/2) + 1/2)/pi,
// F(mu) = 1 - (1 - mu)^5, integrated over both cosines by nested adaptive
// quadrature.
double subsurface_average_at_r0() {
    AdaptiveOptions opt;
    opt.abs_tol = 1e-14;
    opt.max_intervals = 400;
    opt.rule = KronrodRule::k31;
    auto F = [](double mu) { return 1.0 - std::pow(1.0 - mu, 5); };
    auto E = [&](double mu_o) {
        return 2.5 * integrate_adaptive<1>(
                         [&](double mu_i) {
                             return std::array<double, 1>{
                                 (F(mu_i) * F(mu_o) * (1.0 / (mu_i + mu_o) - 0.5) + 0.5) * mu_i};
                         },
                         0.0, 1.0, opt)
                         .value[0];
    };
    return integrate_adaptive<1>([&](double mu_o) { return std::array<double, 1>{2.0 * E(mu_o) * mu_o}; }, 0.0,
                                 1.0, opt)
        .value[0];
}

// 2 * integral of E_c(mu, g) mu dmu, with E_c by the directional quadrature
// at 1e-12, in theta = acos(mu) broken where the masking and Fresnel turn.
double clearcoat_average_over_mu(double gloss) {
    const double breaks[] = {0.0, std::acos(0.25), std::acos(1.0 / 16), std::acos(1.0 / 64), 0.5 * kPi};
    AdaptiveOptions opt;
    opt.abs_tol = 2e-12;
    opt.rule = KronrodRule::k15;
    double sum = 0.0;
    for (int k = 0; k < 4; ++k)
        sum += integrate_adaptive<1>(
                   [&](double theta) {
                       return std::array<double, 1>{
                           std::sin(2.0 * theta) *
                           lobe_albedo(Lobe::disney_clearcoat, std::cos(theta), gloss, 1e-12).value[0]};
                   },
                   breaks[k], breaks[k + 1], opt)
                   .value[0];
    return sum;
}

}  // namespace
}  // namespace disney_family

void register_disney_family(FamilyEntries& family) {
    using namespace disney_family;
    family.families.push_back(
        {"", "Disney BRDF lobes",
        "The albedo E(mu, p) = integral of f cos(theta_i) dw_i and its average of the lobes of Burley "
        "2012, per unit base colour: the diffuse lobe with F_D90 = 0.5 + 2 r cos^2(theta_d) (not energy "
        "conserving: E(1, r) = 41/42 + 5r/84), the subsurface lobe (Hanrahan-Krueger-like, F_ss90 = r "
        "cos^2(theta_d)), the untinted sheen (1 - cos(theta_d))^5 and the clearcoat (GTR1 with alpha = "
        "mix(0.1, 0.001, gloss), Fresnel 0.04 + 0.96 (1 - cos(theta_d))^5, GGX G1 with alpha 0.25); a "
        "base layered under a coat of weight c is scaled by 1 - c E_c(mu_o). The azimuth is integrated in "
        "closed form wherever it has one."});
    std::vector<TableDefinition>& out = family.tables;
    using namespace tables;
    AxisSpec roughness = unit_axis("roughness", "perceptual roughness r (alpha = r^2)");
    roughness.square_name = "alpha";
    const AxisSpec gloss =
        unit_axis("clearcoat_gloss", "clearcoat gloss g: GTR1 alpha = mix(0.1, 0.001, g)");
    const nlohmann::json base = {{"paper", "Burley 2012, Physically-Based Shading at Disney"},
                                 {"base_color", 1.0}};
    auto model = [&](const char* brdf) {
        nlohmann::json m = base;
        m["brdf"] = brdf;
        return m;
    };
    const nlohmann::json diffuse =
        model("(1/pi)(1 + (F_D90 - 1)(1 - mu_i)^5)(1 + (F_D90 - 1)(1 - mu_o)^5), "
              "F_D90 = 0.5 + 2 r cos^2(theta_d)");
    const nlohmann::json subsurface =
        model("(1.25/pi)(F_ss (1/(mu_i + mu_o) - 0.5) + 0.5), F_ss as the diffuse with "
              "F_ss90 = r cos^2(theta_d)");
    const nlohmann::json sheen = model("(1 - cos(theta_d))^5, per unit sheen weight, untinted");
    nlohmann::json clearcoat =
        model("F_c G_c D_c / (4 mu_i mu_o), weight 1: D_c GTR1, alpha = mix(0.1, 0.001, g); "
              "F_c = 0.04 + 0.96 (1 - cos(theta_d))^5; G_c separable Smith GGX, alpha_g = 0.25");
    clearcoat["usage"] = "base layers attenuated by 1 - clearcoat * E_c (Burley's lobe weight "
                         "0.25 clearcoat: 1 - 0.25 clearcoat E_c)";

    const char* e = "E: integral of f cos(theta_i) dw_i";
    const char* e_avg = "E_avg: 2 * integral of E(mu) mu dmu";
    // The checks allow the table's tolerance and 1e-12 for the reference route.
    const double tol = kLobeAbsTolerance + 1e-12;

    TableDefinition diffuse_e = lobe_table(Lobe::disney_diffuse, LobeTableKind::albedo, "disney_diffuse_albedo",
                                           "Disney (Burley) diffuse directional albedo E(mu, r), base colour 1",
                                           {cos_theta_axis(), roughness}, e, diffuse);
    diffuse_e.checks.push_back({"E(mu, r = 0) vs (41/42)(1 - (1 - mu)^5/2)", tol, [](const TexelEvaluator& ev) {
        return worst_over(ev, grid_points({0.5 / 128, 0.1, 0.5, 0.9, 1.0}, {0.0}), 0,
                          [](const auto& p) { return 41.0 / 42.0 * (1.0 - 0.5 * std::pow(1.0 - p[0], 5)); });
    }});
    diffuse_e.checks.push_back({"E(1, r) vs 41/42 + 5r/84", tol, [](const TexelEvaluator& ev) {
        return worst_over(ev, grid_points({1.0}, {0.0, 0.25, 0.5, 1.0}), 0,
                          [](const auto& p) { return 41.0 / 42.0 + 5.0 * p[1] / 84.0; });
    }});
    out.push_back(std::move(diffuse_e));

    TableDefinition diffuse_avg = lobe_table(Lobe::disney_diffuse, LobeTableKind::albedo_average,
                                             "disney_diffuse_albedo_avg",
                                             "Disney diffuse average albedo E_avg(r) = 2 * integral of E mu dmu",
                                             {roughness}, e_avg, diffuse);
    diffuse_avg.checks.push_back({"E_avg(r = 0) vs (41/42)^2", tol, [](const TexelEvaluator& ev) {
        return worst_over(ev, points_1d({0.0}), 0, [](const auto&) { return sqr(41.0 / 42.0); });
    }});
    out.push_back(std::move(diffuse_avg));

    out.push_back(lobe_table(Lobe::disney_subsurface, LobeTableKind::albedo, "disney_subsurface_albedo",
                             "Disney subsurface (Hanrahan-Krueger-like) directional albedo E(mu, r)",
                             {cos_theta_axis(), roughness}, e, subsurface));

    TableDefinition subsurface_avg = lobe_table(Lobe::disney_subsurface, LobeTableKind::albedo_average,
                                                "disney_subsurface_albedo_avg",
                                                "Disney subsurface average albedo E_avg(r)", {roughness}, e_avg,
                                                subsurface);
    subsurface_avg.checks.push_back(
        {"E_avg(r = 0) vs 5 integral of integral of (F(mu_i) F(mu_o)(1/(mu_i + mu_o) - 1/2) + 1/2) mu_i mu_o, "
         "F(mu) = 1 - (1 - mu)^5",
         tol, [](const TexelEvaluator& ev) {
             return worst_over(ev, points_1d({0.0}), 0, [](const auto&) { return subsurface_average_at_r0(); });
         }});
    out.push_back(std::move(subsurface_avg));

    out.push_back(lobe_table(Lobe::disney_sheen, LobeTableKind::albedo_1d, "disney_sheen_albedo",
                             "Disney sheen directional albedo E(mu) per unit sheen weight", {cos_theta_axis()}, e,
                             sheen));
    out.push_back(lobe_table(Lobe::disney_clearcoat, LobeTableKind::albedo, "disney_clearcoat_albedo",
                             "Disney clearcoat directional albedo E_c(mu, g) with weight 1",
                             {cos_theta_axis(), gloss}, e, clearcoat));

    TableDefinition clearcoat_avg =
        lobe_table(Lobe::disney_clearcoat, LobeTableKind::albedo_average, "disney_clearcoat_albedo_avg",
                   "Disney clearcoat average albedo E_c_avg(g)", {gloss}, e_avg, clearcoat);
    // The table integrates over the half vector and wo directly; the check
    // integrates the directional albedo over mu, a different route.
    clearcoat_avg.checks.push_back(
        {"E_avg(g) vs 2 * integral of the directional albedo E(mu, g) mu dmu", tol + 1e-11,
         [](const TexelEvaluator& ev) {
             return worst_over(ev, points_1d({0.0, 1.0}), 0, [](const auto& p) {
                 return clearcoat_average_over_mu(p[0]);
             });
         }});
    out.push_back(std::move(clearcoat_avg));

    family.furnace_models.insert(
        family.furnace_models.end(),
        {{"disney_diffuse", "Burley 2012 diffuse", "disney_diffuse_albedo", "disney_diffuse_albedo_avg", {}, false,
          false, 0},
         {"disney_subsurface", "Burley 2012 subsurface (Hanrahan-Krueger-like)", "disney_subsurface_albedo",
          "disney_subsurface_albedo_avg", {}, false, false, 0},
         {"disney_sheen", "Burley 2012 sheen, per unit sheen weight", "disney_sheen_albedo", "", {}, false, false,
          0},
         {"disney_clearcoat", "Burley 2012 clearcoat (GTR1, F0 = 0.04), weight 1", "disney_clearcoat_albedo",
          "disney_clearcoat_albedo_avg", {}, false, false, 0}});
}

}  // namespace brdflut
