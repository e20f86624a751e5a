// Charlie sheen with the Estevez-Kulla shadowing (charlie_ek.h), its tables
// through the generic lobe path and the engine tables built on them, against
// the paper's constants, the half-vector rule, the Neubelt quadrature of
// sheen_integrals.h and Monte Carlo.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "brdflut/catalogue.h"
#include "brdflut/charlie_ek.h"
#include "brdflut/exr.h"
#include "brdflut/generate.h"
#include "brdflut/generic_lobe.h"
#include "brdflut/sheen_integrals.h"
#include "brdflut/verify.h"
#include "brdflut/ltc_fit.h"
#include "tables/ltc_tables.h"
#include "tables/sheen_charlie_check.h"
#include "test_support.h"

using namespace brdflut;

namespace {

TexelValue texel(const std::string& id, std::vector<double> coords, SheenShadowing s = SheenShadowing::estevez_kulla,
                 Quality q = Quality::standard) {
    const TableDefinition& d = find_table(id);
    TableSettings st = default_settings(d);
    st.quality = q;
    if (!d.options.empty()) st.params["sheen_shadowing"] = to_string(s);
    return d.prepare(st).evaluator->evaluate(coords.data(), 0);
}

// The paper's fit, typed from the paper: (a, b, c, d, e) at r = 0 and r = 1.
double paper_L(double x, const double (&p)[5]) { return p[0] / (1.0 + p[1] * std::pow(x, p[2])) + p[3] * x + p[4]; }
constexpr double kAtZero[5] = {25.3245, 3.32435, 0.16801, -1.27393, -4.85967};
constexpr double kAtOne[5] = {21.5473, 3.82987, 0.19823, -1.97760, -4.32054};

}  // namespace

TEST(EstevezKulla, FitIsThePapersAtBothEndsAndInterpolatesInOneMinusRSquared) {
    for (double x : {0.0, 0.1, 0.3, 0.5}) {
        EXPECT_NEAR(EstevezKullaFit(0.0).L(x), paper_L(x, kAtZero), 1e-13) << x;
        EXPECT_NEAR(EstevezKullaFit(1.0).L(x), paper_L(x, kAtOne), 1e-13) << x;
        // HDRP's CharlieL: lerp(fit at 0, fit at 1, 1 - (1 - r)^2), coefficient by coefficient.
        const double r = 0.35, w = 1.0 - (1.0 - r) * (1.0 - r);
        double p[5];
        for (int i = 0; i < 5; ++i) p[i] = kAtZero[i] + (kAtOne[i] - kAtZero[i]) * w;
        EXPECT_NEAR(EstevezKullaFit(r).L(x), paper_L(x, p), 1e-12) << x;
    }
}

TEST(EstevezKulla, LambdaIsContinuousWithItsSlopeAtOneHalf) {
    for (double alpha : {0.0, 0.2, 0.7, 1.0}) {
        const double h = 1e-6, m = 0.5;
        const double at = EstevezKullaFit(alpha).lambda(m);
        EXPECT_NEAR(EstevezKullaFit(alpha).lambda(std::nextafter(m, 0.0)), at, 1e-12 * at) << alpha;
        // One-sided slopes on either side agree (C1); the second branch
        // reflects L about 1/2.
        const double left = (at - EstevezKullaFit(alpha).lambda(m - h)) / h;
        const double right = (EstevezKullaFit(alpha).lambda(m + h) - at) / h;
        EXPECT_NEAR(left, right, 1e-4 * std::abs(left)) << alpha;
        // Lambda decreases with mu: more shadowing at grazing angles.
        EXPECT_GT(EstevezKullaFit(alpha).lambda(0.1), EstevezKullaFit(alpha).lambda(0.9));
    }
}

TEST(EstevezKulla, TerminatorSofteningActsOnTheLightOnly) {
    for (double alpha : {0.1, 0.6}) {
        // No change at normal incidence; Lambda^(1 + 2 (1 - mu)^8) elsewhere.
        EXPECT_DOUBLE_EQ(EstevezKullaFit(alpha).lambda_light(1.0, true), EstevezKullaFit(alpha).lambda(1.0));
        const double mu = 0.2, l = EstevezKullaFit(alpha).lambda(mu);
        EXPECT_NEAR(EstevezKullaFit(alpha).lambda_light(mu, true), std::pow(l, 1.0 + 2.0 * std::pow(0.8, 8)),
                    1e-12 * std::pow(l, 1.4));
        const Vec3 a = direction_from_mu(0.3), b{-std::sqrt(1.0 - 0.64), 0.0, 0.8};
        const CharlieLobe plain(alpha, SheenShadowing::estevez_kulla), soft(alpha, SheenShadowing::estevez_kulla_soft);
        EXPECT_NEAR(plain.f(a, b), plain.f(b, a), 1e-14 * plain.f(a, b)) << "reciprocal without softening";
        EXPECT_GT(std::abs(soft.f(a, b) - soft.f(b, a)), 1e-6 * soft.f(a, b)) << "not reciprocal with it";
    }
}

// The tables' route over the half vector (sheen_charlie_moments) against the
// generic lobe path, which integrates the BRDF over wi in polar coordinates
// about the normal: every shadowing, from the smallest alpha and view cosine
// the tables compute at, each within the two estimates, and each estimate
// within the tables' tolerance.
TEST(SheenCharlieTables, HalfVectorRouteAgreesWithTheGenericPathForEveryShadowing) {
    const std::array<MomentWeight, 2> weights = {MomentWeight{moment_weight::one}, MomentWeight{moment_weight::schlick}};
    GenericOptions tight;
    tight.abs_tol = 1e-11;
    tight.max_intervals = 2000;
    double worst = 0.0;
    for (SheenShadowing s : {SheenShadowing::estevez_kulla, SheenShadowing::estevez_kulla_soft, SheenShadowing::neubelt})
        for (double alpha : {1e-5, 0.002, 0.07, 1.0})
            for (double mu : {1e-4, 0.004, 0.12, 0.5, 1.0}) {
                const Estimate<2> h = sheen_charlie_moments(mu, alpha, s, 1e-8);
                const Estimate<2> g = generic_moments<2>(CharlieLobe(alpha, s), mu, weights, tight);
                for (std::size_t c = 0; c < 2; ++c) {
                    const double err = std::abs(h.value[c] - g.value[c]);
                    EXPECT_LE(err, h.error[c] + g.error[c])
                        << to_string(s) << " mu " << mu << " alpha " << alpha << " channel " << c;
                    EXPECT_LE(h.error[c], 1e-8 * std::max(1.0, h.value[c])) << to_string(s) << " " << mu << " " << alpha;
                    worst = std::max(worst, err);
                }
            }
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", worst);
    RecordProperty("worst_difference_to_the_generic_path", text);
}

TEST(SheenCharlieTables, NeubeltVariantIsTheSheenQuadrature) {
    // Down to the smallest alpha of the default grid, (0.5/128)^2.
    for (double alpha : {1.53e-5, 0.01, 0.1, 0.5, 1.0})
        for (double mu : {0.5 / 128, 0.3, 0.8, 1.0}) {
            const TexelValue t = texel("sheen_charlie_moments", {mu, alpha}, SheenShadowing::neubelt);
            const Estimate<1> q = sheen_charlie_albedo(mu, alpha);
            EXPECT_NEAR(t.value[0], q.value[0], t.error[0] + q.error[0] + 1e-12) << "mu " << mu << " alpha " << alpha;
        }
}

TEST(SheenCharlieTables, HeldOutTexelsMatchTheHalfVectorRuleWithin1e7) {
    // Off every default grid, down to the smallest alpha and grazing view.
    double worst = 0.0;
    for (SheenShadowing s : {SheenShadowing::estevez_kulla, SheenShadowing::estevez_kulla_soft})
        for (double alpha : {0.0021, 0.083, 0.83})
            for (double mu : {0.0043, 0.31, 0.97}) {
                const TexelValue v = texel("sheen_charlie_moments", {mu, alpha}, s);
                const std::array<double, 2> ref = tables::charlie_moments_by_half_vector(mu, alpha, s);
                for (int c = 0; c < 2; ++c) {
                    const double err = std::abs(v.value[c] - ref[c]);
                    EXPECT_LE(err, v.error[c] + 1e-10) << to_string(s) << " mu " << mu << " alpha " << alpha << " c " << c;
                    // 1e-7 for values up to 1, relative above (float's precision).
                    const double scale = std::max(1.0, std::abs(v.value[c]));
                    EXPECT_LE(err + std::abs(double(float(v.value[c])) - v.value[c]), 1e-7 * scale);
                    EXPECT_LE(v.error[c], 1e-8 * scale);
                    worst = std::max(worst, err);
                }
                EXPECT_DOUBLE_EQ(v.value[2], v.value[0] / (1.0 + v.value[0]));
            }
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", worst);
    RecordProperty("worst_error_vs_half_vector_rule", text);
}

TEST(SheenCharlieTables, MonteCarloAgreesAtGrazingViewAndTheSmallestRoughness) {
    std::uint64_t seed = 11;
    for (SheenShadowing s : {SheenShadowing::estevez_kulla, SheenShadowing::estevez_kulla_soft, SheenShadowing::neubelt})
        for (double alpha : {1e-3, 0.05, 0.6})
            for (double mu : {0.5 / 128, 0.4, 1.0}) {
                const Estimate<2> mc = generic_moments_mc<2>(
                    CharlieLobe(alpha, s), mu,
                    {MomentWeight{moment_weight::one}, MomentWeight{moment_weight::schlick}}, 40000, ++seed);
                const TexelValue q = texel("sheen_charlie_moments", {mu, alpha}, s);
                for (int c = 0; c < 2; ++c)
                    EXPECT_NEAR(mc.value[c], q.value[c], 4.0 * mc.error[c] + q.error[c] + 1e-12)
                        << to_string(s) << " alpha " << alpha << " mu " << mu << " channel " << c;
            }
    const Estimate<2> avg = generic_moment_average_mc<2>(
        CharlieLobe(0.3, SheenShadowing::estevez_kulla),
        {MomentWeight{moment_weight::one}, MomentWeight{moment_weight::schlick}}, 40000, 5);
    const TexelValue q = texel("sheen_charlie_moments_avg", {0.3});
    for (int c = 0; c < 2; ++c) EXPECT_NEAR(avg.value[c], q.value[c], 4.0 * avg.error[c] + q.error[c]) << c;
}

TEST(SheenCharlieTables, ErrorEstimatesCoverTheDifferenceToReferenceQuality) {
    for (double alpha : {0.0, 1e-3, 0.02, 1.0})
        for (double mu : {0.0, 0.5 / 128, 0.6}) {
            const TexelValue s = texel("sheen_charlie_moments", {mu, alpha});
            const TexelValue r = texel("sheen_charlie_moments", {mu, alpha}, SheenShadowing::estevez_kulla,
                                       Quality::reference);
            for (int c = 0; c < 2; ++c)
                EXPECT_LE(std::abs(s.value[c] - r.value[c]), s.error[c] + r.error[c] + 1e-14)
                    << "alpha " << alpha << " mu " << mu << " channel " << c;
        }
    // alpha = 0 is the limit 0; below 1e-4 the view is taken at 1e-4.
    EXPECT_EQ(texel("sheen_charlie_moments", {0.5, 0.0}).value[0], 0.0);
    EXPECT_EQ(texel("sheen_charlie_moments", {0.0, 0.4}).value[0], texel("sheen_charlie_moments", {1e-4, 0.4}).value[0]);
}

TEST(SheenCharlieTables, FabricLambertAlbedoIsOneMinusHalfAlpha) {
    for (double alpha : {0.0, 0.3, 1.0})
        for (double mu : {0.01, 0.7}) EXPECT_NEAR(texel("fabric_lambert_albedo", {mu, alpha}).value[0], 1.0 - 0.5 * alpha, 1e-9);
}

TEST(SheenCharlieTables, IndependentChecksPassAndCatchAWrongTable) {
    struct Wrong : TexelEvaluator {
        TexelValue evaluate(const double*, std::uint64_t) const override {
            TexelValue v;
            v.value = {0.25, 0.05, 0.5, 0.5};
            return v;
        }
    } wrong;
    for (const std::string id : {"sheen_charlie_moments", "sheen_charlie_moments_avg", "fabric_lambert_albedo",
                                 "gltf_sheen_e", "hdrp_fgd_charlie_fabric", "unreal_cloth_energy"}) {
        const TableDefinition& d = find_table(id);
        const PreparedTable p = d.prepare(default_settings(d));
        ASSERT_FALSE(d.checks.empty()) << id;
        for (const ClosedFormCheck& c : d.checks) {
            const auto [err, where] = c.run(*p.evaluator);
            EXPECT_LE(err, c.tolerance) << id << ": " << c.name << " " << where;
            EXPECT_GT(c.run(wrong).first, c.tolerance) << id << ": " << c.name;
        }
    }
}

TEST(SheenCharlieTables, SameBytesForAnyThreadCount) {
    test::TempDir dir;
    for (const std::string id : {"sheen_charlie_moments", "sheen_charlie_moments_avg", "fabric_lambert_albedo",
                                 "hdrp_fgd_charlie_fabric", "unreal_cloth_energy", "gltf_sheen_e"}) {
        TableSettings s = default_settings(find_table(id));
        for (Axis& a : s.axes) a.count = 5;
        for (int threads : {1, 2})
            write_exr(dir / (id + std::to_string(threads) + ".exr"), test::generate_fresh(find_table(id), s, threads),
                      PixelType::float32);
        const std::string a = test::read_file(dir / (id + "1.exr"));
        EXPECT_FALSE(a.empty());
        EXPECT_EQ(a, test::read_file(dir / (id + "2.exr"))) << id;
    }
}

TEST(SheenCharlieTables, EnginePresetsReadTheCoreTablesInTheirLayout) {
    // HDRP: x = NdotV, y = perceptual roughness at centres; G = E/(1 + E).
    const TableDefinition& hdrp = find_table("hdrp_fgd_charlie_fabric");
    const PreparedTable ph = hdrp.prepare(default_settings(hdrp));
    const double c[2] = {0.3, 0.6};
    const TexelValue v = ph.evaluator->evaluate(c, 0);
    const TexelValue core = texel("sheen_charlie_moments", {0.3, 0.36});
    EXPECT_EQ(v.value[0], core.value[1]);
    EXPECT_EQ(v.value[1], core.value[2]);
    EXPECT_NEAR(v.value[2], 1.0 - 0.5 * 0.36, 1e-9);
    // Unreal: alpha is the row coordinate, Neubelt's visibility.
    const TableDefinition& ue = find_table("unreal_cloth_energy");
    const TexelValue u = ue.prepare(default_settings(ue)).evaluator->evaluate(c, 0);
    EXPECT_NEAR(u.value[0], sheen_charlie_albedo(0.3, 0.6).value[0], u.error[0] + 1e-9);
}

TEST(SheenCharlieLtc, HdrpCharlieTablesPassVerifyAndAreTheSameForAnyThreadCount) {
    for (const char* id : {"hdrp_ltc_charlie", "hdrp_ltc_charlie_error"}) {
        const TableDefinition& def = find_table(id);
        const std::vector<CheckRow> rows = verify_table(def);
        ASSERT_FALSE(rows.empty()) << id;
        for (const CheckRow& r : rows) EXPECT_TRUE(r.pass) << id << ": " << r.check << " " << r.max_error << " " << r.where;
        TableSettings s = default_settings(def);
        s.axes[0].count = 5;
        s.axes[1].count = 4;
        const Table a = test::generate_fresh(def, s, 1), b = test::generate_fresh(def, s, 2);
        EXPECT_EQ(a.values, b.values) << id;
        EXPECT_EQ(a.method.dump(), b.method.dump()) << id;
    }
}

// The norm table takes the n0 the fits of the same texel use (computed once
// per run at the lobe's tolerance) when that n0's error estimate meets the
// norm table's own tolerance, whether or not a fit ran first; at reference
// quality it integrates again at its tighter tolerance.
TEST(SheenCharlieLtc, NormTableTakesTheFitsNormOnlyWhenItsEstimateMeetsTheTablesTolerance) {
    const TableDefinition& def = find_table("ltc_sheen_charlie_ek_norm");
    const TableDefinition& matrix = find_table("ltc_sheen_charlie_ek");
    TableSettings reference = default_settings(def);
    reference.quality = Quality::reference;
    int refined = 0;
    for (bool fit_first : {false, true}) {
        clear_shared_results();
        const PreparedTable norm = def.prepare(default_settings(def));
        const PreparedTable fine = def.prepare(reference);
        const PreparedTable fits = matrix.prepare(default_settings(matrix));
        for (double r : {0.25, 0.8})
            for (double mu : {0.15, 0.9}) {
                const double at[2] = {r, mu};
                if (fit_first) fits.evaluator->evaluate(at, 0);
                const LtcLobe lobe = ltc_table_lobe(def, r, mu);
                const LtcNorms own = ltc_norms(lobe);  // at the lobe's tolerance, as the fits
                ASSERT_LE(own.n0_error, lobe.norm_tolerance) << r << " " << mu;
                const TexelValue v = norm.evaluator->evaluate(at, 0);
                EXPECT_EQ(v.value[0], own.n0) << r << " " << mu;
                EXPECT_EQ(v.error[0], own.n0_error);
                const TexelValue f = fine.evaluator->evaluate(at, 0);
                // Reference quality integrates again: where the fits' n0 does
                // not meet its tolerance, its value is not that n0 (where it
                // does, the same first panels may give the same bits).
                if (own.n0_error > 0.01 * lobe.norm_tolerance) {
                    ++refined;
                    EXPECT_NE(f.value[0], own.n0) << "reference quality integrates again";
                }
                EXPECT_LE(f.error[0], 0.01 * lobe.norm_tolerance);
                EXPECT_NEAR(f.value[0], v.value[0], v.error[0] + f.error[0]);
            }
    }
    EXPECT_GT(refined, 0);
}

// The LTC norms of the Charlie lobe are its own moments over the half
// vector (sheen_charlie_moments, bit for bit), and agree with the generic
// path's split sums within both estimates, at every shadowing.
TEST(SheenCharlieLtc, NormsTakeTheHalfVectorRouteAndAgreeWithTheGenericPath) {
    for (SheenShadowing sh : {SheenShadowing::estevez_kulla, SheenShadowing::estevez_kulla_soft, SheenShadowing::neubelt})
        for (double alpha : {0.004, 0.3, 1.0})
            for (double mu : {0.02, 0.5, 0.95}) {
                const LtcLobe lobe(std::make_shared<const CharlieLobe>(alpha, sh), mu, alpha, 7, 1e-9);
                const LtcNorms n = ltc_norms(lobe);
                const Estimate<2> hv = sheen_charlie_moments(mu, alpha, sh, 1e-9);
                EXPECT_EQ(n.n0, hv.value[0]);
                EXPECT_EQ(n.n1, hv.value[1]);
                EXPECT_EQ(n.n0_error, hv.error[0]);
                GenericOptions opt;
                opt.abs_tol = 1e-9;
                const Estimate<2> g = generic_moments<2>(CharlieLobe(alpha, sh), mu, kSplitSumWeights, opt);
                EXPECT_NEAR(n.n0, g.value[0] + g.value[1], n.n0_error + g.error[0] + g.error[1])
                    << to_string(sh) << " alpha " << alpha << " mu " << mu;
                EXPECT_NEAR(n.n1, g.value[1], n.n1_error + g.error[1]) << to_string(sh) << " alpha " << alpha << " mu " << mu;
                EXPECT_LE(n.n0_error, 1e-9);
            }
}

TEST(SheenCharlieLtc, HeitzLayoutLayerFitsTheSameLobeOnLtc1sGridAndIsTheSameForAnyThreadCount) {
    // The norm is the lobe's albedo: sheen_charlie_moments E at alpha = r^2.
    const PreparedTable norm = find_table("ltc_sheen_charlie_ek_norm").prepare(
        default_settings(find_table("ltc_sheen_charlie_ek_norm")));
    const PreparedTable moments =
        find_table("sheen_charlie_moments").prepare(default_settings(find_table("sheen_charlie_moments")));
    for (double r : {0.3, 0.6, 1.0})
        for (double mu : {0.2, 0.7}) {
            const double n_at[2] = {r, mu}, m_at[2] = {mu, r * r};
            EXPECT_NEAR(norm.evaluator->evaluate(n_at, 0).value[0], moments.evaluator->evaluate(m_at, 0).value[0],
                        2e-8)
                << r << " " << mu;
        }
    for (const char* id : {"ltc_sheen_charlie_ek", "ltc_sheen_charlie_ek_error"}) {
        const TableDefinition& def = find_table(id);
        EXPECT_EQ(def.preset, "ltc");
        TableSettings s = default_settings(def);
        s.axes[0].count = 4;
        s.axes[1].count = 3;
        const Table a = test::generate_fresh(def, s, 1), b = test::generate_fresh(def, s, 2);
        EXPECT_EQ(a.values, b.values) << id;
    }
}
