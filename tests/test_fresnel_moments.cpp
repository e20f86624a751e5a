// Fresnel-weighted GGX moments (fresnel_moment_tables.cpp): the weights'
// closed forms, the generic path against the half-vector quadrature and the
// GGX fast kernels, Monte Carlo, thread independence, and the presets'
// layouts (EEVEE's brdf_ggx, Cycles' generalized-Schlick tables).
#include <gtest/gtest.h>

#include <cmath>

#include "brdflut/catalogue.h"
#include "brdflut/exr.h"
#include "brdflut/f82.h"
#include "brdflut/fresnel.h"
#include "brdflut/generate.h"
#include "brdflut/ggx_lobe.h"
#include "brdflut/quadrature.h"
#include "test_support.h"

using namespace brdflut;
using brdflut::test::TempDir;

namespace {

constexpr std::array<MomentWeight, 3> kF82Weights = {MomentWeight{moment_weight::one_minus_schlick},
                                                      MomentWeight{moment_weight::schlick},
                                                      MomentWeight{moment_weight::f82}};

TableSettings sized(const std::string& id, std::vector<int> counts) {
    TableSettings s = default_settings(find_table(id));
    for (std::size_t i = 0; i < s.axes.size(); ++i) s.axes[i].count = counts[i];
    return s;
}

}  // namespace

TEST(F82Tint, FresnelMeetsItsDefinitionAndItsAverageClosedForm) {
    for (double f0 : {0.04, 0.5, 0.95})
        for (double tint : {0.2, 0.8, 1.0}) {
            const double b = f82_tint_b(f0, tint);
            const double schlick = f0 + (1.0 - f0) * std::pow(6.0 / 7.0, 5);
            // F(1/7) = tint * Schlick(1/7); F(1) = F0 and F(0) = 1 (the term vanishes at both ends).
            EXPECT_NEAR(f82_tint_fresnel(1.0 / 7.0, f0, b), tint * schlick, 1e-14);
            EXPECT_DOUBLE_EQ(f82_tint_fresnel(1.0, f0, b), f0);
            EXPECT_DOUBLE_EQ(f82_tint_fresnel(0.0, f0, b), 1.0);
            const double avg = integrate_gauss<1>(
                [&](double mu) { return std::array<double, 1>{2.0 * mu * f82_tint_fresnel(mu, f0, b)}; }, 0.0, 1.0,
                8)[0];  // a polynomial of degree 8: exact
            EXPECT_NEAR(avg, f82_tint_average(f0, b), 1e-14);
        }
    EXPECT_EQ(moment_weight::f82(0.0, 0.0), 0.0);
    EXPECT_EQ(moment_weight::f82(1.0, 0.0), 0.0);
    // c (1 - c)^6 peaks at c = 1/7.
    EXPECT_GT(moment_weight::f82(1.0 / 7.0, 0.0), moment_weight::f82(1.0 / 7.0 + 1e-3, 0.0));
    EXPECT_GT(moment_weight::f82(1.0 / 7.0, 0.0), moment_weight::f82(1.0 / 7.0 - 1e-3, 0.0));
}

TEST(F82Tint, RemappedDielectricFresnelRunsFromZeroToOne) {
    for (double eta : {1.1, 1.5, 3.0}) {
        EXPECT_NEAR(moment_weight::dielectric_remapped(1.0, eta), 0.0, 1e-15);
        EXPECT_NEAR(moment_weight::dielectric_remapped(0.0, eta), 1.0, 1e-15);
        const double f0 = std::pow((eta - 1.0) / (eta + 1.0), 2);
        EXPECT_NEAR(moment_weight::dielectric_remapped(0.4, eta), (fresnel_dielectric(0.4, eta) - f0) / (1.0 - f0),
                    1e-15);
    }
    EXPECT_EQ(moment_weight::dielectric_remapped(0.3, 1.0), 0.0);
}

TEST(FresnelMoments, GenericPathMatchesTheHalfVectorQuadratureForAnyWeight) {
    // Weights and points the tables' checks do not use.
    const std::array<MomentWeight, 3> weights = {MomentWeight{moment_weight::schlick_power, 2.5},
                                                 MomentWeight{moment_weight::f82},
                                                 MomentWeight{moment_weight::dielectric_remapped, 1.45}};
    for (GgxLobeKind kind : {GgxLobeKind::brdf, GgxLobeKind::vndf})
        for (Visibility vis : {Visibility::height_correlated, Visibility::separable})
            for (double alpha : {0.004, 0.13, 0.9})
                for (double mu : {0.003, 0.37, 0.96}) {
                    GenericOptions opt;
                    opt.abs_tol = 1e-10;
                    const Estimate<3> g = generic_moments<3>(GgxLobe(alpha, vis, kind), mu, weights, opt);
                    const auto r = ggx_moments_half_vector<3>(mu, alpha, vis, kind, weights);
                    for (std::size_t k = 0; k < 3; ++k)
                        EXPECT_NEAR(g.value[k], r[k], 1e-9) << "alpha " << alpha << " mu " << mu << " weight " << k;
                }
}

TEST(FresnelMoments, ExponentZeroIsTheAlbedoAndFiveIsTheSplitSumBias) {
    // Through the generic path with (1 - c)^e, against the GGX fast kernels
    // (ggx_albedo, ggx_dfg's B), a route that shares no code with it.
    const std::array<MomentWeight, 2> weights = {MomentWeight{moment_weight::schlick_power, 0.0},
                                                 MomentWeight{moment_weight::schlick_power, 5.0}};
    const Table e = generate(find_table("ggx_albedo"), sized("ggx_albedo", {5, 4}));
    const Table dfg = generate(find_table("ggx_dfg"), sized("ggx_dfg", {5, 4}));
    for (std::size_t t = 0; t < e.texel_count(); ++t) {
        const double mu = e.axes[0].value(static_cast<int>(t % 5)), alpha = e.axes[1].value(static_cast<int>(t / 5));
        GenericOptions opt;
        opt.abs_tol = 1e-10;
        const Estimate<2> g = generic_moments<2>(GgxLobe(alpha, Visibility::height_correlated), mu, weights, opt);
        EXPECT_NEAR(g.value[0], e.at(t, 0), 2e-8) << mu << " " << alpha;
        EXPECT_NEAR(g.value[1], dfg.at(t, 1), 2e-8) << mu << " " << alpha;
    }
}

TEST(FresnelMoments, F82TableAgreesWithTheFastKernelsAndTheHalfVectorRouteAtItsTexels) {
    // Stored values (float) at every texel of small grids, against the GGX
    // fast kernels for A and B and the half-vector quadrature for all three.
    for (const std::string vis : {"height_correlated", "separable"}) {
        TableSettings s = sized("ggx_dfg_f82", {5, 4});
        s.params["visibility"] = vis;
        TableSettings d = sized("ggx_dfg", {5, 4});
        d.params["visibility"] = vis;
        const Table f82 = generate(find_table("ggx_dfg_f82"), s);
        const Table dfg = generate(find_table("ggx_dfg"), d);
        for (std::size_t t = 0; t < f82.texel_count(); ++t) {
            const double mu = f82.axes[0].value(static_cast<int>(t % 5));
            const double alpha = f82.axes[1].value(static_cast<int>(t / 5));
            const auto r = ggx_moments_half_vector<3>(mu, alpha, visibility_from_string(vis), GgxLobeKind::brdf,
                                                      kF82Weights);
            for (int k = 0; k < 3; ++k) {
                const double stored = static_cast<float>(f82.at(t, k));
                EXPECT_NEAR(stored, r[static_cast<std::size_t>(k)], 1e-7)
                    << vis << " " << mu << " " << alpha << " " << k;
                if (k < 2) {
                    EXPECT_NEAR(f82.at(t, k), dfg.at(t, k), 2e-8) << vis << " " << mu << " " << alpha;
                }
            }
        }
    }
}

TEST(FresnelMoments, CyclesTablesAgreeWithTheHalfVectorRouteAtHeldOutTexels) {
    // Cycles' own grid (end points, clamps): the interior texels of a 16^3
    // table that the checks do not visit, stored as float.
    for (const std::string id : {"cycles_ggx_gen_schlick_s", "cycles_ggx_gen_schlick_ior_s"}) {
        const TableDefinition& def = find_table(id);
        const TableSettings s = default_settings(def);
        const auto evaluator = def.prepare(s).evaluator;
        const bool ior = id == "cycles_ggx_gen_schlick_ior_s";
        for (int i : {3, 9, 14})
            for (int j : {0, 6, 11})
                for (int k : {2, 8, 15}) {
                    const double c[3] = {s.axes[0].value(i), s.axes[1].value(j), s.axes[2].value(k)};
                    const double stored = static_cast<float>(evaluator->evaluate(c, 0).value[0]);
                    const MomentWeight w = ior ? MomentWeight{moment_weight::dielectric_remapped, c[2]}
                                               : MomentWeight{moment_weight::schlick_power, 5.0 * (1.0 - c[2]) / c[2]};
                    const double r = ggx_moments_half_vector<1>(c[1], c[0], Visibility::height_correlated,
                                                                GgxLobeKind::vndf, {w})[0];
                    EXPECT_NEAR(stored, r, 1e-7) << id << " at " << i << "," << j << "," << k;
                }
    }
}

TEST(FresnelMoments, CyclesExponentAxisAndMirrorColumn) {
    const TableDefinition& def = find_table("cycles_ggx_gen_schlick_s");
    const TableSettings s = default_settings(def);
    // z = i/15 clamped to [1e-4, 0.99]: e = 5 at the middle is not on the
    // grid (16 end points), the first is 5 (1 - 1e-4)/1e-4, the last 5 (0.01/0.99).
    EXPECT_DOUBLE_EQ(s.axes[2].value(0), 1e-4);
    EXPECT_DOUBLE_EQ(s.axes[2].value(15), 0.99);
    // rough 0 is clamped to 1e-4 (alpha 1e-8): Cycles treats it as a mirror,
    // s = (1 - mu)^e.
    EXPECT_DOUBLE_EQ(s.axes[0].value(0), 1e-8);
    const auto ev = def.prepare(s).evaluator;
    const double c[3] = {1e-8, 0.4, 0.5};
    EXPECT_NEAR(ev->evaluate(c, 0).value[0], std::pow(0.6, 5.0), 1e-15);
}

TEST(FresnelMoments, MonteCarloAgreesWithinFourStandardErrors) {
    for (const auto& [mu, alpha] : std::vector<std::pair<double, double>>{{0.02, 0.05}, {0.5, 0.4}, {0.9, 0.9}}) {
        for (GgxLobeKind kind : {GgxLobeKind::brdf, GgxLobeKind::vndf}) {
            const GgxLobe lobe(alpha, Visibility::height_correlated, kind);
            const std::array<MomentWeight, 3> weights = {MomentWeight{moment_weight::f82},
                                                         MomentWeight{moment_weight::schlick_power, 12.0},
                                                         MomentWeight{moment_weight::dielectric_remapped, 1.5}};
            GenericOptions opt;
            opt.abs_tol = 1e-10;
            const Estimate<3> q = generic_moments<3>(lobe, mu, weights, opt);
            const Estimate<3> m = generic_moments_mc<3>(lobe, mu, weights, 1 << 18, 7);
            for (std::size_t k = 0; k < 3; ++k) {
                EXPECT_GT(m.error[k], 0.0);
                EXPECT_LE(std::abs(q.value[k] - m.value[k]), 4.0 * m.error[k] + 1e-12)
                    << "mu " << mu << " alpha " << alpha << " weight " << k;
            }
        }
    }
    // The averages.
    const GgxLobe lobe(0.3, Visibility::height_correlated);
    const Estimate<3> q = generic_moment_average<3>(lobe, kF82Weights);
    const Estimate<3> m = generic_moment_average_mc<3>(lobe, kF82Weights, 1 << 18, 9);
    for (std::size_t k = 0; k < 3; ++k) EXPECT_LE(std::abs(q.value[k] - m.value[k]), 4.0 * m.error[k]) << k;
}

TEST(FresnelMoments, SameBytesForOneAndTwoThreads) {
    TempDir dir;
    for (const std::string id : {"ggx_dfg_f82", "ggx_dfg_f82_avg", "cycles_ggx_gen_schlick_s",
                                 "cycles_ggx_gen_schlick_ior_s", "eevee_brdf_ggx"}) {
        TableSettings s = default_settings(find_table(id));
        for (Axis& a : s.axes) a.count = std::min(a.count, 6);
        for (int threads : {1, 2})
            write_exr(dir / (id + std::to_string(threads) + ".exr"), test::generate_fresh(find_table(id), s, threads),
                      PixelType::float32);
        const std::string a = test::read_file(dir / (id + "1.exr"));
        EXPECT_FALSE(a.empty());
        EXPECT_EQ(a, test::read_file(dir / (id + "2.exr"))) << id;
    }
}

TEST(FresnelMoments, EeveeLayoutReadsTheF82TableAtItsCoordinates) {
    const TableDefinition& def = find_table("eevee_brdf_ggx");
    EXPECT_EQ(def.preset, "eevee");
    const TableSettings s = default_settings(def);
    ASSERT_EQ(s.axes.size(), 2u);
    EXPECT_EQ(s.axes[0].count, 64);
    EXPECT_EQ(s.axes[1].count, 64);
    // y = j/63, cos(theta) = 1 - y^2 clamped to [1e-4, 0.9999].
    EXPECT_DOUBLE_EQ(s.axes[1].value(0), 0.9999);
    EXPECT_DOUBLE_EQ(s.axes[1].value(63), 1e-4);
    EXPECT_NEAR(s.axes[1].value(21), 1.0 - std::pow(21.0 / 63.0, 2), 1e-15);
    // Texel (x = 40, y = 21): roughness 40/63, alpha its square, separable G.
    const auto ev = def.prepare(s).evaluator;
    const double r = s.axes[0].value(40), mu = s.axes[1].value(21);
    const double c[2] = {r, mu};
    const TexelValue v = ev->evaluate(c, 0);
    const auto ref = ggx_moments_half_vector<3>(mu, r * r, Visibility::separable, GgxLobeKind::brdf, kF82Weights);
    for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(v.value[k], ref[k], 2e-8) << k;
}
