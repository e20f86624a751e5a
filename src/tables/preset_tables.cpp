// Engine presets: the tables an engine uses, each exactly in the engine's
// layout (grid, texel placement, axis warps, roughness parameterization,
// channel order and meaning, visibility term), declared as data: per table
// its layout and, per channel, a recipe over core catalogue tables
// (tables/recipe.h). Every value is a core table's value (or a linear
// combination of them) at the texel's coordinates converted to the core
// table's axes (alpha = r^2 through alpha_from_perceptual), so compare,
// verify and inspect work unchanged.
//
// Karis 2013, "Real Shading in Unreal Engine 4" (split sum, Schlick-Smith G)
// Kulla and Conty 2017, "Revisiting Physically Based Shading at Imageworks"
#include <cmath>

#include "brdflut/ggx_integrals.h"
#include "brdflut/glass_integrals.h"
#include "brdflut/lobe_integrals.h"
#include "brdflut/sheen_integrals.h"
#include "tables/checks.h"
#include "tables/recipe.h"
#include "tables/registry.h"
#include "tables/sheen_charlie_check.h"

namespace brdflut {
namespace {

AxisSpec cos_theta(int count, Placement placement, Warp warp = Warp::linear) {
    AxisSpec a = tables::cos_theta_axis(count);
    a.axis.placement = placement;
    a.axis.warp = warp;
    if (warp == Warp::square) a.meaning += "; stored at u = sqrt(cos(theta_o))";
    return a;
}

AxisSpec roughness(int count, Placement placement) {
    return {Axis{"roughness", 0.0, 1.0, count, placement, Warp::linear}, 0.0, 1.0,
            "perceptual roughness r; GGX (and Charlie) alpha = r^2", "", "alpha"};
}

AxisSpec alpha_sqrt_linear(int count) {
    AxisSpec a = tables::alpha_axis(count);
    a.axis.placement = Placement::endpoints;
    return a;
}

// Cycles' glass axes (cycles_precompute.cpp): rough = sqrt(alpha) = x/(nx - 1)
// clamped to [1e-4, 1], mu = y/(ny - 1) clamped to [1e-4, 1], z = i/(nz - 1)
// clamped to [1e-4, 0.99] with n = (1 + z^2)/(1 - z^2).
AxisSpec cycles_rough(int count) {
    AxisSpec a = alpha_sqrt_linear(count);
    a.axis.clamp_lo = 1e-8;  // rough 1e-4
    a.axis.clamp_hi = 1.0;
    return a;
}
AxisSpec cycles_mu(int count) {
    AxisSpec a = cos_theta(count, Placement::endpoints);
    a.axis.clamp_lo = 1e-4;
    a.axis.clamp_hi = 1.0;
    return a;
}
double ior_of_z(double z) { return (1.0 + z * z) / (1.0 - z * z); }
AxisSpec cycles_ior(int count) {
    AxisSpec a = tables::ior_axis(count);
    a.axis.placement = Placement::endpoints;
    a.axis.min = 1.0;
    a.axis.max = HUGE_VAL;  // z = 1
    a.axis.clamp_lo = ior_of_z(1e-4);
    a.axis.clamp_hi = ior_of_z(0.99);
    return a;
}

nlohmann::json ggx_model(Visibility vis) {
    return {{"brdf", "GGX microfacet, single scattering"},
            {"distribution", "ggx"},
            {"visibility", to_string(vis)},
            {"fresnel", "Schlick, factored out: F0 (1 - (1 - v.h)^5) + (1 - v.h)^5"},
            {"roughness", "alpha = perceptual_roughness^2"}};
}

// The method metadata of every preset table.
const tables::RecipeMethod kMethod{
    "per channel the rule of the matching core table: ggx_dfg (split sums), ggx_albedo_avg, "
    "ggx_glass_albedo and ggx_glass_albedo_avg (glass), "
    "disney_diffuse_albedo, sheen_charlie_albedo, sheen_charlie_moments (generic lobe path), "
    "fabric_lambert_albedo; error per value: that rule's estimate",
    "as the core tables: GGX visible normals (ggx_*), cosine hemisphere (disney_*), uniform + Charlie "
    "mixture (sheen_charlie_albedo), cosine + reflected Charlie normals (sheen_charlie_moments), a defensive "
    "mixture of GGX visible normals (ggx_glass_*)"};

// The presets' independent checks: the closed forms of their channels'
// integrals, at the preset's own coordinates. Each allows the sum of the
// tolerances of the integrals in the channel and 1e-12 for the closed form.
namespace checks {
using namespace tables;
const double kGgx = kGgxTableTolerance, kGlass = kGlassTolerances.standard;
const std::vector<double> kMus{0.5 / 128, 0.05, 0.25, 0.5, 0.9, 1.0};

// A + B at roughness 1 (alpha = 1), from channels a (-1: none, the B channel
// holds A + B) and b, of a table with axes (cos_theta, roughness).
ClosedFormCheck split_at_one(int a, int b, bool schlick) {
    return {schlick ? "A + B at roughness 1 vs 2 (1 - ln 2)/(1 + mu) (Schlick-Smith, k = 1/2)"
                    : "A + B at roughness 1 vs 1 - mu ln(1 + 1/mu)",
            2 * kGgx + 1e-12, [a, b, schlick](const TexelEvaluator& e) {
                return worst_error(e, grid_points(kMus, {1.0}), [a, b, schlick](const TexelValue& v, const auto& p) {
                    const double sum = (a >= 0 ? v.value[static_cast<std::size_t>(a)] : 0.0) +
                                       v.value[static_cast<std::size_t>(b)];
                    return sum - (schlick ? ggx_schlick_albedo_alpha_one(p[0]) : ggx_albedo_alpha_one(p[0]));
                });
            }};
}

// Charlie sheen E at normal incidence in channel c, roughness axis second.
ClosedFormCheck charlie_normal(int c) {
    return {"Charlie E(1, r) vs 2^(1 - n/2) / (n + 2), n = 2 + 1/r^2", kSheenAbsTolerance + 1e-12,
            [c](const TexelEvaluator& e) {
                return worst_over(e, grid_points({1.0}, {0.2, 0.5, 1.0}), c,
                                  [](const auto& p) { return charlie_albedo_normal(p[1] * p[1]); });
            }};
}

// HDRP's diffuse channel (B = E - 1/2) at roughness 0.
ClosedFormCheck disney_diffuse_smooth(int c) {
    return {"B at roughness 0 vs (41/42)(1 - (1 - mu)^5/2) - 1/2 (Disney diffuse)", kLobeAbsTolerance + 1e-12,
            [c](const TexelEvaluator& e) {
                return worst_over(e, grid_points(kMus, {0.0}), c, [](const auto& p) {
                    return 41.0 / 42.0 * (1.0 - 0.5 * std::pow(1.0 - p[0], 5)) - 0.5;
                });
            }};
}

// A channel of a Charlie moments table against the half-vector rule
// (sheen_charlie_check.h): E (moment 0), F (1) or E/(1 + E) (2), axes
// (cos_theta, roughness r with alpha = r^2) or, when `alpha_axis`, (cos_theta, alpha).
ClosedFormCheck charlie_moment(int c, int moment, SheenShadowing s, bool alpha_axis) {
    const char* what = moment == 0 ? "E" : moment == 1 ? "F (Fresnel moment)" : "E/(1 + E)";
    return {std::string(what) + " vs a nested Gauss-Kronrod rule over the half vector (" + to_string(s) + ")",
            1e-8 + 1e-10, [c, moment, s, alpha_axis](const TexelEvaluator& e) {
                return worst_over(e, grid_points({0.1, 0.6, 0.95}, {0.3, 0.8}), c, [&](const auto& p) {
                    const double alpha = alpha_axis ? p[1] : p[1] * p[1];
                    const auto r = charlie_moments_by_half_vector(p[0], alpha, s);
                    return moment == 2 ? r[0] / (1.0 + r[0]) : r[static_cast<std::size_t>(moment)];
                });
            }};
}

// HDRP's fabric Lambert albedo 1 - r^2/2 in channel c.
ClosedFormCheck fabric_lambert(int c) {
    return {"fabric Lambert albedo vs 1 - r^2/2", 1e-8 + 1e-12, [c](const TexelEvaluator& e) {
                return worst_over(e, grid_points({0.1, 0.9}, {0.0, 0.5, 1.0}), c,
                                  [](const auto& p) { return 1.0 - 0.5 * p[1] * p[1]; });
            }};
}

// Cycles' E over (alpha, mu) at alpha = 1.
ClosedFormCheck albedo_at_alpha_one() {
    return {"E at alpha = 1 vs 1 - mu ln(1 + 1/mu)", 2 * kGgx + 1e-12, [](const TexelEvaluator& e) {
                std::vector<std::array<double, 2>> pts;
                for (double mu : kMus) pts.push_back({1.0, mu});
                return worst_over(e, pts, 0, [](const auto& p) { return ggx_albedo_alpha_one(p[1]); });
            }};
}

ClosedFormCheck albedo_avg_at_alpha_one() {
    return {"E_avg at alpha = 1 vs (4/3)(1 - ln 2)", kGgx + 1e-12, [](const TexelEvaluator& e) {
                return worst_over(e, points_1d({1.0}), 0, [](const auto&) { return ggx_albedo_avg_alpha_one(); });
            }};
}

// Glass at n = 1, E_R + E_T: the straight path masked on both sides; axes
// (alpha, mu, n) or, for the average, (alpha, n).
ClosedFormCheck glass_index_matched() {
    return {"E at n = 1 vs G2(mu, mu) (1 + Lambda(mu)) (no interface)", 2 * kGlass + 1e-12,
            [](const TexelEvaluator& e) {
                std::vector<std::array<double, 3>> pts;
                for (double alpha : {0.05, 0.3, 1.0})
                    for (double mu : {0.05, 0.4, 0.9}) pts.push_back({alpha, mu, 1.0});
                return worst_over(e, pts, 0, [](const auto& p) {
                    return glass_index_matched_transmission(p[1], p[0], Visibility::height_correlated);
                });
            }};
}
ClosedFormCheck glass_average_index_matched() {
    return {"E_avg at n = 1 vs 2 * integral of G2(mu, mu) (1 + Lambda(mu)) mu dmu", 2 * kGlass + 1e-12,
            [](const TexelEvaluator& e) {
                return worst_over(e, grid_points({0.05, 0.3, 1.0}, {1.0}), 0, [](const auto& p) {
                    return glass_index_matched_transmission_average(p[0], Visibility::height_correlated);
                });
            }};
}
}  // namespace checks

using tables::ChannelRecipe;
using tables::PresetDeclaration;
using tables::RecipeTable;

// The channels of a split-sum texture from ggx_dfg's A (channel 0) and B (1).
const char* kA = "A: integral of f (1 - (1 - v.h)^5) cos(theta_i) dw_i";
const char* kB = "B: integral of f (1 - v.h)^5 cos(theta_i) dw_i";
ChannelRecipe split_a(std::string meaning = kA) { return {std::move(meaning), {{"ggx_dfg", 0}}}; }
ChannelRecipe split_b(std::string meaning = kB) { return {std::move(meaning), {{"ggx_dfg", 1}}}; }
ChannelRecipe split_sum(std::string meaning) { return {std::move(meaning), {{"ggx_dfg", 0}, {"ggx_dfg", 1}}}; }
ChannelRecipe charlie(std::string meaning) { return {std::move(meaning), {{"sheen_charlie_albedo", 0}}}; }
// Channel c of sheen_charlie_moments: E (0), F (1), E/(1 + E) (2).
ChannelRecipe charlie_moment(std::string meaning, int c) {
    return {std::move(meaning), {{"sheen_charlie_moments", c}}};
}

// Unreal's cloth table indexes D_Charlie by the row coordinate itself
// (D_Charlie(Roughness, NoH) takes 1/Roughness as the exponent).
AxisSpec alpha_linear(int count) {
    AxisSpec a = tables::alpha_axis(count);
    a.axis.warp = Warp::linear;
    a.meaning = "Charlie alpha, linear in the row coordinate (Unreal's D_Charlie(Roughness) exponent 1/Roughness)";
    return a;
}

std::vector<AxisSpec> mu_r(int mus, int rs, Placement placement) {
    return {cos_theta(mus, placement), roughness(rs, placement)};
}

std::vector<PresetDeclaration> declare() {
    const nlohmann::json hc = ggx_model(Visibility::height_correlated);
    nlohmann::json filament_model = hc;
    filament_model["cloth"] = tables::charlie_sheen_model();
    nlohmann::json hdrp_model = hc;
    hdrp_model["diffuse"] = "Disney (Burley 2012), per unit base colour, F_D90 = 0.5 + 2 r cos^2(theta_d)";
    nlohmann::json hdrp_charlie_model = {
        {"brdf", "Charlie sheen (Estevez and Kulla 2017) with their Lambda fit, no softening, no Fresnel"},
        {"distribution", "charlie: (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi)"},
        {"shadowing", "estevez_kulla"},
        {"diffuse", "fabric Lambert (1 - alpha/2)/pi"},
        {"roughness", "alpha = perceptual_roughness^2"}};
    nlohmann::json gltf_sheen_model = hdrp_charlie_model;
    gltf_sheen_model.erase("diffuse");
    gltf_sheen_model["brdf"] = "KHR_materials_sheen: D_Charlie V_Sheen (Estevez-Kulla Lambda fit, no softening)";
    nlohmann::json unreal_cloth_model = tables::charlie_sheen_model();
    unreal_cloth_model["roughness"] = "alpha = the row coordinate (D_Charlie(Roughness): exponent 1/Roughness)";
    unreal_cloth_model["fresnel"] = "1; G holds the moment of (1 - v.h)^5";
    nlohmann::json cycles_model = hc;
    cycles_model["fresnel"] = "1";
    nlohmann::json glass_model = tables::glass_model(Visibility::height_correlated, false);
    glass_model.erase("side");
    glass_model["side"] = "ggx_glass_E: eta = n; ggx_glass_inv_E: eta = 1/n";
    const std::string cycles_source =
        "blender/blender intern/cycles/app/cycles_precompute.cpp, intern/cycles/scene/shader.tables";
    const std::string cycles_glass_source =
        "blender/blender intern/cycles/app/cycles_precompute.cpp (precompute_ggx_glass_E), "
        "intern/cycles/scene/shader.tables, kernel/closure/bsdf_microfacet.h "
        "(microfacet_ggx_preserve_energy)";
    // A Cycles glass table: E_R + E_T (channel 2) of a core glass table, over
    // (rough, mu, z) or, for the averages, (rough, z).
    const auto glass = [&](std::string id, std::string description, const char* core, bool average,
                           std::string meaning) {
        RecipeTable t{std::move(id), std::move(description), cycles_glass_source, {}, {}, {}, glass_model, {}};
        t.axes = average ? std::vector<AxisSpec>{cycles_rough(16), cycles_ior(16)}
                         : std::vector<AxisSpec>{cycles_rough(16), cycles_mu(16), cycles_ior(16)};
        t.channels = {{std::move(meaning), {{core, 2}}}};
        t.checks = {average ? checks::glass_average_index_matched() : checks::glass_index_matched()};
        return t;
    };

    std::vector<PresetDeclaration> all;
    all.push_back(
        {{"filament", "Filament's DFG: 128x128 RGB16F, multiscatter form (E = mix(R, G, f0)) and cloth in B",
          PixelType::half},
         {{"filament_dfg", "Filament DFG LUT: specular = mix(R, G, f0), cloth (Charlie) in B",
           "google/filament libs/ibl/src/CubemapIBL.cpp (DFG, DFV_Multiscatter, DFV_Charlie_Uniform)",
           mu_r(128, 128, Placement::center),
           {split_b("R: integral of f (1 - v.h)^5 cos(theta_i) dw_i (the B term)"),
            split_sum("G: integral of f cos(theta_i) dw_i (A + B)"),
            charlie("B: Charlie cloth, integral of D_charlie V_neubelt cos(theta_i) dw_i")},
           {},
           filament_model,
           {checks::split_at_one(-1, 1, false), checks::charlie_normal(2)}}}});
    all.push_back(
        {{"unreal",
          "UE4's PreIntegratedGF: 128x32 scale and bias with Schlick-Smith G (k = alpha/2); UE5's 32x32 cloth "
          "energy table (Charlie with Neubelt's visibility: E and the Fresnel moment)",
          PixelType::float32},
         {{"unreal_dfg", "UE4 PreIntegratedGF: specular = F0 * R + G, Schlick-Smith G with k = alpha/2",
           "Karis 2013, \"Real Shading in Unreal Engine 4\" (IntegrateBRDF); UE4 SystemTextures.cpp",
           mu_r(128, 32, Placement::center),
           {split_a("A: integral of f (1 - (1 - v.h)^5) cos(theta_i) dw_i (scale)"),
            split_b("B: integral of f (1 - v.h)^5 cos(theta_i) dw_i (bias)")},
           {{"visibility", "schlick_smith"}},
           ggx_model(Visibility::schlick_smith),
           {checks::split_at_one(0, 1, true)}},
          {"unreal_cloth_energy",
           "UE5 ShadingEnergyClothSpecTexture: (E, F) of Charlie with Neubelt's visibility, alpha = row coordinate",
           "Engine/Shaders/Private/ShadingEnergyConservationTable.usf (BUILD_ENERGY_TABLE 2, SUBSTRATE_ENABLED: "
           "D_Charlie(Roughness) Vis_Ashikhmin), Engine/Source/Runtime/Renderer/Private/ShadingEnergyConservation.cpp",
           {cos_theta(32, Placement::center), alpha_linear(32)},
           {charlie_moment("E: integral of D_charlie V_neubelt cos(theta_i) dw_i", 0),
            charlie_moment("F: integral of D_charlie V_neubelt (1 - v.h)^5 cos(theta_i) dw_i", 1)},
           {{"sheen_shadowing", "neubelt"}},
           unreal_cloth_model,
           {checks::charlie_moment(0, 0, SheenShadowing::neubelt, true),
            checks::charlie_moment(1, 1, SheenShadowing::neubelt, true)}}}});
    all.push_back(
        {{"hdrp",
          "Unity HDRP's PreIntegratedFGD tables, 64x64: GGX and Disney diffuse (x = sqrt(NdotV), end points); "
          "Charlie sheen and fabric Lambert (x = NdotV, centres)",
          PixelType::half},
         {{"hdrp_fgd", "HDRP PreIntegratedFGD_GGXDisneyDiffuse: specular = lerp(R, G, F0), diffuse = B + 0.5",
           "Unity-Technologies/Graphics com.unity.render-pipelines.core ShaderLibrary/"
           "ImageBasedLighting.hlsl (IntegrateGGXAndDisneyDiffuseFGD), PreIntegratedFGD.hlsl",
           {cos_theta(64, Placement::endpoints, Warp::square), roughness(64, Placement::endpoints)},
           {split_b("R: integral of f (1 - v.h)^5 cos(theta_i) dw_i (the B term)"),
            split_sum("G: integral of f cos(theta_i) dw_i (A + B)"),
            {"B: Disney diffuse albedo E(mu, r) - 0.5", {{"disney_diffuse_albedo", 0}}, -0.5}},
           {},
           hdrp_model,
           {checks::split_at_one(-1, 1, false), checks::disney_diffuse_smooth(2)}},
          {"hdrp_fgd_charlie_fabric",
           "HDRP PreIntegratedFGD_CharlieAndFabric: sheen = lerp(R, y, F0), y = G/(1 - G); B = fabric Lambert",
           "Unity-Technologies/Graphics com.unity.render-pipelines.high-definition Runtime/Material/"
           "PreIntegratedFGD/preIntegratedFGD_CharlieFabricLambert.shader @ea9e22d4e47d291cadc670818287d912a8b60647, "
           "ShaderLibrary/BSDF.hlsl (D_Charlie, V_Charlie, CharlieL, FabricLambert)",
           mu_r(64, 64, Placement::center),
           {charlie_moment("R: integral of f (1 - v.h)^5 cos(theta_i) dw_i (Charlie, Estevez-Kulla)", 1),
            charlie_moment("G: E / (1 + E), E = integral of f cos(theta_i) dw_i", 2),
            {"B: fabric Lambert albedo 1 - alpha/2", {{"fabric_lambert_albedo", 0}}}},
           {{"sheen_shadowing", "estevez_kulla"}},
           hdrp_charlie_model,
           {checks::charlie_moment(0, 1, SheenShadowing::estevez_kulla, false),
            checks::charlie_moment(1, 2, SheenShadowing::estevez_kulla, false), checks::fabric_lambert(2)}}}});
    all.push_back(
        {{"cycles",
          "Blender Cycles' table_ggx_E (32x32, x = sqrt(alpha), y = mu, end points), table_ggx_Eavg and the "
          "four rough glass tables (16^3 and 16^2, z = sqrt((n-1)/(n+1)))",
          PixelType::float32},
         {{"cycles_ggx_e", "Cycles table_ggx_E: GGX albedo E, x = sqrt(alpha), rows mu, end points", cycles_source,
           {alpha_sqrt_linear(32), cos_theta(32, Placement::endpoints)},
           {{"E: integral of f cos(theta_i) dw_i with F = 1", {{"ggx_albedo", 0}}}},
           {},
           cycles_model,
           {checks::albedo_at_alpha_one()}},
          {"cycles_ggx_e_avg", "Cycles table_ggx_Eavg: GGX average albedo, x = sqrt(alpha), end points",
           cycles_source,
           {alpha_sqrt_linear(32)},
           {{"E_avg: 2 * integral of E(mu) mu dmu", {{"ggx_albedo_avg", 0}}}},
           {},
           cycles_model,
           {checks::albedo_avg_at_alpha_one()}},
          glass("cycles_ggx_glass_e",
                "Cycles table_ggx_glass_E: E_R + E_T at eta = n, x = sqrt(alpha), y = mu, z = sqrt((n-1)/(n+1))",
                "ggx_glass_albedo", false,
                "E: E_R + E_T, integral of f cos over both hemispheres (energy)"),
          glass("cycles_ggx_glass_e_avg",
                "Cycles table_ggx_glass_Eavg: average of E_R + E_T at eta = n over (sqrt(alpha), z)",
                "ggx_glass_albedo_avg", true,
                "E_avg: 2 * integral of (E_R + E_T)(mu) mu dmu"),
          glass("cycles_ggx_glass_inv_e",
                "Cycles table_ggx_glass_inv_E: E_R + E_T at eta = 1/n, x = sqrt(alpha), y = mu, z",
                "ggx_glass_albedo_inside", false,
                "E: E_R + E_T at eta = 1/n (energy)"),
          glass("cycles_ggx_glass_inv_e_avg",
                "Cycles table_ggx_glass_inv_Eavg: average of E_R + E_T at eta = 1/n over (sqrt(alpha), z)",
                "ggx_glass_albedo_avg_inside", true,
                "E_avg: 2 * integral of (E_R + E_T)(mu) mu dmu at eta = 1/n")}});
    all.push_back(
        {{"gltf",
          "glTF-IBL-Sampler's LUTs: GGX split sum (RG) and Charlie (B), and the Sample Renderer's sheen albedo "
          "lut_sheen_E (Estevez-Kulla), cell centres, 128x128 here",
          PixelType::half},
         {{"gltf_ggx", "glTF-IBL-Sampler lut_ggx: specular = F0 * R + G",
           "KhronosGroup/glTF-IBL-Sampler lib/source/shaders/filter.frag (LUT)",
           mu_r(128, 128, Placement::center),
           {split_a(), split_b()},
           {},
           hc,
           {checks::split_at_one(0, 1, false)}},
          {"gltf_charlie", "glTF-IBL-Sampler lut_charlie: Charlie sheen E in B (R, G unused)",
           "KhronosGroup/glTF-IBL-Sampler lib/source/shaders/filter.frag (LUT, cCharlie)",
           mu_r(128, 128, Placement::center),
           {{"unused: 0", {}},
            {"unused: 0", {}},
            charlie("E: integral of D_charlie V_neubelt cos(theta_i) dw_i, alpha = sheen_roughness^2")},
           {},
           tables::charlie_sheen_model(),
           {checks::charlie_normal(2)}},
          {"gltf_sheen_e",
           "glTF Sample Renderer lut_sheen_E: E of the KHR_materials_sheen BRDF (Charlie D, V_Sheen) in R",
           "KhronosGroup/glTF-Sample-Viewer assets/images/lut_sheen_E.png @481083eca92e8cca8ed2296cf811f22f5c61e4b0 "
           "(read as albedoSheenScalingLUT(NdotV, sheenRoughness).r); brdf.glsl (D_Charlie, V_Sheen)",
           mu_r(128, 128, Placement::center),
           {charlie_moment("E: integral of D_charlie V_sheen cos(theta_i) dw_i, alpha = sheen_roughness^2", 0)},
           {{"sheen_shadowing", "estevez_kulla"}},
           gltf_sheen_model,
           {checks::charlie_moment(0, 0, SheenShadowing::estevez_kulla, false)}}}});
    all.push_back(
        {{"godot", "Godot 4's environment BRDF (an analytic fit in the engine) as a 128x128 split-sum table",
          PixelType::half},
         {{"godot_dfg", "Godot environment BRDF as a table: specular = F0 * R + G (height-correlated GGX)",
           "godotengine/godot servers/rendering/renderer_rd/shaders/forward_clustered/"
           "scene_forward_clustered.glsl (environment BRDF approximation)",
           mu_r(128, 128, Placement::center),
           {split_a(), split_b()},
           {},
           hc,
           {checks::split_at_one(0, 1, false)}}}});
    // The LTC presets' tables are fits (ltc_tables.cpp), which name these
    // presets.
    all.push_back({{"ltc",
                    "Heitz 2016 LTC area-light tables ltc_1, ltc_2 as three.js, EEVEE and Godot load them "
                    "(64x64, rows sqrt(1 - cos theta), columns roughness, end points), refitted, with the "
                    "per-texel error table ltc_ggx_error; the same layout fitted to the Charlie sheen "
                    "(ltc_sheen_charlie, _norm, _error) and EON diffuse (ltc_eon, _norm, _error) lobes",
                    PixelType::float32},
                   {}});
    all.push_back({{"hdrp_ltc",
                    "Unity HDRP's LTC layers (64x64, columns roughness, rows sqrt(1 - cos theta), end points), "
                    "refitted: GGX (alpha >= 1e-3), Cook-Torrance (Beckmann with the V-cavity G, alpha >= "
                    "0.002) and Charlie (Estevez-Kulla shadowing, alpha >= 0.002), each with its error table; "
                    "float, as the entries reach past the half range",
                    PixelType::float32},
                   {}});
    return all;
}

}  // namespace

const std::vector<tables::PresetDeclaration>& tables::preset_declarations() {
    static const std::vector<PresetDeclaration> all = declare();
    return all;
}

const std::vector<Preset>& presets() {
    static const std::vector<Preset> all = [] {
        std::vector<Preset> out;
        for (const tables::PresetDeclaration& p : tables::preset_declarations()) out.push_back(p.preset);
        return out;
    }();
    return all;
}

void register_preset_family(FamilyEntries& family) {
    family.families.push_back(
        {"", "Engine presets",
         "The tables engines ship, each exactly in the engine's layout (grid, texel placement, axis warps, "
         "roughness parameterization, channel order and meaning, visibility term): each is one data entry, a "
         "recipe per stored channel (a linear combination of core tables' channels plus an offset, with the "
         "options the core tables take), evaluated from the core tables themselves, so that compare, verify "
         "and inspect work on them unchanged: Filament's DFG with cloth, Unreal's PreIntegratedGF, HDRP's "
         "PreIntegratedFGD, Cycles' GGX and rough glass albedo tables, glTF-IBL-Sampler's LUTs and Godot's "
         "environment BRDF. Each names the engine source it follows in its metadata; [the engines "
         "page](../engines.md) says what each engine's shipped table holds and how brdflut's compares with "
         "it."});
    for (const tables::PresetDeclaration& p : tables::preset_declarations())
        for (const tables::RecipeTable& t : p.tables)
            family.tables.push_back(tables::recipe_table(t, p.preset.name, kMethod));
    // The core tables the recipes read belong to other families.
    family.complete.push_back([](FamilyEntries& f) {
        for (const tables::PresetDeclaration& p : tables::preset_declarations())
            tables::resolve_recipe_tables(p.tables, f);
    });
}

}  // namespace brdflut
