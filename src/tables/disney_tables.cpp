// Directional albedo of the Disney principled BRDF's lobes, per unit base
// colour, for energy-consistent layering.
//
// Burley 2012, "Physically-Based Shading at Disney"
#include "brdflut/disney.h"
#include "tables/lobe_table.h"
#include "tables/registry.h"

namespace brdflut {

void register_disney_tables(std::vector<TableDefinition>& out) {
    using namespace tables;
    const AxisSpec roughness = unit_axis("roughness", "perceptual roughness r (alpha = r^2)");
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
    out.push_back(lobe_table(Lobe::disney_diffuse, LobeTableKind::albedo, "disney_diffuse_albedo",
                             "Disney (Burley) diffuse directional albedo E(mu, r), base colour 1",
                             {cos_theta_axis(), roughness}, e, diffuse));
    out.push_back(lobe_table(Lobe::disney_diffuse, LobeTableKind::albedo_average,
                             "disney_diffuse_albedo_avg",
                             "Disney diffuse average albedo E_avg(r) = 2 * integral of E mu dmu",
                             {roughness}, e_avg, diffuse));
    out.push_back(lobe_table(Lobe::disney_subsurface, LobeTableKind::albedo,
                             "disney_subsurface_albedo",
                             "Disney subsurface (Hanrahan-Krueger-like) directional albedo E(mu, r)",
                             {cos_theta_axis(), roughness}, e, subsurface));
    out.push_back(lobe_table(Lobe::disney_subsurface, LobeTableKind::albedo_average,
                             "disney_subsurface_albedo_avg",
                             "Disney subsurface average albedo E_avg(r)", {roughness}, e_avg,
                             subsurface));
    out.push_back(lobe_table(Lobe::disney_sheen, LobeTableKind::albedo_1d, "disney_sheen_albedo",
                             "Disney sheen directional albedo E(mu) per unit sheen weight",
                             {cos_theta_axis()}, e, sheen));
    out.push_back(lobe_table(Lobe::disney_clearcoat, LobeTableKind::albedo,
                             "disney_clearcoat_albedo",
                             "Disney clearcoat directional albedo E_c(mu, g) with weight 1",
                             {cos_theta_axis(), gloss}, e, clearcoat));
    out.push_back(lobe_table(Lobe::disney_clearcoat, LobeTableKind::albedo_average,
                             "disney_clearcoat_albedo_avg",
                             "Disney clearcoat average albedo E_c_avg(g)", {gloss}, e_avg,
                             clearcoat));
}

}  // namespace brdflut
