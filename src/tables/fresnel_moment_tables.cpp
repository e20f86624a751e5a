// Fresnel-weighted moments of GGX through the generic lobe path
// (generic_lobe.h, ggx_lobe.h): the split sums with the F82-tint channel
// (f82.h) and their averages, for the F82-tint metal albedo
// E(mu, alpha; F0, b) = F0 A + B - b C, and Blender Cycles'
// generalized-Schlick interpolation tables in Cycles' own layout. The checks
// use a second quadrature over the half vector (ggx_moments_half_vector)
// and the closed forms at alpha = 1 and at normal view.
//
// Kutz et al. 2021, "Novel aspects of the Adobe Standard Material"
// Hoffman 2023, "Generalization of Adobe's Fresnel Model"
#include <cmath>
#include <memory>

#include "brdflut/f82.h"
#include "brdflut/ggx_lobe.h"
#include "brdflut/random.h"
#include "tables/checks.h"
#include "tables/registry.h"

namespace brdflut {
namespace fresnel_moment_family {  // this family's own names, apart from the other families' in a unity build
namespace {

// With an honest estimate below it and float rounding, every stored value is
// within 1e-7 of the exact integral (as the Beckmann tables).
constexpr double kMomentTableTolerance = 1e-8;
constexpr tables::Tolerances kTolerances = tables::quadrature_tolerances(kMomentTableTolerance);

// Alphas below are computed as the mirror limit (the lobe is then within
// 4e-6 rad of the mirror direction; see beckmann_tables.cpp for the same
// bound of the generic path's direction rounding).
constexpr double kMinAlpha = 2e-6;

const char* kQuadratureRule =
    "generic lobe path (generic_lobe.h) over the GGX lobe: wi in polar coordinates about the mirror "
    "direction, theta split at the horizon clip, at the width w = 2 alpha and at aspect w (aspect = "
    "min(1, mu_o + alpha)), adaptive Gauss-Kronrod (10,21) in theta^2 from the peak to aspect w and in "
    "ln(theta) beyond, nested with the azimuth clipped analytically to the "
    "upper hemisphere; averages: adaptive Gauss-Kronrod (10,21) over mu; alpha below 2e-6: the mirror "
    "limit; error per value: QUADPACK estimate plus the integrated inner estimates plus a bound on the "
    "rounding of the directions";
const char* kMcSampler =
    "equal mixture of reflected GGX normals from D cos(theta_h) and the cosine-weighted hemisphere "
    "(Cycles' tables: GGX visible normals, reflected)";

const char* kA = "A: integral of f (1 - (1 - v.h)^5) cos(theta_i) dw_i";
const char* kB = "B: integral of f (1 - v.h)^5 cos(theta_i) dw_i";
const char* kC = "C: integral of f (v.h) (1 - v.h)^6 cos(theta_i) dw_i (the F82-tint term)";

// The weights of the three channels.
constexpr std::array<MomentWeight, 3> kF82Weights = {MomentWeight{moment_weight::one_minus_schlick},
                                                      MomentWeight{moment_weight::schlick},
                                                      MomentWeight{moment_weight::f82}};

nlohmann::json f82_model(Visibility vis) {
    return {{"brdf", "GGX microfacet, single scattering"},
            {"distribution", "ggx"},
            {"visibility", to_string(vis)},
            {"fresnel",
             "F82-tint (Kutz et al. 2021, Hoffman 2023), factored out: F(c) = F0 + (1 - F0)(1 - c)^5 - "
             "b c (1 - c)^6, b = [F0 + (1 - F0)(6/7)^5](1 - tint) 7^7/6^6; E = F0 A + B - b C"},
            {"roughness", "alpha = perceptual_roughness^2"}};
}

// What a table of this family integrates.
enum class Kind {
    f82_dfg,        // (A, B, C) at (mu, alpha)
    f82_dfg_avg,    // their averages at alpha
    cycles_schlick, // Cycles' s over (rough, mu, z): weight (1 - c)^e, e = 5 (1 - z)/z, visible normals
    cycles_ior,     // Cycles' s over (rough, mu, n): the remapped dielectric Fresnel, visible normals
};

double exponent_of_z(double z) { return 5.0 * (1.0 - z) / z; }

class MomentEvaluator final : public TexelEvaluator {
public:
    MomentEvaluator(Kind kind, Visibility vis, const TableSettings& s)
        : kind_(kind), vis_(vis), mc_(s.method == Method::monte_carlo), samples_(s.samples), seed_(s.seed),
          abs_tol_(kTolerances.at(s.quality)) {}

    TexelValue evaluate(const double* c, std::uint64_t texel) const override {
        TexelValue out;
        const std::uint64_t seed = mix_seed(seed_, texel);
        GenericOptions opt;
        opt.abs_tol = abs_tol_;
        const double scale = mc_ ? tables::kMcErrorSigmas : 1.0;
        auto store = [&](const auto& e, std::size_t n) {
            for (std::size_t k = 0; k < n; ++k) {
                out.value[k] = e.value[k];
                out.error[k] = scale * e.error[k];
            }
            out.evaluations = e.evaluations;
        };
        if (kind_ == Kind::f82_dfg_avg) {
            const double alpha = c[0];
            if (!(alpha >= kMinAlpha)) {
                out.value = {20.0 / 21.0, 1.0 / 21.0, 1.0 / 126.0, 0.0};
                return out;
            }
            const GgxLobe lobe(alpha, vis_);
            store(mc_ ? generic_moment_average_mc<3>(lobe, kF82Weights, samples_, seed)
                      : generic_moment_average<3>(lobe, kF82Weights, opt),
                  3);
            return out;
        }
        if (kind_ == Kind::f82_dfg) {
            const double mu = c[0], alpha = c[1];
            if (!(alpha >= kMinAlpha)) {
                for (std::size_t k = 0; k < 3; ++k) out.value[k] = kF82Weights[k](std::clamp(mu, 0.0, 1.0));
                return out;
            }
            const GgxLobe lobe(alpha, vis_);
            store(mc_ ? generic_moments_mc<3>(lobe, mu, kF82Weights, samples_, seed)
                      : generic_moments<3>(lobe, mu, kF82Weights, opt),
                  3);
            return out;
        }
        // Cycles: coordinates (sqrt(alpha) as alpha, mu, z or n).
        const double alpha = c[0], mu = c[1];
        const MomentWeight w = kind_ == Kind::cycles_schlick
                                   ? MomentWeight{moment_weight::schlick_power, exponent_of_z(c[2])}
                                   : MomentWeight{moment_weight::dielectric_remapped, c[2]};
        if (!(alpha >= kMinAlpha)) {  // visible normals all at the normal: the mirror limit
            out.value[0] = w(std::clamp(mu, 0.0, 1.0));
            return out;
        }
        // The weight's cusp or clamp is a cone about wo (weight_view_cones).
        const GgxLobe lobe(alpha, Visibility::height_correlated, GgxLobeKind::vndf);
        store(mc_ ? generic_moments_mc<1>(lobe, mu, {w}, samples_, seed) : generic_moments<1>(lobe, mu, {w}, opt),
              1);
        return out;
    }

private:
    Kind kind_;
    Visibility vis_;
    bool mc_;
    long long samples_;
    std::uint64_t seed_;
    double abs_tol_;
};

TableDefinition make(Kind kind, std::string id, std::string description, std::vector<AxisSpec> axes,
                     std::vector<std::string> channels, nlohmann::json model) {
    TableDefinition d;
    d.id = std::move(id);
    d.description = std::move(description);
    d.axes = std::move(axes);
    d.channels = std::move(channels);
    const bool f82 = kind == Kind::f82_dfg || kind == Kind::f82_dfg_avg;
    if (f82) d.options = {tables::visibility_option()};
    // Cycles' tables are Monte Carlo estimates themselves, but at the ends
    // of their z axes the weight is a rare event for any sampler ((1 - c)^e
    // with e up to 5e4, a dielectric of index 99.5 at grazing view): a
    // standard error from verify's 1e5 draws cannot hold the quadrature
    // there. The tests compare the visible-normal estimate at interior
    // points (test_fresnel_moments.cpp).
    d.supports_monte_carlo = f82;
    // A generic-path integral costs about a millisecond a texel: too much
    // for identify's coarse search; `compare --as` checks files against them.
    d.searched_by_identify = false;
    d.prepare = [kind, f82, model](const TableSettings& s) {
        const Visibility vis = f82 ? visibility_from_string(tables::param(s, "visibility"))
                                   : Visibility::height_correlated;
        PreparedTable p;
        p.evaluator = std::make_unique<MomentEvaluator>(kind, vis, s);
        p.model = f82 ? f82_model(vis) : model;
        p.method = s.method == Method::monte_carlo
                       ? tables::monte_carlo_method(kMcSampler, s)
                       : tables::quadrature_method(kQuadratureRule, kTolerances.at(s.quality));
        return p;
    };
    return d;
}

// ---------------------------------------------------------------------------
// Independent checks: the half-vector quadrature (ggx_lobe.h), and closed
// forms.

// Tolerance of a comparison with the half-vector route (1e-12): the table's
// own and room for rounding.
constexpr double kRouteTol = kMomentTableTolerance + 1e-11;

ClosedFormCheck f82_dfg_half_vector() {
    return {"A, B, C vs the half-vector quadrature (u = t^2/(alpha^2 + t^2), azimuth clipped exactly)", kRouteTol,
            [](const TexelEvaluator& e) {
                return tables::worst_error(
                    e, tables::grid_points({0.02, 0.3, 0.75, 1.0}, {0.01, 0.2, 0.65}),
                    [](const TexelValue& v, const auto& p) {
                        const auto r = ggx_moments_half_vector<3>(p[0], p[1], Visibility::height_correlated,
                                                                  GgxLobeKind::brdf, kF82Weights);
                        double worst = 0.0;
                        for (std::size_t k = 0; k < 3; ++k) worst = std::max(worst, std::abs(v.value[k] - r[k]));
                        return worst;
                    });
            }};
}

ClosedFormCheck f82_dfg_alpha_one() {
    return {"A + B at alpha = 1 vs 1 - mu ln(1 + 1/mu)", 2 * kMomentTableTolerance + 1e-12,
            [](const TexelEvaluator& e) {
                return tables::worst_error(e, tables::grid_points({0.01, 0.25, 0.5, 0.9, 1.0}, {1.0}),
                                           [](const TexelValue& v, const auto& p) {
                                               return v.value[0] + v.value[1] - tables::ggx_albedo_alpha_one(p[0]);
                                           });
            }};
}

ClosedFormCheck f82_avg_alpha_one() {
    return {"A_avg + B_avg at alpha = 1 vs (4/3)(1 - ln 2)", 2 * kMomentTableTolerance + 1e-12,
            [](const TexelEvaluator& e) {
                return tables::worst_error(e, tables::points_1d({1.0}), [](const TexelValue& v, const auto&) {
                    return v.value[0] + v.value[1] - tables::ggx_albedo_avg_alpha_one();
                });
            }};
}

// The averages by Gauss-Legendre over mu of the half-vector route (the
// moments are smooth in mu at alpha >= 0.3; 48 nodes in mu = v^2 reach
// 1e-11 there).
ClosedFormCheck f82_avg_half_vector() {
    return {"A_avg, B_avg, C_avg vs 48-point Gauss-Legendre in mu = v^2 of the half-vector quadrature",
            2 * kMomentTableTolerance + 1e-10, [](const TexelEvaluator& e) {
                return tables::worst_error(e, tables::points_1d({0.3, 0.6}), [](const TexelValue& v, const auto& p) {
                    const std::array<double, 3> r = integrate_gauss<3>(
                        [&](double s) {
                            const double mu = s * s;
                            auto m = ggx_moments_half_vector<3>(mu, p[0], Visibility::height_correlated,
                                                                GgxLobeKind::brdf, kF82Weights, 1e-12);
                            for (double& x : m) x *= 4.0 * mu * s;
                            return m;
                        },
                        0.0, 1.0, 48);
                    double worst = 0.0;
                    for (std::size_t k = 0; k < 3; ++k) worst = std::max(worst, std::abs(v.value[k] - r[k]));
                    return worst;
                });
            }};
}

// Cycles' tables: axes (alpha, mu, z or n).
ClosedFormCheck cycles_half_vector(bool ior) {
    return {"s vs the half-vector quadrature over visible normals", kRouteTol, [ior](const TexelEvaluator& e) {
                std::vector<std::array<double, 3>> pts;
                for (double alpha : {0.01, 0.2, 0.7})
                    for (double mu : {0.05, 0.5, 1.0})
                        for (double z : ior ? std::vector<double>{1.1, 1.5, 3.0} : std::vector<double>{0.1, 0.5, 0.9})
                            pts.push_back({alpha, mu, z});
                return tables::worst_over(e, pts, 0, [ior](const auto& p) {
                    const MomentWeight w = ior ? MomentWeight{moment_weight::dielectric_remapped, p[2]}
                                               : MomentWeight{moment_weight::schlick_power, exponent_of_z(p[2])};
                    return ggx_moments_half_vector<1>(p[1], p[0], Visibility::height_correlated, GgxLobeKind::vndf,
                                                      {w})[0];
                });
            }};
}

// At normal view and exponent 0 (z = 1) s is the share of visible normals
// whose reflection stays above the horizon, theta_h < 45 degrees:
// 1 / (1 + alpha^2).
ClosedFormCheck cycles_normal_share() {
    return {"s at mu = 1, z = 1 (e = 0) vs 1 / (1 + alpha^2)", kMomentTableTolerance + 1e-12,
            [](const TexelEvaluator& e) {
                std::vector<std::array<double, 3>> pts;
                for (double alpha : {0.05, 0.3, 0.6, 1.0}) pts.push_back({alpha, 1.0, 1.0});
                return tables::worst_over(e, pts, 0, [](const auto& p) { return 1.0 / (1.0 + p[0] * p[0]); });
            }};
}

// Cycles' axes (cycles_precompute.cpp): x = rough = sqrt(alpha), clamped
// to [1e-4, 1]; y = mu clamped to [1e-4, 1]; z clamped to [1e-4, 0.99]; end
// points, 16 each.
AxisSpec cycles_rough() {
    AxisSpec a = tables::alpha_axis(16);
    a.axis.placement = Placement::endpoints;
    a.axis.clamp_lo = 1e-8;  // rough 1e-4
    a.axis.clamp_hi = 1.0;
    return a;
}
AxisSpec cycles_mu() {
    AxisSpec a = tables::cos_theta_axis(16);
    a.axis.placement = Placement::endpoints;
    a.axis.clamp_lo = 1e-4;
    a.axis.clamp_hi = 1.0;
    return a;
}
AxisSpec cycles_schlick_z() {
    return {Axis{"schlick_z", 0.0, 1.0, 16, Placement::endpoints, Warp::linear, false, 0.0, 1e-4, 0.99}, 1e-6, 1.0,
            "z = 1/(1 + e/5): the generalized-Schlick exponent e = 5 (1 - z)/z (z = 0.5: e = 5, the metals' slice)"};
}
AxisSpec cycles_ior_z() {
    const auto z_of = [](double z) { return (1.0 + z * z) / (1.0 - z * z); };
    AxisSpec a = tables::ior_axis(16);
    a.axis.placement = Placement::endpoints;
    a.axis.min = 1.0;
    a.axis.max = HUGE_VAL;
    a.axis.clamp_lo = z_of(1e-4);
    a.axis.clamp_hi = z_of(0.99);
    return a;
}

nlohmann::json cycles_model(bool ior) {
    return {{"brdf", "GGX visible normals (Heitz 2018), reflection above the horizon"},
            {"distribution", "ggx"},
            {"integral",
             "s = integral over visible normals h of D_wo(h) w(v.h) [reflection above the horizon] dh, "
             "D_wo = G1(mu_o) max(0, v.h) D(h) / mu_o: the mean of w over a visible-normal sampler's "
             "draws, those below the horizon counting 0"},
            {"fresnel", ior ? "w = (F(v.h, n) - F0(n)) / (1 - F0(n)), the exact dielectric Fresnel remapped from "
                              "F0 to F90 (Fresnel = mix(F0', F90, s))"
                            : "w = (1 - v.h)^e, generalized Schlick (Fresnel = mix(F0, F90, s))"},
            {"roughness", "alpha = rough^2"},
            {"preset", "cycles"},
            {"engine_source",
             "blender/blender intern/cycles/app/cycles_precompute.cpp (precompute_ggx_gen_schlick_s), "
             "kernel/closure/bsdf_microfacet.h (bsdf_microfacet_estimate_albedo)"}};
}

}  // namespace
}  // namespace fresnel_moment_family

void register_fresnel_moment_family(FamilyEntries& family) {
    using namespace fresnel_moment_family;
    family.families.push_back(
        {"", "Fresnel-weighted GGX moments",
         "Moments of the GGX lobe under the Fresnel weights engines factor out of their tables, computed "
         "through the generic lobe path (no GGX-specific quadrature) and checked against a second quadrature "
         "over the half vector. The F82-tint Fresnel of metals (Kutz et al. 2021, Hoffman 2023), "
         "F(c) = F0 + (1 - F0)(1 - c)^5 - b c (1 - c)^6 with b = [F0 + (1 - F0)(6/7)^5](1 - tint) 7^7/6^6, "
         "is linear in F0 and b, so its albedo is E = F0 A + B - b C: `ggx_dfg_f82` holds the split sums A, "
         "B and the F82 moment C (EEVEE's `metal_bias`), `ggx_dfg_f82_avg` their averages (OpenPBR's energy "
         "compensation). Blender Cycles' `table_ggx_gen_schlick_s` and `table_ggx_gen_schlick_ior_s` are the "
         "mean of the weight (1 - c)^e, or of the dielectric Fresnel remapped from F0 to F90, over GGX visible "
         "normals (a draw reflected below the horizon counts 0), in Cycles' layout: these are not the ratio "
         "B/(A + B) of the split sums."});
    std::vector<TableDefinition>& out = family.tables;
    const nlohmann::json none;
    TableDefinition dfg = make(Kind::f82_dfg, "ggx_dfg_f82",
                               "GGX split sums A, B and the F82-tint moment C: E = F0 A + B - b C",
                               {tables::cos_theta_axis(64), tables::alpha_axis(64)}, {kA, kB, kC}, none);
    dfg.checks = {f82_dfg_alpha_one(), f82_dfg_half_vector()};
    out.push_back(std::move(dfg));
    TableDefinition avg = make(Kind::f82_dfg_avg, "ggx_dfg_f82_avg",
                               "Averages 2 * integral of (A, B, C)(mu) mu dmu: E_avg = F0 A_avg + B_avg - b C_avg",
                               {tables::alpha_axis(32)},
                               {"A_avg: 2 * integral of A(mu) mu dmu", "B_avg: 2 * integral of B(mu) mu dmu",
                                "C_avg: 2 * integral of C(mu) mu dmu"},
                               none);
    avg.checks = {f82_avg_alpha_one(), f82_avg_half_vector()};
    out.push_back(std::move(avg));
    TableDefinition s = make(Kind::cycles_schlick, "cycles_ggx_gen_schlick_s",
                             "Cycles table_ggx_gen_schlick_s: mean of (1 - v.h)^e over GGX visible normals, "
                             "x = sqrt(alpha), y = mu, z = 1/(1 + e/5)",
                             {cycles_rough(), cycles_mu(), cycles_schlick_z()},
                             {"s: F0 -> F90 interpolation factor of the generalized Schlick Fresnel"},
                             cycles_model(false));
    s.preset = "cycles";
    s.engine_source = cycles_model(false).at("engine_source").get<std::string>();
    s.checks = {cycles_normal_share(), cycles_half_vector(false)};
    out.push_back(std::move(s));
    TableDefinition si = make(Kind::cycles_ior, "cycles_ggx_gen_schlick_ior_s",
                              "Cycles table_ggx_gen_schlick_ior_s: mean of the remapped dielectric Fresnel over GGX "
                              "visible normals, x = sqrt(alpha), y = mu, z = sqrt((n-1)/(n+1))",
                              {cycles_rough(), cycles_mu(), cycles_ior_z()},
                              {"s: F0 -> F90 interpolation factor following the dielectric Fresnel of index n"},
                              cycles_model(true));
    si.preset = "cycles";
    si.engine_source = cycles_model(true).at("engine_source").get<std::string>();
    si.checks = {cycles_half_vector(true)};
    out.push_back(std::move(si));
}

}  // namespace brdflut
