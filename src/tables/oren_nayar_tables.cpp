// Directional albedo of the Oren-Nayar rough diffuse models, per unit albedo.
//
// Oren and Nayar 1994, "Generalization of Lambert's Reflectance Model"
// Fujii 2012, "A tiny improvement of Oren-Nayar reflectance model"
// Portsmouth et al. 2025, "EON: A practical energy-preserving rough diffuse BRDF"
#include "brdflut/oren_nayar.h"
#include "tables/lobe_table.h"
#include "tables/registry.h"

namespace brdflut {

void register_oren_nayar_tables(std::vector<TableDefinition>& out) {
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
    out.push_back(lobe_table(Lobe::oren_nayar, LobeTableKind::albedo, "oren_nayar_albedo",
                             "Oren-Nayar (qualitative) directional albedo E(mu, sigma), rho = 1",
                             {cos_theta_axis(), sigma_rad}, e, on));
    out.push_back(lobe_table(Lobe::oren_nayar, LobeTableKind::albedo_average,
                             "oren_nayar_albedo_avg", "Oren-Nayar average albedo E_avg(sigma)",
                             {sigma_rad}, e_avg, on));
    out.push_back(lobe_table(Lobe::fujii_oren_nayar, LobeTableKind::albedo,
                             "fujii_oren_nayar_albedo",
                             "Fujii Oren-Nayar (FON) directional albedo E(mu, sigma), rho = 1",
                             {cos_theta_axis(), sigma_fon}, e, fon));
    out.push_back(lobe_table(Lobe::fujii_oren_nayar, LobeTableKind::albedo_average,
                             "fujii_oren_nayar_albedo_avg", "Fujii Oren-Nayar average albedo",
                             {sigma_fon}, e_avg, fon));
    out.push_back(lobe_table(Lobe::eon, LobeTableKind::albedo, "eon_albedo",
                             "EON directional albedo at rho = 1: a white furnace (1 everywhere)",
                             {cos_theta_axis(), sigma_fon}, e, eon));
    out.push_back(lobe_table(Lobe::eon, LobeTableKind::albedo_average, "eon_albedo_avg",
                             "EON average albedo at rho = 1 (1 everywhere)", {sigma_fon}, e_avg,
                             eon));
}

}  // namespace brdflut
