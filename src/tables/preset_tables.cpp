// Engine presets: the tables an engine uses, each exactly in the engine's
// layout (grid, texel placement, axis warps, roughness parameterization,
// channel order and meaning, visibility term). Every value is one of the
// core integrals (ggx_integrals.h, lobe_integrals.h, sheen_integrals.h) at
// the texel's coordinates converted to the model's (alpha = r^2 through
// alpha_from_perceptual), so compare, verify and inspect work unchanged.
//
// Karis 2013, "Real Shading in Unreal Engine 4" (split sum, Schlick-Smith G)
// Kulla and Conty 2017, "Revisiting Physically Based Shading at Imageworks"
#include <memory>

#include "brdflut/ggx_integrals.h"
#include "brdflut/glass_integrals.h"
#include "brdflut/lobe_integrals.h"
#include "brdflut/random.h"
#include "brdflut/sheen_integrals.h"
#include "tables/checks.h"
#include "tables/registry.h"

namespace brdflut {
namespace {

enum class Kind {
    filament_dfg,      // (mu, r): R = B, G = A + B, B = Charlie cloth E
    unreal_dfg,        // (mu, r): R = A, G = B, Schlick-Smith k = alpha/2
    hdrp_fgd,          // (mu, r): R = B, G = A + B, B = Disney diffuse E - 0.5
    cycles_ggx_e,      // (alpha, mu): R = E
    cycles_ggx_e_avg,  // (alpha): R = E_avg
    split_sum,         // (mu, r): R = A, G = B, height-correlated (glTF, Godot)
    gltf_charlie,      // (mu, r): R = G = 0, B = Charlie cloth E
    cycles_glass_e,    // (alpha, mu, n): R = E_R + E_T at eta = n
    cycles_glass_inv_e,      // the same at eta = 1/n
    cycles_glass_e_avg,      // (alpha, n): R = E_R avg + E_T avg at eta = n
    cycles_glass_inv_e_avg,  // the same at eta = 1/n
};

class PresetEvaluator final : public TexelEvaluator {
public:
    PresetEvaluator(Kind kind, const TableSettings& s)
        : kind_(kind), mc_(s.method == Method::monte_carlo), samples_(s.samples), seed_(s.seed),
          quality_(s.quality) {}

    TexelValue evaluate(const double* c, std::uint64_t texel) const override {
        const std::uint64_t seed = mix_seed(seed_, texel);
        TexelValue out;
        switch (kind_) {
            case Kind::filament_dfg: {
                const double alpha = alpha_from_perceptual(c[1]);
                const Estimate<2> s = split(c[0], alpha, Visibility::height_correlated, seed);
                const Estimate<1> cloth = sheen(c[0], alpha, seed);
                out.value = {s.value[1], s.value[0] + s.value[1], cloth.value[0], 0.0};
                out.error = {s.error[1], s.error[0] + s.error[1], cloth.error[0], 0.0};
                out.evaluations = s.evaluations + cloth.evaluations;
                break;
            }
            case Kind::unreal_dfg:
            case Kind::split_sum: {
                const Visibility vis =
                    kind_ == Kind::unreal_dfg ? Visibility::schlick_smith : Visibility::height_correlated;
                const Estimate<2> s = split(c[0], alpha_from_perceptual(c[1]), vis, seed);
                out.value = {s.value[0], s.value[1], 0.0, 0.0};
                out.error = {s.error[0], s.error[1], 0.0, 0.0};
                out.evaluations = s.evaluations;
                break;
            }
            case Kind::hdrp_fgd: {
                const Estimate<2> s = split(c[0], alpha_from_perceptual(c[1]), Visibility::height_correlated, seed);
                const Estimate<1> d = mc_ ? lobe_albedo_mc(Lobe::disney_diffuse, c[0], c[1], samples_, seed)
                                          : lobe_albedo(Lobe::disney_diffuse, c[0], c[1],
                                                        tolerance(kLobeAbsTolerance));
                out.value = {s.value[1], s.value[0] + s.value[1], d.value[0] - 0.5, 0.0};
                out.error = {s.error[1], s.error[0] + s.error[1], scale() * d.error[0], 0.0};
                out.evaluations = s.evaluations + d.evaluations;
                break;
            }
            case Kind::cycles_ggx_e: {
                const Estimate<2> s = split(c[1], c[0], Visibility::height_correlated, seed);
                out.value[0] = s.value[0] + s.value[1];
                out.error[0] = s.error[0] + s.error[1];
                out.evaluations = s.evaluations;
                break;
            }
            case Kind::cycles_ggx_e_avg: {
                const Estimate<1> e = mc_ ? ggx_albedo_average_mc(c[0], Visibility::height_correlated, samples_, seed)
                                          : ggx_albedo_average(c[0], Visibility::height_correlated,
                                                               tables::ggx_table_tolerance(quality_));
                out.value[0] = e.value[0];
                out.error[0] = scale() * e.error[0];
                out.evaluations = e.evaluations;
                break;
            }
            case Kind::cycles_glass_e:
            case Kind::cycles_glass_inv_e: {
                const double eta = kind_ == Kind::cycles_glass_e ? c[2] : 1.0 / c[2];
                Estimate<2> e = mc_ ? ggx_glass_mc(c[1], c[0], eta, Visibility::height_correlated, samples_, seed)
                                    : ggx_glass(c[1], c[0], eta, Visibility::height_correlated,
                                                tables::kGlassTolerances.at(quality_));
                out.value[0] = e.value[0] + e.value[1];
                out.error[0] = scale() * (e.error[0] + e.error[1]);
                out.evaluations = e.evaluations;
                break;
            }
            case Kind::cycles_glass_e_avg:
            case Kind::cycles_glass_inv_e_avg: {
                const bool inside = kind_ == Kind::cycles_glass_inv_e_avg;
                const double eta = inside ? 1.0 / c[1] : c[1];
                Estimate<2> e = mc_ ? ggx_glass_average_mc(c[0], eta, Visibility::height_correlated, samples_, seed)
                                    : tables::glass_average(c[0], c[1], inside, Visibility::height_correlated,
                                                            tables::kGlassTolerances.at(quality_));
                out.value[0] = e.value[0] + e.value[1];
                out.error[0] = scale() * (e.error[0] + e.error[1]);
                out.evaluations = e.evaluations;
                break;
            }
            case Kind::gltf_charlie: {
                const Estimate<1> cloth = sheen(c[0], alpha_from_perceptual(c[1]), seed);
                out.value[2] = cloth.value[0];
                out.error[2] = cloth.error[0];
                out.evaluations = cloth.evaluations;
                break;
            }
        }
        return out;
    }

private:
    double scale() const { return mc_ ? tables::kMcErrorSigmas : 1.0; }
    // A core integral's absolute tolerance at the requested quality, as its
    // own table takes it.
    double tolerance(double standard) const { return tables::quadrature_tolerances(standard).at(quality_); }

    // {A, B} with errors as stored (Monte Carlo: 4 standard errors; the error
    // of a sum is bounded by the sum of the errors).
    Estimate<2> split(double mu, double alpha, Visibility vis, std::uint64_t seed) const {
        // mu = 0 (end-point grids) gives the grazing limit: see kGrazingMu.
        bool computed = true;
        Estimate<2> e = mc_ ? ggx_split_sum_mc(mu, alpha, vis, samples_, seed)
                            : tables::ggx_split_sum_shared(mu, alpha, vis, tables::ggx_table_tolerance(quality_),
                                                           &computed);
        if (!computed) e.evaluations = 0;
        for (double& x : e.error) x *= scale();
        return e;
    }

    Estimate<1> sheen(double mu, double alpha, std::uint64_t seed) const {
        Estimate<1> e = mc_ ? sheen_charlie_albedo_mc(mu, alpha, samples_, seed)
                            : sheen_charlie_albedo(mu, alpha, tolerance(kSheenAbsTolerance));
        e.error[0] *= scale();
        return e;
    }

    Kind kind_;
    bool mc_;
    long long samples_;
    std::uint64_t seed_;
    Quality quality_;
};

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

const char* kQuadratureRule =
    "per channel the rule of the matching core table: ggx_dfg (split sums), ggx_albedo_avg, "
    "ggx_glass_albedo and ggx_glass_albedo_avg (glass), "
    "disney_diffuse_albedo, sheen_charlie_albedo; error per value: that rule's estimate";

struct Entry {
    Kind kind;
    std::string preset, id, description, engine_source;
    std::vector<AxisSpec> axes;
    std::vector<std::string> channels;
    nlohmann::json model;
};

// The preset's independent checks: the closed forms of its channels'
// integrals, at the preset's own coordinates. Each allows the sum of the
// tolerances of the integrals in the channel and 1e-12 for the closed form.
std::vector<ClosedFormCheck> preset_checks(Kind kind) {
    using namespace tables;
    const double ggx = ggx_table_tolerance(Quality::standard), glass = kGlassTolerances.standard;
    const std::vector<double> mus{0.5 / 128, 0.05, 0.25, 0.5, 0.9, 1.0};
    // A + B at roughness 1 (alpha = 1), from the channels that hold it.
    auto split_at_one = [&](int a, int b, bool schlick) {
        return ClosedFormCheck{
            schlick ? "A + B at roughness 1 vs 2 (1 - ln 2)/(1 + mu) (Schlick-Smith, k = 1/2)"
                    : "A + B at roughness 1 vs 1 - mu ln(1 + 1/mu)",
            2 * ggx + 1e-12, [mus, a, b, schlick](const TexelEvaluator& e) {
                return worst_error(e, grid_points(mus, {1.0}), [a, b, schlick](const TexelValue& v, const auto& p) {
                    const double sum = (a >= 0 ? v.value[static_cast<std::size_t>(a)] : 0.0) +
                                       v.value[static_cast<std::size_t>(b)];
                    return sum - (schlick ? ggx_schlick_albedo_alpha_one(p[0]) : ggx_albedo_alpha_one(p[0]));
                });
            }};
    };
    // Charlie sheen E at normal incidence, channel c, roughness axis second.
    auto charlie_normal = [](int c) {
        return ClosedFormCheck{"Charlie E(1, r) vs 2^(1 - n/2) / (n + 2), n = 2 + 1/r^2", kSheenAbsTolerance + 1e-12,
                               [c](const TexelEvaluator& e) {
                                   return worst_over(e, grid_points({1.0}, {0.2, 0.5, 1.0}), c, [](const auto& p) {
                                       return charlie_albedo_normal(p[1] * p[1]);
                                   });
                               }};
    };
    // Glass at n = 1, E_R + E_T: the straight path masked on both sides.
    auto glass_index_matched = [glass](bool average) {
        if (!average)
            return ClosedFormCheck{"E at n = 1 vs G2(mu, mu) (1 + Lambda(mu)) (no interface)", 2 * glass + 1e-12,
                                   [](const TexelEvaluator& e) {
                                       std::vector<std::array<double, 3>> pts;
                                       for (double alpha : {0.05, 0.3, 1.0})
                                           for (double mu : {0.05, 0.4, 0.9}) pts.push_back({alpha, mu, 1.0});
                                       return worst_over(e, pts, 0, [](const auto& p) {
                                           return glass_index_matched_transmission(p[1], p[0],
                                                                                   Visibility::height_correlated);
                                       });
                                   }};
        return ClosedFormCheck{"E_avg at n = 1 vs 2 * integral of G2(mu, mu) (1 + Lambda(mu)) mu dmu",
                               2 * glass + 1e-12, [](const TexelEvaluator& e) {
                                   return worst_over(e, grid_points({0.05, 0.3, 1.0}, {1.0}), 0, [](const auto& p) {
                                       return glass_index_matched_transmission_average(p[0],
                                                                                       Visibility::height_correlated);
                                   });
                               }};
    };
    switch (kind) {
        case Kind::filament_dfg: return {split_at_one(-1, 1, false), charlie_normal(2)};
        case Kind::unreal_dfg: return {split_at_one(0, 1, true)};
        case Kind::split_sum: return {split_at_one(0, 1, false)};
        case Kind::hdrp_fgd:
            return {split_at_one(-1, 1, false),
                    {"B at roughness 0 vs (41/42)(1 - (1 - mu)^5/2) - 1/2 (Disney diffuse)", kLobeAbsTolerance + 1e-12,
                     [mus](const TexelEvaluator& e) {
                         return worst_over(e, grid_points(mus, {0.0}), 2, [](const auto& p) {
                             return 41.0 / 42.0 * (1.0 - 0.5 * std::pow(1.0 - p[0], 5)) - 0.5;
                         });
                     }}};
        case Kind::cycles_ggx_e:
            return {{"E at alpha = 1 vs 1 - mu ln(1 + 1/mu)", 2 * ggx + 1e-12, [mus](const TexelEvaluator& e) {
                         std::vector<std::array<double, 2>> pts;
                         for (double mu : mus) pts.push_back({1.0, mu});
                         return worst_over(e, pts, 0, [](const auto& p) { return ggx_albedo_alpha_one(p[1]); });
                     }}};
        case Kind::cycles_ggx_e_avg:
            return {{"E_avg at alpha = 1 vs (4/3)(1 - ln 2)", ggx + 1e-12, [](const TexelEvaluator& e) {
                         return worst_over(e, points_1d({1.0}), 0, [](const auto&) { return ggx_albedo_avg_alpha_one(); });
                     }}};
        case Kind::gltf_charlie: return {charlie_normal(2)};
        case Kind::cycles_glass_e:
        case Kind::cycles_glass_inv_e: return {glass_index_matched(false)};
        case Kind::cycles_glass_e_avg:
        case Kind::cycles_glass_inv_e_avg: return {glass_index_matched(true)};
    }
    return {};
}

TableDefinition make(Entry e) {
    TableDefinition d;
    d.id = e.id;
    d.description = e.description;
    d.axes = e.axes;
    d.channels = e.channels;
    d.supports_monte_carlo = true;
    d.searched_by_identify = e.kind != Kind::cycles_glass_e_avg && e.kind != Kind::cycles_glass_inv_e_avg;
    d.preset = e.preset;
    d.checks = preset_checks(e.kind);
    nlohmann::json model = e.model;
    model["preset"] = e.preset;
    model["engine_source"] = e.engine_source;
    const Kind kind = e.kind;
    const bool glass = kind == Kind::cycles_glass_e || kind == Kind::cycles_glass_inv_e ||
                       kind == Kind::cycles_glass_e_avg || kind == Kind::cycles_glass_inv_e_avg;
    d.prepare = [kind, model, glass](const TableSettings& s) {
        PreparedTable p;
        p.evaluator = std::make_unique<PresetEvaluator>(kind, s);
        p.model = model;
        p.method = s.method == Method::monte_carlo
                       ? tables::monte_carlo_method("as the core tables: GGX visible normals (ggx_*), "
                                                    "cosine hemisphere (disney_*), uniform + Charlie "
                                                    "mixture (sheen_*), a defensive mixture of GGX "
                                                    "visible normals (ggx_glass_*)", s)
                       : tables::quadrature_method(kQuadratureRule, glass ? tables::kGlassTolerances.at(s.quality)
                                                                          : tables::ggx_table_tolerance(s.quality));
        return p;
    };
    return d;
}

}  // namespace

const std::vector<Preset>& presets() {
    static const std::vector<Preset> all{
        {"filament", "Filament's DFG: 128x128 RGB16F, multiscatter form (E = mix(R, G, f0)) and cloth in B",
         PixelType::half},
        {"unreal", "UE4's PreIntegratedGF: 128x32 scale and bias with Schlick-Smith G (k = alpha/2)",
         PixelType::float32},
        {"hdrp", "Unity HDRP's PreIntegratedFGD: 64x64, x = sqrt(NdotV), end points, GGX and Disney diffuse",
         PixelType::half},
        {"cycles",
         "Blender Cycles' table_ggx_E (32x32, x = sqrt(alpha), y = mu, end points), table_ggx_Eavg and the "
         "four rough glass tables (16^3 and 16^2, z = sqrt((n-1)/(n+1)))",
         PixelType::float32},
        {"gltf", "glTF-IBL-Sampler's LUTs: GGX split sum (RG) and Charlie (B), cell centres, 128x128 here",
         PixelType::half},
        {"godot", "Godot 4's environment BRDF (an analytic fit in the engine) as a 128x128 split-sum table",
         PixelType::half},
        {"ltc", "Heitz 2016 LTC area-light tables ltc_1, ltc_2 as three.js, EEVEE and Godot load them "
                "(64x64, rows sqrt(1 - cos theta), columns roughness, end points), refitted, with the "
                "per-texel error table ltc_ggx_error; the same layout fitted to the Charlie sheen "
                "(ltc_sheen_charlie, _norm, _error) and EON diffuse (ltc_eon, _norm, _error) lobes",
         PixelType::float32},
        {"hdrp_ltc", "Unity HDRP's LTC GGX matrix (64x64, columns roughness, rows sqrt(1 - cos theta), end "
                     "points, alpha >= 1e-3), refitted; float, as its entries reach past the half range",
         PixelType::float32},
    };
    return all;
}

void register_preset_family(FamilyEntries& family) {
    family.families.push_back(
        {"", "Engine presets",
         "The tables engines ship, each exactly in the engine's layout (grid, texel placement, axis warps, "
         "roughness parameterization, channel order and meaning, visibility term) and computed from the core "
         "tables' integrals, so that compare, verify and inspect work on them unchanged: Filament's DFG with "
         "cloth, Unreal's PreIntegratedGF, HDRP's PreIntegratedFGD, Cycles' GGX and rough glass albedo tables, "
         "glTF-IBL-Sampler's LUTs and Godot's environment BRDF. Each names the engine source it follows in "
         "its metadata; [the engines page](../engines.md) says what each engine's shipped table holds and "
         "how brdflut's compares with it."});
    std::vector<TableDefinition>& out = family.tables;
    const nlohmann::json hc = ggx_model(Visibility::height_correlated);
    nlohmann::json filament_model = hc;
    filament_model["cloth"] = tables::charlie_sheen_model();
    nlohmann::json hdrp_model = hc;
    hdrp_model["diffuse"] = "Disney (Burley 2012), per unit base colour, F_D90 = 0.5 + 2 r cos^2(theta_d)";
    nlohmann::json cycles_model = hc;
    cycles_model["fresnel"] = "1";

    out.push_back(make({Kind::filament_dfg, "filament", "filament_dfg",
                        "Filament DFG LUT: specular = mix(R, G, f0), cloth (Charlie) in B",
                        "google/filament libs/ibl/src/CubemapIBL.cpp (DFG, DFV_Multiscatter, DFV_Charlie_Uniform)",
                        {cos_theta(128, Placement::center), roughness(128, Placement::center)},
                        {"R: integral of f (1 - v.h)^5 cos(theta_i) dw_i (the B term)",
                         "G: integral of f cos(theta_i) dw_i (A + B)",
                         "B: Charlie cloth, integral of D_charlie V_neubelt cos(theta_i) dw_i"},
                        filament_model}));
    out.push_back(make({Kind::unreal_dfg, "unreal", "unreal_dfg",
                        "UE4 PreIntegratedGF: specular = F0 * R + G, Schlick-Smith G with k = alpha/2",
                        "Karis 2013, \"Real Shading in Unreal Engine 4\" (IntegrateBRDF); UE4 SystemTextures.cpp",
                        {cos_theta(128, Placement::center), roughness(32, Placement::center)},
                        {"A: integral of f (1 - (1 - v.h)^5) cos(theta_i) dw_i (scale)",
                         "B: integral of f (1 - v.h)^5 cos(theta_i) dw_i (bias)"},
                        ggx_model(Visibility::schlick_smith)}));
    out.push_back(make({Kind::hdrp_fgd, "hdrp", "hdrp_fgd",
                        "HDRP PreIntegratedFGD_GGXDisneyDiffuse: specular = lerp(R, G, F0), diffuse = B + 0.5",
                        "Unity-Technologies/Graphics com.unity.render-pipelines.core ShaderLibrary/"
                        "ImageBasedLighting.hlsl (IntegrateGGXAndDisneyDiffuseFGD), PreIntegratedFGD.hlsl",
                        {cos_theta(64, Placement::endpoints, Warp::square), roughness(64, Placement::endpoints)},
                        {"R: integral of f (1 - v.h)^5 cos(theta_i) dw_i (the B term)",
                         "G: integral of f cos(theta_i) dw_i (A + B)",
                         "B: Disney diffuse albedo E(mu, r) - 0.5"},
                        hdrp_model}));
    out.push_back(make({Kind::cycles_ggx_e, "cycles", "cycles_ggx_e",
                        "Cycles table_ggx_E: GGX albedo E, x = sqrt(alpha), rows mu, end points",
                        "blender/blender intern/cycles/app/cycles_precompute.cpp, intern/cycles/scene/shader.tables",
                        {alpha_sqrt_linear(32), cos_theta(32, Placement::endpoints)},
                        {"E: integral of f cos(theta_i) dw_i with F = 1"}, cycles_model}));
    out.push_back(make({Kind::cycles_ggx_e_avg, "cycles", "cycles_ggx_e_avg",
                        "Cycles table_ggx_Eavg: GGX average albedo, x = sqrt(alpha), end points",
                        "blender/blender intern/cycles/app/cycles_precompute.cpp, intern/cycles/scene/shader.tables",
                        {alpha_sqrt_linear(32)}, {"E_avg: 2 * integral of E(mu) mu dmu"}, cycles_model}));
    nlohmann::json glass_model = tables::glass_model(Visibility::height_correlated, false);
    glass_model.erase("side");
    glass_model["side"] = "ggx_glass_E: eta = n; ggx_glass_inv_E: eta = 1/n";
    const char* cycles_source =
        "blender/blender intern/cycles/app/cycles_precompute.cpp (precompute_ggx_glass_E), "
        "intern/cycles/scene/shader.tables, kernel/closure/bsdf_microfacet.h "
        "(microfacet_ggx_preserve_energy)";
    out.push_back(make({Kind::cycles_glass_e, "cycles", "cycles_ggx_glass_e",
                        "Cycles table_ggx_glass_E: E_R + E_T at eta = n, x = sqrt(alpha), y = mu, z = sqrt((n-1)/(n+1))",
                        cycles_source, {cycles_rough(16), cycles_mu(16), cycles_ior(16)},
                        {"E: E_R + E_T, integral of f cos over both hemispheres (energy)"}, glass_model}));
    out.push_back(make({Kind::cycles_glass_e_avg, "cycles", "cycles_ggx_glass_e_avg",
                        "Cycles table_ggx_glass_Eavg: average of E_R + E_T at eta = n over (sqrt(alpha), z)",
                        cycles_source, {cycles_rough(16), cycles_ior(16)},
                        {"E_avg: 2 * integral of (E_R + E_T)(mu) mu dmu"}, glass_model}));
    out.push_back(make({Kind::cycles_glass_inv_e, "cycles", "cycles_ggx_glass_inv_e",
                        "Cycles table_ggx_glass_inv_E: E_R + E_T at eta = 1/n, x = sqrt(alpha), y = mu, z",
                        cycles_source, {cycles_rough(16), cycles_mu(16), cycles_ior(16)},
                        {"E: E_R + E_T at eta = 1/n (energy)"}, glass_model}));
    out.push_back(make({Kind::cycles_glass_inv_e_avg, "cycles", "cycles_ggx_glass_inv_e_avg",
                        "Cycles table_ggx_glass_inv_Eavg: average of E_R + E_T at eta = 1/n over (sqrt(alpha), z)",
                        cycles_source, {cycles_rough(16), cycles_ior(16)},
                        {"E_avg: 2 * integral of (E_R + E_T)(mu) mu dmu at eta = 1/n"}, glass_model}));
    out.push_back(make({Kind::split_sum, "gltf", "gltf_ggx",
                        "glTF-IBL-Sampler lut_ggx: specular = F0 * R + G",
                        "KhronosGroup/glTF-IBL-Sampler lib/source/shaders/filter.frag (LUT)",
                        {cos_theta(128, Placement::center), roughness(128, Placement::center)},
                        {"A: integral of f (1 - (1 - v.h)^5) cos(theta_i) dw_i",
                         "B: integral of f (1 - v.h)^5 cos(theta_i) dw_i"},
                        hc}));
    out.push_back(make({Kind::gltf_charlie, "gltf", "gltf_charlie",
                        "glTF-IBL-Sampler lut_charlie: Charlie sheen E in B (R, G unused)",
                        "KhronosGroup/glTF-IBL-Sampler lib/source/shaders/filter.frag (LUT, cCharlie)",
                        {cos_theta(128, Placement::center), roughness(128, Placement::center)},
                        {"unused: 0", "unused: 0",
                         "E: integral of D_charlie V_neubelt cos(theta_i) dw_i, alpha = sheen_roughness^2"},
                        tables::charlie_sheen_model()}));
    out.push_back(make({Kind::split_sum, "godot", "godot_dfg",
                        "Godot environment BRDF as a table: specular = F0 * R + G (height-correlated GGX)",
                        "godotengine/godot servers/rendering/renderer_rd/shaders/forward_clustered/"
                        "scene_forward_clustered.glsl (environment BRDF approximation)",
                        {cos_theta(128, Placement::center), roughness(128, Placement::center)},
                        {"A: integral of f (1 - (1 - v.h)^5) cos(theta_i) dw_i",
                         "B: integral of f (1 - v.h)^5 cos(theta_i) dw_i"},
                        hc}));
}

}  // namespace brdflut
