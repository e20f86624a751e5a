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
    "disney_diffuse_albedo, sheen_charlie_albedo; error per value: that rule's estimate",
    "as the core tables: GGX visible normals (ggx_*), cosine hemisphere (disney_*), uniform + Charlie "
    "mixture (sheen_*), a defensive mixture of GGX visible normals (ggx_glass_*)"};

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

// EEVEE's brdf_ggx, axes (roughness, cos_theta): R + G at roughness 1
// with the separable Smith G, whose G1 at alpha = 1 is 2 mu / (1 + mu).
ClosedFormCheck separable_at_one() {
    return {"R + G at roughness 1 vs 2 (1 - ln 2)/(1 + mu) (separable Smith, alpha = 1)", 2 * kGgx + 1e-12,
            [](const TexelEvaluator& e) {
                return worst_error(e, grid_points({1.0}, kMus), [](const TexelValue& v, const auto& p) {
                    return v.value[0] + v.value[1] - ggx_schlick_albedo_alpha_one(p[1]);
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

std::vector<AxisSpec> mu_r(int mus, int rs, Placement placement) {
    return {cos_theta(mus, placement), roughness(rs, placement)};
}

std::vector<PresetDeclaration> declare() {
    const nlohmann::json hc = ggx_model(Visibility::height_correlated);
    nlohmann::json filament_model = hc;
    filament_model["cloth"] = tables::charlie_sheen_model();
    nlohmann::json hdrp_model = hc;
    hdrp_model["diffuse"] = "Disney (Burley 2012), per unit base colour, F_D90 = 0.5 + 2 r cos^2(theta_d)";
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
        {{"unreal", "UE4's PreIntegratedGF: 128x32 scale and bias with Schlick-Smith G (k = alpha/2)",
          PixelType::float32},
         {{"unreal_dfg", "UE4 PreIntegratedGF: specular = F0 * R + G, Schlick-Smith G with k = alpha/2",
           "Karis 2013, \"Real Shading in Unreal Engine 4\" (IntegrateBRDF); UE4 SystemTextures.cpp",
           mu_r(128, 32, Placement::center),
           {split_a("A: integral of f (1 - (1 - v.h)^5) cos(theta_i) dw_i (scale)"),
            split_b("B: integral of f (1 - v.h)^5 cos(theta_i) dw_i (bias)")},
           {{"visibility", "schlick_smith"}},
           ggx_model(Visibility::schlick_smith),
           {checks::split_at_one(0, 1, true)}}}});
    all.push_back(
        {{"hdrp", "Unity HDRP's PreIntegratedFGD: 64x64, x = sqrt(NdotV), end points, GGX and Disney diffuse",
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
           {checks::split_at_one(-1, 1, false), checks::disney_diffuse_smooth(2)}}}});
    all.push_back(
        {{"cycles",
          "Blender Cycles' table_ggx_E (32x32, x = sqrt(alpha), y = mu, end points), table_ggx_Eavg, the "
          "four rough glass tables (16^3 and 16^2, z = sqrt((n-1)/(n+1))) and the two generalized-Schlick "
          "tables (16^3, fresnel_moment_tables.cpp)",
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
    // EEVEE's brdf_ggx (eevee_lut_comp.glsl, ggx_brdf_split_sum): x =
    // roughness (alpha = x^2), y = sqrt(1 - cos(theta)), end points, NV
    // clamped to [1e-4, 0.9999], separable Smith G; channels scale, bias and
    // the F82-tint metal_bias.
    nlohmann::json eevee_model = ggx_model(Visibility::separable);
    eevee_model["fresnel"] = "F82-tint, factored out: F0 * R + F90 * G - b * B, b as fresnel_f82tint_B";
    AxisSpec eevee_y = cos_theta(64, Placement::endpoints, Warp::square);
    eevee_y.axis.min = 1.0;
    eevee_y.axis.max = 0.0;
    eevee_y.axis.clamp_lo = 1e-4;
    eevee_y.axis.clamp_hi = 0.9999;
    eevee_y.meaning = "cos(theta_o) = 1 - y^2 (y = sqrt(1 - cos(theta_o))), clamped to [1e-4, 0.9999]";
    all.push_back(
        {{"eevee", "Blender EEVEE's brdf_ggx: 64x64 split sums with the F82-tint channel, x = roughness, "
                   "y = sqrt(1 - cos theta), end points, separable Smith G",
          PixelType::float32},
         {{"eevee_brdf_ggx", "EEVEE brdf_ggx: specular = F0 * R + F90 * G - b * B (F82 tint)",
           "blender/blender source/blender/draw/engines/eevee/shaders/eevee_lut_comp.glsl (ggx_brdf_split_sum), "
           "eevee_lut.cc",
           {roughness(64, Placement::endpoints), eevee_y},
           {{"R: scale, integral of f (1 - (1 - v.h)^5) cos(theta_i) dw_i", {{"ggx_dfg_f82", 0}}},
            {"G: bias, integral of f (1 - v.h)^5 cos(theta_i) dw_i", {{"ggx_dfg_f82", 1}}},
            {"B: metal_bias, integral of f (v.h) (1 - v.h)^6 cos(theta_i) dw_i", {{"ggx_dfg_f82", 2}}}},
           {{"visibility", "separable"}},
           eevee_model,
           {checks::separable_at_one()}}}});
    all.push_back(
        {{"gltf", "glTF-IBL-Sampler's LUTs: GGX split sum (RG) and Charlie (B), cell centres, 128x128 here",
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
           {checks::charlie_normal(2)}}}});
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
                    "refitted: GGX (alpha >= 1e-3) and Cook-Torrance (Beckmann with the V-cavity G, alpha >= "
                    "0.002, with its error table); float, as the entries reach past the half range",
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
