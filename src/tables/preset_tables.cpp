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
// Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based
//             BRDFs" (the height-correlated G2 that Vis_SmithJointApprox
//             approximates)
#include <algorithm>
#include <cmath>

#include "brdflut/cloth_invggx.h"
#include "brdflut/fresnel.h"
#include "brdflut/generic_lobe.h"
#include "brdflut/ggx_lobe.h"
#include "brdflut/ggx_integrals.h"
#include "brdflut/glass_integrals.h"
#include "brdflut/lobe_integrals.h"
#include "brdflut/ltc_fit.h"
#include "brdflut/sheen_integrals.h"
#include "tables/checks.h"
#include "tables/recipe.h"
#include "tables/registry.h"
#include "tables/sheen_charlie_check.h"

namespace brdflut {
namespace preset_family {  // this family's own names, apart from the other families' in a unity build
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

// The axis stored in reverse (Godot writes row SIZE - 1 - y).
AxisSpec flipped(AxisSpec a) {
    a.axis.flip = true;
    return a;
}

// The axis's parameter clamped from below (USD Storm's max(NoV, 0.001)).
AxisSpec clamped_low(AxisSpec a, double lo) {
    a.axis.clamp_lo = lo;
    a.axis.clamp_hi = a.axis.max;
    return a;
}

// OSL BSDL's MiniMicrofacet axes (microfacet_tools_decl.h): cos = max((i/15)^2,
// 1e-6) and rough = j/15 at end points with alpha = max(rough^2, 1e-5).
AxisSpec bsdl_cos(int count) {
    AxisSpec a = cos_theta(count, Placement::endpoints, Warp::square);
    a.axis.clamp_lo = 1e-6;
    a.axis.clamp_hi = 1.0;
    return a;
}
AxisSpec bsdl_roughness(int count) {
    AxisSpec a = roughness(count, Placement::endpoints);
    a.axis.clamp_lo = std::sqrt(1e-5);
    a.axis.clamp_hi = 1.0;
    return a;
}

// BSDL's Conty-Kulla sheen table (MTX/bsdf_sheen_decl.h, genluts.cpp): rows
// rough = j/15 at end points, the lobe's alpha = clamp(rough, 0.06, 1)
// (ContyKullaDist); columns cos = max(i/15, 1e-6).
AxisSpec bsdl_sheen_alpha(int count) {
    AxisSpec a = tables::alpha_axis(count);
    a.axis.placement = Placement::endpoints;
    a.axis.warp = Warp::linear;
    a.axis.clamp_lo = 0.06;
    a.axis.clamp_hi = 1.0;
    a.meaning = "Charlie alpha = clamp(rough, 0.06, 1), rough = j/15 (BSDL's ContyKullaDist)";
    return a;
}

// BSDL's dielectric tables (SPI/bsdf_dielectric_decl.h, genluts.cpp): cos =
// max(i/15, 1e-6), linear; the index eta = 1.001 + 3.999 t^2 over t = f/31.
AxisSpec bsdl_linear_cos(int count) { return clamped_low(cos_theta(count, Placement::endpoints), 1e-6); }
AxisSpec bsdl_ior(int count) {
    AxisSpec a = tables::ior_axis(count);
    a.axis.min = 1.001;
    a.axis.max = 5.0;
    a.axis.placement = Placement::endpoints;
    a.axis.warp = Warp::square;
    a.meaning = "index n = 1.001 + 3.999 t^2 at end points t (DielectricFresnel::from_table_index); the front "
                "table holds eta = n, the back eta = 1/n";
    return a;
}

// GGX alpha itself, linear, cell centres (MaterialX's albedo table rows).
AxisSpec alpha_linear(int count) {
    AxisSpec a = tables::alpha_axis(count);
    a.axis.warp = Warp::linear;
    a.meaning = "GGX alpha (linear); the Charlie sheen is evaluated at the same alpha";
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
AxisSpec cycles_mu(int count) { return clamped_low(cos_theta(count, Placement::endpoints), 1e-4); }
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

// Unreal's energy tables: alpha = max(r, 0.01)^2 over roughness cell
// centres, and the glass table's index n = 1 + 2 z over cell centres.
AxisSpec unreal_alpha(int count) {
    AxisSpec a = tables::alpha_axis(count);
    a.axis.clamp_lo = 1e-4;
    a.meaning = "GGX alpha = max(r, 0.01)^2, rows linear in perceptual roughness r (GetGGXBasis)";
    return a;
}
AxisSpec unreal_ior(int count) {
    AxisSpec a = tables::ior_axis(count);
    a.axis.warp = Warp::linear;
    a.axis.min = 1.0;
    a.axis.max = 3.0;
    a.axis.placement = Placement::center;
    a.meaning = "index of refraction n = 1 + 2 z over the texel centres z (Unreal's EtaIn)";
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
    "disney_diffuse_albedo, sheen_charlie_albedo, sheen_charlie_moments (over the half vector), "
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

// A + B at roughness 1 from channels a and b of a table with axes
// (roughness, cos_theta), as three.js lays them out.
ClosedFormCheck split_at_one_swapped(int a, int b) {
    return {"A + B at roughness 1 vs 1 - mu ln(1 + 1/mu)", 2 * kGgx + 1e-12, [a, b](const TexelEvaluator& e) {
                return worst_error(e, grid_points({1.0}, kMus), [a, b](const TexelValue& v, const auto& p) {
                    return v.value[static_cast<std::size_t>(a)] + v.value[static_cast<std::size_t>(b)] -
                           ggx_albedo_alpha_one(p[1]);
                });
            }};
}

// Charlie sheen E at normal incidence in channel c, alpha axis second.
ClosedFormCheck charlie_normal_alpha(int c) {
    return {"Charlie E(1, alpha) vs 2^(1 - n/2) / (n + 2), n = 2 + 1/alpha", kSheenAbsTolerance + 1e-12,
            [c](const TexelEvaluator& e) {
                return worst_over(e, grid_points({1.0}, {0.04, 0.25, 1.0}), c,
                                  [](const auto& p) { return charlie_albedo_normal(p[1]); });
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

// A and B (channels 0, 1; axes cos_theta, roughness) against the generic lobe
// path's quadrature of the same integrand, at roughness where the visibility
// terms differ most from the height-correlated G2.
ClosedFormCheck joint_approx_generic() {
    return {"A, B vs the generic lobe path's quadrature of GGX with Vis_SmithJointApprox", kGgx + 1e-9,
            [](const TexelEvaluator& e) {
                CheckResult worst{0.0, ""};
                for (const auto& p : grid_points({0.05, 0.5}, {0.4, 0.8})) {
                    GenericOptions opt;
                    opt.abs_tol = 1e-10;
                    const Estimate<2> g =
                        generic_moments<2>(GgxLobe(p[1] * p[1], Visibility::smith_joint_approx), p[0],
                                           kSplitSumWeights, opt);
                    const TexelValue v = e.evaluate(p.data(), 0);
                    for (std::size_t c = 0; c < 2; ++c) {
                        const double err = std::abs(v.value[c] - g.value[c]);
                        if (!std::isfinite(err)) return CheckResult{HUGE_VAL, point_text(p) + ": not finite"};
                        if (err > worst.first || worst.second.empty()) worst = {err, point_text(p)};
                    }
                }
                return worst;
            }};
}

// BSDL's 1 - E at alpha = 1 (roughness axis second, cos_theta first).
ClosedFormCheck one_minus_albedo_at_alpha_one() {
    return {"1 - E at roughness 1 vs mu ln(1 + 1/mu)", kGgx + 1e-12, [](const TexelEvaluator& e) {
                return worst_over(e, grid_points({0.05, 0.25, 0.5, 1.0}, {1.0}), 0,
                                  [](const auto& p) { return 1.0 - ggx_albedo_alpha_one(p[0]); });
            }};
}

// A channel of a Charlie moments table against the half-vector rule
// (sheen_charlie_check.h): E (moment 0), F (1), E/(1 + E) (2) or 1 - E (3),
// axes (cos_theta, roughness r with alpha = r^2) or, when `alpha_axis`,
// (cos_theta, alpha).
ClosedFormCheck charlie_moment(int c, int moment, SheenShadowing s, bool alpha_axis) {
    const char* what = moment == 0 ? "E" : moment == 1 ? "F (Fresnel moment)" : moment == 2 ? "E/(1 + E)" : "1 - E";
    return {std::string(what) + " vs a nested Gauss-Kronrod rule over the half vector (" + to_string(s) + ")",
            1e-8 + 1e-10, [c, moment, s, alpha_axis](const TexelEvaluator& e) {
                // Beside a coarse grid, a patch at roughness 0.75 to 0.9 (alpha 0.56 to
                // 0.8), where D's |theta_h|^(1/alpha) cusp at the mirror direction
                // is sharpest: the quadrature once missed it by up to 1.8e-7 there.
                std::vector<std::array<double, 2>> pts = grid_points({0.1, 0.6, 0.95}, {0.3, 0.8});
                for (const auto& q : grid_points({0.17, 0.81, 0.934, 0.96}, {0.75, 0.79, 0.82, 0.863}))
                    pts.push_back(q);
                return worst_over(e, pts, c, [&](const auto& p) {
                    const double alpha = alpha_axis ? p[1] : p[1] * p[1];
                    const auto r = charlie_moments_by_half_vector(p[0], alpha, s);
                    return moment == 2 ? r[0] / (1.0 + r[0]) : moment == 3 ? 1.0 - r[0] : r[static_cast<std::size_t>(moment)];
                });
            }};
}

// Unreal's legacy cloth albedo in channel 0 of a table over (mu, alpha) at
// alpha = 1, where D_InvGGX is 1/pi.
ClosedFormCheck inv_ggx_cloth_at_one() {
    return {"E at alpha = 1 vs (1/(1 - mu) + mu ln(mu)/(1 - mu)^2)/2", 1e-8 + 1e-12, [](const TexelEvaluator& e) {
                return worst_over(e, grid_points({0.1, 0.5, 0.9}, {1.0}), 0,
                                  [](const auto& p) { return inv_ggx_cloth_albedo_alpha_one(p[0]); });
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
// Channel c of a glass table with axes (alpha, mu, n), or (mu, alpha, n)
// when mu_first, at n = 1.
ClosedFormCheck glass_index_matched(int c = 0, bool mu_first = false) {
    return {std::string(c == 0 ? "E" : "channel " + std::string(1, "RGBA"[c]) + ":") +
                " at n = 1 vs G2(mu, mu) (1 + Lambda(mu)) (no interface)",
            2 * kGlass + 1e-12, [c, mu_first](const TexelEvaluator& e) {
                std::vector<std::array<double, 3>> pts;
                for (double alpha : {0.05, 0.3, 1.0})
                    for (double mu : {0.05, 0.4, 0.9})
                        pts.push_back(mu_first ? std::array<double, 3>{mu, alpha, 1.0}
                                               : std::array<double, 3>{alpha, mu, 1.0});
                return worst_over(e, pts, c, [mu_first](const auto& p) {
                    const double mu = mu_first ? p[0] : p[1], alpha = mu_first ? p[1] : p[0];
                    return glass_index_matched_transmission(mu, alpha, Visibility::height_correlated);
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
// The F82-tint moment C = integral of f (v.h)(1 - v.h)^6 cos in channel c
// of a table with axes (roughness r, cos_theta), alpha = r^2, against the
// half-vector quadrature of ggx_lobe.h, at points no other check uses
// (inside the layout's clamps, which the layout tests cover).
ClosedFormCheck f82_moment_half_vector(int c) {
    return {"C vs the half-vector quadrature (u = t^2/(alpha^2 + t^2), azimuth clipped exactly)", kGgx + 1e-11,
            [c](const TexelEvaluator& e) {
                return worst_over(e, grid_points({0.004, 0.13, 0.55, 1.0}, {0.001, 0.07, 0.4, 1.0}), c,
                                  [](const auto& p) {
                                      const double alpha = p[0] * p[0], mu = p[1];
                                      return ggx_moments_half_vector<1>(
                                          mu, alpha, Visibility::height_correlated, GgxLobeKind::brdf,
                                          std::array<MomentWeight, 1>{MomentWeight{moment_weight::f82}})[0];
                                  });
            }};
}

// 1 - (E_R + E_T) of a table with axes (mu, alpha, n), or (mu, r, n) with
// alpha = r^2 when `roughness_axis`, at n = 1: there is no interface, no
// reflection, and E_T is the straight path masked on both sides (Adobe's
// OpenPBR tables with the separable G, BSDL's with the height-correlated G2).
ClosedFormCheck glass_complement_index_matched(Visibility vis, bool roughness_axis) {
    return {"1 - (E_R + E_T) at n = 1 vs 1 - G2(mu, mu) (1 + Lambda(mu)) (no interface, " + std::string(to_string(vis)) +
                " G)",
            2 * kGlass + 1e-12, [vis, roughness_axis](const TexelEvaluator& e) {
                std::vector<std::array<double, 3>> pts;
                for (double alpha : {0.05, 0.3, 1.0})
                    for (double mu : {0.05, 0.4, 0.9}) pts.push_back({mu, roughness_axis ? std::sqrt(alpha) : alpha, 1.0});
                return worst_over(e, pts, 0, [vis, roughness_axis](const auto& p) {
                    const double alpha = roughness_axis ? p[1] * p[1] : p[1];
                    return 1.0 - glass_index_matched_transmission(p[0], alpha, vis);
                });
            }};
}
ClosedFormCheck adobe_ideal_average_index_matched() {
    return {"1 - E_avg at n = 1 vs 1 - 2 * integral of G2(mu, mu) (1 + Lambda(mu)) mu dmu (separable G)",
            2 * kGlass + 1e-12, [](const TexelEvaluator& e) {
                return worst_over(e, grid_points({0.05, 0.3, 1.0}, {1.0}), 0, [](const auto& p) {
                    return 1.0 - glass_index_matched_transmission_average(p[0], Visibility::separable);
                });
            }};
}
// A smooth interface (alpha = 0) reflects the Fresnel reflectance, from
// outside (n > 1) and from inside (n < 1, total internal reflection included).
ClosedFormCheck adobe_opaque_smooth() {
    return {"1 - E_R at alpha = 0 vs 1 - F(mu, n) (exact dielectric Fresnel, both sides)", kGlass + 1e-12,
            [](const TexelEvaluator& e) {
                std::vector<std::array<double, 3>> pts;
                for (double n : {0.4, 0.75, 1.0, 1.5, 2.5})
                    for (double mu : {0.05, 0.4, 0.9}) pts.push_back({mu, 0.0, n});
                return worst_over(e, pts, 0, [](const auto& p) { return 1.0 - fresnel_dielectric(p[0], p[2]); });
            }};
}
ClosedFormCheck adobe_opaque_average_smooth() {
    return {"1 - E_R avg at alpha = 0 vs 1 - F_avg(n) (closed form; for n < 1, (1 - F_avg(1/n)) n^2)",
            kGlass + 1e-12, [](const TexelEvaluator& e) {
                return worst_over(e, grid_points({0.0}, {0.4, 0.75, 1.5, 2.5}), 0, [](const auto& p) {
                    const double n = p[1];
                    // Inside, F_avg(1/m) = 1 - (1 - F_avg(m)) / m^2 with m = 1/n.
                    return n >= 1.0 ? 1.0 - fresnel_dielectric_average_closed_form(n)
                                    : (1.0 - fresnel_dielectric_average_closed_form(1.0 / n)) * n * n;
                });
            }};
}
// The metal (F = 1) at alpha = 1, where D = 1/pi and separable G1 = 2 mu/(1 + mu).
ClosedFormCheck adobe_metal_at_alpha_one() {
    return {"1 - E at alpha = 1 vs 1 - 2 (1 - ln 2)/(1 + mu) (separable G)", kGgx + 1e-12,
            [](const TexelEvaluator& e) {
                return worst_over(e, grid_points({0.05, 0.25, 0.5, 1.0}, {1.0}), 0,
                                  [](const auto& p) { return 1.0 - ggx_schlick_albedo_alpha_one(p[0]); });
            }};
}
ClosedFormCheck adobe_metal_average_at_alpha_one() {
    return {"1 - E_avg at alpha = 1 vs 1 - 4 (1 - ln 2)^2 (separable G)", kGgx + 1e-12, [](const TexelEvaluator& e) {
                return worst_over(e, points_1d({1.0}), 0, [](const auto&) {
                    const double c = 1.0 - std::log(2.0);
                    return 1.0 - 4.0 * c * c;
                });
            }};
}

// Mitsuba 3's roughplastic transmittance at its default material (alpha
// 0.1, n = 1.49 / 1.000277): E_T (separable G) against a second route, a
// 1024 x 1024 Gauss-Legendre rule over the visible-normal sample space
// (the construction Mitsuba runs with 32 x 32 nodes; at 1024 its own error
// is below 6e-9 at these points, measured against the reference quality).
ClosedFormCheck mitsuba_transmittance_visible_normal_rule(double alpha, double eta) {
    return {"E_T vs a 1024^2 Gauss-Legendre rule over GGX visible normals (Heitz 2018 sample space, separable G)",
            kGlass + 1e-8, [alpha, eta](const TexelEvaluator& e) {
                return worst_over(e, points_1d({0.05, 0.5, 1.0}), 0, [alpha, eta](const auto& p) {
                    return ggx_transmission_visible_normal_rule(p[0], alpha, eta, 1024);
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
AxisSpec charlie_alpha_linear(int count) {
    AxisSpec a = tables::alpha_axis(count);
    a.axis.warp = Warp::linear;
    a.meaning = "Charlie alpha, linear in the row coordinate (Unreal's D_Charlie(Roughness) exponent 1/Roughness)";
    return a;
}

// Adobe's OpenPBR energy tables (openpbr_microfacet_multiple_scattering_data.h):
// 32 end points per axis; cos_theta = j/31 with the first at 1e-3 (the
// tables' mu = 0 column is the integral at mu = 1e-3, not at 0), alpha
// = (j/31)^2, and the index axis split at n = 1: j < 16 holds 1/n = 1 +
// 1.5 (15 - j)/15 (light leaving a medium of index up to 2.5), j >= 16 holds
// n = 1 + 1.5 (j - 16)/15.
AxisSpec adobe_mu(int count) { return clamped_low(cos_theta(count, Placement::endpoints), 1e-3); }
AxisSpec adobe_alpha(int count) {
    AxisSpec a = alpha_sqrt_linear(count);
    a.meaning = "GGX alpha = r^2, r = j/(count - 1) (openpbr_alpha_to_exact_index: sqrt(alpha) (count - 1))";
    return a;
}
AxisSpec adobe_ior(int count) {
    AxisSpec a = tables::ior_axis(count);
    a.axis.min = 1.0 / 2.5;
    a.axis.max = 2.5;
    a.axis.placement = Placement::split_endpoints;
    a.axis.warp = Warp::ior_split;
    a.domain_min = 0.1;  // the glass model takes any eta > 0; n < 1 is eta = n from the other side
    a.meaning = "relative index n = eta_t/eta_i from 1/2.5 to 2.5; the first half holds n < 1 (light leaving the "
                "denser medium) linear in 1/n, the second n >= 1 linear in n, both halves ending at n = 1 "
                "(openpbr_ior_to_exact_index)";
    return a;
}

std::vector<AxisSpec> mu_r(int mus, int rs, Placement placement) {
    return {cos_theta(mus, placement), roughness(rs, placement)};
}

const char* kUnrealSource =
    "EpicGames/UnrealEngine Engine/Source/Runtime/Renderer/Private/SystemTextures.cpp (PreintegratedGF: "
    "Vis_SmithJointApprox, m = roughness^2, 128x32 cell centres, G16R16), the same code in UE4 and UE 5.x "
    "(read at the public mirror unicorn2022/UE5.8.0 @5d9a05c15b1f8c6d7b3354b360677ce30d688149)";
const char* kUnrealGlassEnergySource =
    "EpicGames/UnrealEngine Engine/Shaders/Private/ShadingEnergyConservationTable.usf (BUILD_ENERGY_TABLE 1: "
    "SampleRefraction, GGXEvalReflection and GGXEvalRefraction, Smith G2 height-correlated; EtaIn = 1 + 2 z), "
    "PathTracing/Material/PathTracingGlossy.ush (alpha = max(roughness, 0.01)^2), "
    "Engine/Source/Runtime/Renderer/Private/ShadingEnergyConservation.cpp (32^3 G16R16, 2^14 samples, shipped "
    "as ShadingEnergyConservationData.h GGXGlassValues), read at the public mirror unicorn2022/UE5.8.0 "
    "@5d9a05c15b1f8c6d7b3354b360677ce30d688149";
const char* kUnrealLegacyClothSource =
    "EpicGames/UnrealEngine Engine/Shaders/Private/ShadingEnergyConservationTable.usf (BUILD_ENERGY_TABLE 2 "
    "without SUBSTRATE_ENABLED: D_InvGGX(Alpha.x * Alpha.y, NoH), Vis_Cloth), BRDF.ush (D_InvGGX, Vis_Cloth), "
    "PathTracing/Material/PathTracingGlossy.ush (alpha = max(roughness, 0.01)^2), "
    "Engine/Source/Runtime/Renderer/Private/ShadingEnergyConservation.cpp (32x32 G16R16, shipped as "
    "ShadingEnergyConservationData.h ClothSpecValues), read at the public mirror unicorn2022/UE5.8.0 "
    "@5d9a05c15b1f8c6d7b3354b360677ce30d688149";
const char* kAdobeOpenPbrSource =
    "adobe/openpbr-bsdf impl/openpbr_microfacet_multiple_scattering_data.h (axes, openpbr_ior_to_exact_index, "
    "the extrapolation above n = 2.5), impl/data/openpbr_energy_array_access.h (array[ior][alpha][cos_theta], "
    "UNORM16), impl/data/openpbr_*_energy_complement_data.h @a29da969683ed3e154af7f32f0e981c05161d885";
const char* kBsdlDielectricSource =
    "AcademySoftwareFoundation/OpenShadingLanguage src/libbsdl/include/BSDL/SPI/bsdf_dielectric_decl.h "
    "(Nc = Nr = 16, Nf = 32, get_cosine) and bsdf_dielectric_impl.h @b3ba1c8e645895da23ed1a6eeca1b241e5bae4ad "
    "(DielectricFresnel::from_table_index, eval: G2_G1 weights, energy), src/libbsdl/src/genluts.cpp "
    "(data[f][r][c] = 1 - E, 128^2 samples), microfacet_tools_impl.h (GGXDist: height-correlated G2)";
const char* kMitsubaRoughPlasticSource =
    "mitsuba-renderer/mitsuba3 src/bsdfs/roughplastic.cpp (MI_ROUGH_TRANSMITTANCE_RES 64, mu = max(1e-6, "
    "linspace(0, 1, 64)), eta = int_ior / ext_ior, m_external_transmittance) and "
    "include/mitsuba/render/microfacet.h (eval_transmittance: (1 - F) G1 of the refracted direction over "
    "visible normals, a 32 x 32 Gauss-Legendre rule) @b45b0a930275114de0f8c34e8cf52775e176ca9a";
const char* kGodotSource =
    "godotengine/godot servers/rendering/renderer_rd/shaders/forward_clustered/integrate_dfg.glsl "
    "@e8387d695efee663e2f427bd427792a6f0c633f0 (PR #103934)";

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
    nlohmann::json godot_model = ggx_model(Visibility::schlick_smith);
    godot_model["cloth"] = tables::charlie_sheen_model();
    nlohmann::json materialx_model = hc;
    materialx_model["roughness"] = "alpha = the row coordinate (linear); the sheen's Charlie alpha is the same";
    materialx_model["sheen"] = tables::charlie_sheen_model();
    const nlohmann::json unreal_legacy_cloth_model = {
        {"brdf", "Unreal legacy cloth: D_InvGGX(alpha^2, n.h) Vis_Cloth(mu_o, mu_i), no Fresnel"},
        {"roughness", "alpha = max(r, 0.01)^2"},
        {"fresnel", "1; G holds the moment of (1 - v.h)^5"}};
    nlohmann::json unreal_glass_model = tables::glass_model(Visibility::height_correlated, false);
    unreal_glass_model.erase("side");
    unreal_glass_model["side"] = "R: eta = n (outside in); G: eta = 1/n (inside out)";
    unreal_glass_model["roughness"] = "alpha = max(r, 0.01)^2";
    nlohmann::json bsdl_glass_model = tables::glass_model(Visibility::height_correlated, false);
    bsdl_glass_model.erase("side");
    bsdl_glass_model["side"] = "front: eta = n; back: eta = 1/n";
    bsdl_glass_model["roughness"] = "alpha = max(r^2, 1e-5)";
    nlohmann::json bsdl_sheen_model = {
        {"brdf", "BSDL ContyKullaSheen: D_Charlie G2 / (4 mu_o mu_i), no Fresnel"},
        {"distribution", "charlie: (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi)"},
        {"shadowing", "estevez_kulla_soft: G2 = 1/(1 + Lambda(mu_o) + Lambda(mu_i)^(1 + 2 (1 - mu_i)^8)), "
                      "Lambda the Estevez-Kulla fit (BSDL's legacy, non-reciprocal G2)"},
        {"roughness", "alpha = clamp(rough, 0.06, 1)"},
        {"lookup", "BSDL reads albedo = 1 - the table, linear in both axes"},
        {"cos_theta", "below 1e-4 computed at 1e-4 (the first column's 1e-6 included)"}};
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
          "Unreal Engine's PreintegratedGF (UE4 and UE5): 128x32 scale and bias, GGX with Vis_SmithJointApprox; "
          "UE5's 32^3 GGX glass energy table (E_R + E_T from outside and inside) and 32x32 cloth energy tables "
          "(E and the Fresnel moment: Substrate's Charlie with Neubelt's visibility, the legacy D_InvGGX)",
          PixelType::float32},
         {{"unreal_dfg",
           "UE PreintegratedGF: specular = F0 * R + G, GGX with Vis_SmithJointApprox (a = alpha = r^2)",
           kUnrealSource, mu_r(128, 32, Placement::center),
           {split_a("A: integral of f (1 - (1 - v.h)^5) cos(theta_i) dw_i (scale)"),
            split_b("B: integral of f (1 - v.h)^5 cos(theta_i) dw_i (bias)")},
           {{"visibility", "smith_joint_approx"}},
           ggx_model(Visibility::smith_joint_approx),
           {checks::split_at_one(0, 1, false), checks::joint_approx_generic()},
           Storage::unorm16},  // G16R16 UNORM
          {"unreal_ggx_glass_energy",
           "UE5 ShadingEnergyGGXGlassTexture: E_R + E_T of rough glass from outside (R) and inside (G), 32^3",
           kUnrealGlassEnergySource,
           {cos_theta(32, Placement::center), unreal_alpha(32), unreal_ior(32)},
           {{"R: E_R + E_T at eta = n (outside in)", {{"ggx_glass_albedo", 2}}},
            {"G: E_R + E_T at eta = 1/n (inside out)", {{"ggx_glass_albedo_inside", 2}}}},
           {},
           unreal_glass_model,
           {checks::glass_index_matched(0, true), checks::glass_index_matched(1, true)},
           Storage::unorm16},  // G16R16 UNORM, as ShadingEnergyConservationData.h
          {"unreal_cloth_energy_legacy",
           "UE5 ShadingEnergyClothSpecTexture without Substrate: (E, F) of D_InvGGX with Vis_Cloth, 32x32",
           kUnrealLegacyClothSource,
           {cos_theta(32, Placement::center), unreal_alpha(32)},
           {{"E: integral of D_InvGGX Vis_Cloth cos(theta_i) dw_i", {{"cloth_invggx_moments", 0}}},
            {"F: integral of D_InvGGX Vis_Cloth (1 - v.h)^5 cos(theta_i) dw_i", {{"cloth_invggx_moments", 1}}}},
           {},
           unreal_legacy_cloth_model,
           {checks::inv_ggx_cloth_at_one()},
           Storage::unorm16},  // G16R16 UNORM, as ShadingEnergyConservationData.h
          {"unreal_cloth_energy",
           "UE5 ShadingEnergyClothSpecTexture: (E, F) of Charlie with Neubelt's visibility, alpha = row coordinate",
           "Engine/Shaders/Private/ShadingEnergyConservationTable.usf (BUILD_ENERGY_TABLE 2, SUBSTRATE_ENABLED: "
           "D_Charlie(Roughness) Vis_Ashikhmin), Engine/Source/Runtime/Renderer/Private/ShadingEnergyConservation.cpp",
           {cos_theta(32, Placement::center), charlie_alpha_linear(32)},
           {charlie_moment("E: integral of D_charlie V_neubelt cos(theta_i) dw_i", 0),
            charlie_moment("F: integral of D_charlie V_neubelt (1 - v.h)^5 cos(theta_i) dw_i", 1)},
           {{"sheen_shadowing", "neubelt"}},
           unreal_cloth_model,
           {checks::charlie_moment(0, 0, SheenShadowing::neubelt, true),
            checks::charlie_moment(1, 1, SheenShadowing::neubelt, true)}}}});
    all.push_back(
        {{"unreal_karis2013",
          "Karis 2013 course notes' IntegrateBRDF: 128x32 scale and bias with Schlick-Smith G (k = alpha/2)",
          PixelType::float32},
         {{"unreal_karis2013_dfg",
           "Karis 2013 split sum: specular = F0 * R + G, Schlick-Smith G with k = alpha/2",
           "Karis 2013, \"Real Shading in Unreal Engine 4\" (IntegrateBRDF, course notes)",
           mu_r(128, 32, Placement::center),
           {split_a("A: integral of f (1 - (1 - v.h)^5) cos(theta_i) dw_i (scale)"),
            split_b("B: integral of f (1 - v.h)^5 cos(theta_i) dw_i (bias)")},
           {{"visibility", "schlick_smith"}},
           ggx_model(Visibility::schlick_smith),
           {checks::split_at_one(0, 1, true)}}}});
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
          "Blender Cycles' table_ggx_E (32x32, x = sqrt(alpha), y = mu, end points), table_ggx_Eavg, the "
          "four rough glass tables (16^3 and 16^2, z = sqrt((n-1)/(n+1))), the two generalized-Schlick "
          "tables (16^3, fresnel_moment_tables.cpp) and Zeltner's sheen LTC (32x32, three channels, "
          "sheen_volume_tables.cpp)",
          PixelType::float32},
         {{"cycles_ggx_e", "Cycles table_ggx_E: GGX albedo E, x = sqrt(alpha), rows mu, end points", cycles_source,
           {cycles_rough(32), cycles_mu(32)},
           {{"E: integral of f cos(theta_i) dw_i with F = 1", {{"ggx_albedo", 0}}}},
           {},
           cycles_model,
           {checks::albedo_at_alpha_one()}},
          {"cycles_ggx_e_avg", "Cycles table_ggx_Eavg: GGX average albedo, x = sqrt(alpha), end points",
           cycles_source,
           {cycles_rough(32)},
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
           {checks::split_at_one(0, 1, false)},
           Storage::unorm8},  // RGBA8 PNG
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
        {{"godot",
          "Godot 4 Forward+'s DFG texture: 128x128 RGBA16F, multiscatter form with Schlick-Smith G, rows "
          "flipped, Charlie cloth in B",
          PixelType::half},
         {{"godot_dfg",
           "Godot Forward+ DFG: R = B term, G = A + B (Schlick-Smith, k = alpha/2), B = Charlie cloth, A = 1",
           kGodotSource,
           {cos_theta(128, Placement::center), flipped(roughness(128, Placement::center))},
           {split_b("R: integral of f (1 - v.h)^5 cos(theta_i) dw_i (the B term)"),
            split_sum("G: integral of f cos(theta_i) dw_i (A + B)"),
            charlie("B: Charlie cloth, integral of D_charlie V_neubelt cos(theta_i) dw_i"),
            {"A: 1", {}, 1.0}},
           {{"visibility", "schlick_smith"}},
           godot_model,
           {checks::split_at_one(-1, 1, true), checks::charlie_normal(2)}}}});
    all.push_back(
        {{"godot_mobile",
          "Godot 4 Mobile and Compatibility's environment BRDF (an analytic fit in the engine) as a 128x128 "
          "split-sum table",
          PixelType::half},
         {{"godot_mobile_dfg",
           "Godot Mobile environment BRDF as a table: specular = F0 * R + G (height-correlated GGX)",
           "godotengine/godot servers/rendering/renderer_rd/shaders/forward_mobile/"
           "scene_forward_mobile.glsl (environment BRDF approximation)",
           mu_r(128, 128, Placement::center),
           {split_a(), split_b()},
           {},
           hc,
           {checks::split_at_one(0, 1, false)}}}});
    all.push_back(
        {{"threejs",
          "three.js's DFGLUTData: 16x16 RG16F split sum (since r182; 32x32 up to r181), columns roughness, rows "
          "NdotV",
          PixelType::half},
         {{"threejs_dfg", "three.js DFGLUTData: (scale, bias) = (A, B), height-correlated GGX, x = roughness",
           "mrdoob/three.js src/renderers/shaders/DFGLUTData.js as released in r187 (npm three 0.187.0, 16x16, "
           "the same data since r182); r181's 32x32 is @95dc8849b1f9037294afaa03ef3330e41fd58aa6 (--size 32). "
           "Generator utils/generateDFGLUT.js",
           {roughness(16, Placement::center), cos_theta(16, Placement::center)},
           {split_a(), split_b()},
           {},
           hc,
           {checks::split_at_one_swapped(0, 1)}}}});
    all.push_back(
        {{"materialx",
          "MaterialX's u_albedoTable: 64x64, rows GGX alpha (linear), split sum in RG and the Imageworks "
          "sheen albedo in B",
          PixelType::float32},
         {{"materialx_albedo",
           "MaterialX u_albedoTable: R = A, G = B (height-correlated GGX at alpha = y), B = Charlie sheen albedo",
           "AcademySoftwareFoundation/MaterialX @4177b2cbd48b579ca1e8f7d9901584d811c63b68 "
           "libraries/pbrlib/genglsl/lib/mx_generate_albedo_table.glsl, mx_microfacet_specular.glsl, "
           "mx_microfacet_sheen.glsl",
           {cos_theta(64, Placement::center), alpha_linear(64)},
           {split_a(), split_b(),
            charlie("B: Imageworks sheen albedo, Charlie D at alpha = y with Neubelt's visibility")},
           {},
           materialx_model,
           {checks::split_at_one(0, 1, false), checks::charlie_normal_alpha(2)}}}});
    all.push_back(
        {{"osl_bsdl",
          "OSL BSDL's energy tables: MiniMicrofacetGGX (16x16, 1 - E of GGX, cos = (i/15)^2, alpha = (j/15)^2) and "
          "DielectricFront and Back (16x16x32, 1 - (E_R + E_T) of rough glass, cos = i/15) and ContyKullaSheen (16x16, "
          "1 - E of the Charlie sheen, cos = i/15)",
          PixelType::float32},
         {{"osl_bsdl_ggx", "BSDL spi::MiniMicrofacetGGX: 1 - E (height-correlated GGX, F = 1)",
           "AcademySoftwareFoundation/OpenShadingLanguage @ad63273a0b0fb4d46c2d2e34bf2323f6cb69c3aa "
           "src/libbsdl/src/genluts.cpp, "
           "include/BSDL/microfacet_tools_decl.h (MiniMicrofacet, get_cosine, GGXDist)",
           {bsdl_cos(16), bsdl_roughness(16)},
           {{"1 - E: the energy GGX loses, 1 - integral of f cos(theta_i) dw_i", {{"ggx_albedo", 0, -1.0}}, 1.0}},
           {},
           cycles_model,
           {checks::one_minus_albedo_at_alpha_one()}},
          {"osl_bsdl_dielectric_front",
           "BSDL spi::DielectricFront: 1 - (E_R + E_T) of rough glass from outside (eta = n), 16x16x32",
           kBsdlDielectricSource,
           {bsdl_linear_cos(16), bsdl_roughness(16), bsdl_ior(32)},
           {{"1 - (E_R + E_T): the energy the rough interface loses, eta = n", {{"ggx_glass_albedo", 2, -1.0}}, 1.0}},
           {},
           bsdl_glass_model,
           {checks::glass_complement_index_matched(Visibility::height_correlated, true)}},
          {"osl_bsdl_dielectric_back",
           "BSDL spi::DielectricBack: 1 - (E_R + E_T) of rough glass from inside (eta = 1/n), 16x16x32",
           kBsdlDielectricSource,
           {bsdl_linear_cos(16), bsdl_roughness(16), bsdl_ior(32)},
           {{"1 - (E_R + E_T): the energy the rough interface loses, eta = 1/n",
             {{"ggx_glass_albedo_inside", 2, -1.0}},
             1.0}},
           {},
           bsdl_glass_model,
           {checks::glass_complement_index_matched(Visibility::height_correlated, true)}},
          {"osl_bsdl_sheen",
           "BSDL ContyKullaSheen (spi::CharlieLobe): 1 - E of Charlie with the Estevez-Kulla Lambda and the "
           "terminator softening, 16x16",
           "AcademySoftwareFoundation/OpenShadingLanguage @ad63273a0b0fb4d46c2d2e34bf2323f6cb69c3aa "
           "src/libbsdl/src/genluts.cpp, include/BSDL/MTX/bsdf_sheen_decl.h and bsdf_sheen_impl.h "
           "(ContyKullaDist, ContyKullaSheen: the legacy G2)",
           {bsdl_linear_cos(16), bsdl_sheen_alpha(16)},
           {{"1 - E: the energy the sheen lobe loses, 1 - integral of f cos(theta_i) dw_i",
             {{"sheen_charlie_moments", 0, -1.0}},
             1.0}},
           {{"sheen_shadowing", "estevez_kulla_soft"}},
           bsdl_sheen_model,
           {checks::charlie_moment(0, 3, SheenShadowing::estevez_kulla_soft, true)}}}});
    {
        // Adobe's OpenPBR BSDF: the energy its single-scattering GGX lobes
        // lose, 1 - E, with the separable Smith G (the tables agree with it,
        // not with the height-correlated G2, to their noise), UNORM16.
        const auto adobe = [&](std::string id, std::string description, std::vector<AxisSpec> axes,
                               ChannelRecipe channel, const char* core_model, ClosedFormCheck check) {
            nlohmann::json model = std::string(core_model) == "glass"
                                       ? tables::glass_model(Visibility::separable, false)
                                       : ggx_model(Visibility::separable);
            if (model.contains("side")) {
                model.erase("side");
                model["side"] = "eta = n, the axis value: n < 1 is light leaving the denser medium";
            }
            model["fresnel"] = std::string(core_model) == "glass" ? "exact dielectric" : "1";
            model["lookup"] = "above n = 2.5 (or below 1/2.5) Adobe scales the opaque tables' value by "
                              "1 - (F0(n) - F0(2.5))/(1 - F0(2.5)), F0 = ((n - 1)/(n + 1))^2";
            return RecipeTable{std::move(id),
                               std::move(description),
                               kAdobeOpenPbrSource,
                               std::move(axes),
                               {std::move(channel)},
                               {{"visibility", "separable"}},
                               model,
                               {std::move(check)},
                               Storage::unorm16};
        };
        const auto one_minus = [](std::string meaning, const char* core, int c) {
            return ChannelRecipe{std::move(meaning), {{core, c, -1.0}}, 1.0};
        };
        all.push_back(
            {{"adobe_openpbr",
              "Adobe's OpenPBR BSDF energy tables: 1 - E of GGX (separable G) for the ideal (reflection and "
              "transmission) and opaque (reflection) dielectric over a split index axis and for the metal (F = 1), "
              "32 end points per axis, UNORM16",
              PixelType::float32},
             {adobe("adobe_openpbr_ideal_dielectric_energy_complement",
                    "OpenPBR ideal dielectric: 1 - (E_R + E_T) over (mu, alpha, n), n split at 1",
                    {adobe_mu(32), adobe_alpha(32), adobe_ior(32)},
                    one_minus("1 - (E_R + E_T): the energy the rough interface loses", "ggx_glass_albedo", 2), "glass",
                    checks::glass_complement_index_matched(Visibility::separable, false)),
              adobe("adobe_openpbr_ideal_dielectric_avg_energy_complement",
                    "OpenPBR ideal dielectric: 1 - E_avg (E_R + E_T averaged over mu) over (alpha, n)",
                    {adobe_alpha(32), adobe_ior(32)},
                    one_minus("1 - E_avg: 1 - 2 * integral of (E_R + E_T) mu dmu", "ggx_glass_albedo_avg", 2), "glass",
                    checks::adobe_ideal_average_index_matched()),
              adobe("adobe_openpbr_opaque_dielectric_energy_complement",
                    "OpenPBR opaque dielectric: 1 - E_R over (mu, alpha, n), n split at 1",
                    {adobe_mu(32), adobe_alpha(32), adobe_ior(32)},
                    one_minus("1 - E_R: the energy the interface does not reflect", "ggx_glass_albedo", 0), "glass",
                    checks::adobe_opaque_smooth()),
              adobe("adobe_openpbr_opaque_dielectric_avg_energy_complement",
                    "OpenPBR opaque dielectric: 1 - E_R avg over (alpha, n)", {adobe_alpha(32), adobe_ior(32)},
                    one_minus("1 - E_R avg: 1 - 2 * integral of E_R mu dmu", "ggx_glass_albedo_avg", 0), "glass",
                    checks::adobe_opaque_average_smooth()),
              adobe("adobe_openpbr_ideal_metal_energy_complement", "OpenPBR ideal metal: 1 - E (F = 1) over (mu, alpha)",
                    {adobe_mu(32), adobe_alpha(32)},
                    one_minus("1 - E: 1 - integral of f cos(theta_i) dw_i with F = 1", "ggx_albedo", 0), "ggx",
                    checks::adobe_metal_at_alpha_one()),
              adobe("adobe_openpbr_ideal_metal_avg_energy_complement", "OpenPBR ideal metal: 1 - E_avg (F = 1) over alpha",
                    {adobe_alpha(32)}, one_minus("1 - E_avg: 1 - 2 * integral of E(mu) mu dmu", "ggx_albedo_avg", 0),
                    "ggx", checks::adobe_metal_average_at_alpha_one())}});
    }
    all.push_back(
        {{"babylon",
          "Babylon.js's environmentBRDFTexture: 256x256, R = B term, G = A + B, B = Charlie sheen; RGBD-encoded "
          "as Babylon ships it with --format png",
          PixelType::half},
         {{"babylon_brdf",
           "Babylon.js environment BRDF: R = B term, G = A + B (height-correlated), B = Charlie sheen albedo",
           "BabylonJS/Babylon.js packages/dev/core/src/Misc/brdfTextureTools.ts "
           "@02e530f440cdc783201fcc6131376f7a8c5ed8f4 (getEnvironmentBRDFTexture); pbrBRDFFunctions "
           "(getReflectanceFromBRDFLookup, getSheenReflectanceFromBRDFLookup)",
           mu_r(256, 256, Placement::center),
           {split_b("R: integral of f (1 - v.h)^5 cos(theta_i) dw_i (the B term)"),
            split_sum("G: integral of f cos(theta_i) dw_i (A + B)"),
            charlie("B: Charlie sheen albedo, alpha = sheen_roughness^2")},
           {},
           filament_model,
           {checks::split_at_one(-1, 1, false), checks::charlie_normal(2)},
           Storage::rgbd}}});  // RGBD in an RGBA8 PNG
    all.push_back(
        {{"usd_storm",
          "OpenUSD Storm's domeLightBRDF: split sum with Schlick-Smith G (k = alpha/2), NdotE clamped to "
          "0.001, the dome light's cubemap size (256 here)",
          PixelType::half},
         {{"usd_storm_dfg", "USD Storm domeLightBRDF: specular = F * R + G, Schlick-Smith G (k = alpha/2)",
           "PixarAnimationStudios/OpenUSD pxr/imaging/hdSt/shaders/domeLight.glslfx "
           "@0a8af1f4fda322d7efd7bcc0ddf1c4b399c8a1a6 (DomeLight.BRDF); simpleLightingShader.cpp (size)",
           {clamped_low(cos_theta(256, Placement::center), 0.001), roughness(256, Placement::center)},
           {split_a(), split_b()},
           {{"visibility", "schlick_smith"}},
           ggx_model(Visibility::schlick_smith),
           {checks::split_at_one(0, 1, true)}}}});
    all.push_back(
        {{"bevy", "Bevy's brdf_dfg_lut (dfg_lut feature): split sum sampled at (NdotV, perceptual roughness)",
          PixelType::half},
         {{"bevy_dfg", "Bevy F_AB lookup: specular = F0 * R + G (height-correlated GGX, as Bevy's direct lighting)",
           "bevyengine/bevy crates/bevy_pbr/src/render/pbr_lighting.wgsl (F_AB, brdf_dfg_lut), PR #23737",
           mu_r(64, 64, Placement::center),
           {split_a(), split_b()},
           {},
           hc,
           {checks::split_at_one(0, 1, false)}}}});
    // pbrt-v4's BSSRDFTable (beam_diffusion_tables.cpp names this preset).
    all.push_back({{"pbrt",
                    "pbrt-v4's BSSRDFTable for photon beam diffusion: the profile 2 pi r Sr (64 radii x 100 "
                    "albedos) and rhoEff (100), exact; --construction pbrt_midpoint gives pbrt's own values",
                    PixelType::float32},
                   {}});
    // Unreal's SSProfiles kernels (sss_kernel_tables.cpp names this preset).
    all.push_back({{"unreal_sss",
                    "Unreal Engine's SSProfiles rows: the three mirrored kernels of a Separable profile (13, 9 "
                    "and 6 one-sided taps, weights per channel and offset in mm) and the 32-sample transmission "
                    "profile of a Burley profile",
                    PixelType::float32},
                   {}});
    // The LTC presets' tables are fits (ltc_tables.cpp), which name these
    // presets.
    // Beside ltc_2: the F82-tint moment on its grid, so that an area light
    // on an F82 metal gets F0 (n0 - n1) + n1 - b C instead of Schlick's edge.
    AxisSpec ltc_roughness = roughness(64, Placement::endpoints);
    ltc_roughness.axis.clamp_lo = std::sqrt(kLtcMinAlpha);
    ltc_roughness.meaning = "perceptual roughness r; GGX alpha = max(r^2, 1e-5), as ltc_2";
    AxisSpec ltc_view = cos_theta(64, Placement::endpoints, Warp::square);
    ltc_view.axis.min = 1.0;
    ltc_view.axis.max = 0.0;
    ltc_view.axis.clamp_lo = kLtcMinMu;
    ltc_view.meaning = "cos(theta_o); rows at u = sqrt(1 - cos(theta_o)); mu >= cos(1.57), as ltc_2";
    all.push_back({{"ltc",
                    "Heitz 2016 LTC area-light tables ltc_1, ltc_2 as three.js, EEVEE and Godot load them "
                    "(64x64, rows sqrt(1 - cos theta), columns roughness, end points), refitted, with the "
                    "per-texel error table ltc_ggx_error and the F82-tint moment ltc_f82; the same layout "
                    "fitted to the Charlie sheen with Neubelt's visibility (ltc_sheen_charlie, _norm, _error) "
                    "and with the Estevez-Kulla shadowing (ltc_sheen_charlie_ek, _norm, _error), EON diffuse "
                    "(ltc_eon, _norm, _error) and Zeltner 2022's analytic volumetric sheen (ltc_sheen_zeltner, _norm, "
                    "_error) lobes",
                    PixelType::float32},
                   {{"ltc_f82",
                     "F82-tint moment on ltc_2's grid: an area light on an F82 metal is (F0 (n0 - n1) + n1 - b C) "
                     "times the LTC integral",
                     "selfshadow/ltc_code fit/fitLTC.cpp (ltc_2's grid and clamps); Hoffman 2023, "
                     "\"Generalization of Adobe's Fresnel Model\" (F82-tint)",
                     {ltc_roughness, ltc_view},
                     {{"C: integral of f (v.h) (1 - v.h)^6 cos(theta_i) dw_i (GGX, height-correlated, F = 1)",
                       {{"ggx_dfg_f82", 2}}}},
                     {},
                     ggx_model(Visibility::height_correlated),
                     {checks::f82_moment_half_vector(0)}}}});
    {
        // Mitsuba 3 precomputes roughplastic's transmittance per material, at
        // its alpha and relative index: both are pinned core axes.
        nlohmann::json model = tables::glass_model(Visibility::separable, false);
        model["distribution"] = "GGX (roughplastic with distribution = ggx; Mitsuba's default, beckmann, is not made)";
        model["construction"] = "the exact integral; Mitsuba takes a 32 x 32 Gauss-Legendre rule over the "
                                "visible-normal sample space";
        const std::string mitsuba_ior = "1.4895873842945502";  // 1.49 / 1.000277: polypropylene over air
        all.push_back(
            {{"mitsuba3",
              "Mitsuba 3's roughplastic transmittance table (64 end points in mu, clamped at 1e-6) for one "
              "material: E_T of GGX rough glass, separable G, at --alpha and --ior",
              PixelType::float32},
             {{"mitsuba3_roughplastic_external_transmittance",
               "Mitsuba 3 roughplastic m_external_transmittance: E_T over mu at one material's alpha and index",
               kMitsubaRoughPlasticSource,
               {clamped_low(cos_theta(64, Placement::endpoints), 1e-6)},
               {{"E_T: the fraction of the light arriving along mu that crosses the rough interface",
                 {{"ggx_glass_albedo", 1}}}},
               {{"visibility", "separable"}},
               model,
               {checks::mitsuba_transmittance_visible_normal_rule(0.1, std::stod(mitsuba_ior))},
               std::nullopt,
               {{"alpha", "material roughness: the GGX alpha at which the table holds its core tables' alpha axis, "
                          "0 to 1 (Mitsuba's roughplastic alpha, default 0.1)",
                 "0.1"},
                {"ior", "material index: the relative index n = int_ior / ext_ior at which the table holds its "
                        "core tables' ior axis, 1 or more (Mitsuba's default 1.49 / 1.000277, polypropylene over air)",
                 mitsuba_ior}}}}});
    }
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
}  // namespace preset_family

const std::vector<tables::PresetDeclaration>& tables::preset_declarations() {
    using namespace preset_family;
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
    using namespace preset_family;
    family.families.push_back(
        {"", "Engine presets",
         "The tables engines ship, each exactly in the engine's layout (grid, texel placement, axis warps, "
         "clamps, roughness parameterization, channel order and meaning, visibility term): each is one data "
         "entry, a recipe per stored channel (a linear combination of core tables' channels plus an offset, "
         "or the ratio of two such sums, with the options the core tables take; the metadata records each "
         "channel's expression), evaluated from the core tables themselves, so that compare, verify and "
         "inspect work on them unchanged: Filament's DFG with cloth, Unreal's PreintegratedGF (and the "
         "Karis 2013 course-notes variant) and UE5's glass and cloth energy tables, HDRP's PreIntegratedFGD, Cycles' GGX and rough glass albedo "
         "tables with their clamps, glTF-IBL-Sampler's LUTs, Godot's Forward+ DFG texture (and the Mobile "
         "fit as a table), three.js's DFGLUTData, MaterialX's albedo table, OSL BSDL's GGX energy table, "
         "Babylon.js's environment BRDF, USD Storm's dome-light BRDF, Bevy's DFG LUT and Mitsuba 3's roughplastic "
         "transmittance (one material: its alpha and index are pinned core axes, --alpha and --ior). Each names the "
         "engine source it follows in its metadata; [the engines page](../engines.md) says what each "
         "engine's shipped table holds and how brdflut's compares with it."});
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
