// LTC fits of the Charlie sheen and EON rough diffuse lobes (and, for the
// minima of neighbouring texels, of every lobe the catalogue fits): the norm
// against the catalogue's albedo tables, local optimality, no texel in a
// worse minimum than its neighbours' fits continued to it, the
// symmetric fit at normal view, the identity for a Lambertian lobe, and
// verify's checks of their tables (their thread independence: test_ltc.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "brdflut/catalogue.h"
#include "brdflut/error.h"
#include "brdflut/generate.h"
#include "brdflut/ltc.h"
#include "brdflut/ltc_fit.h"
#include "brdflut/verify.h"
#include "tables/ltc_tables.h"

namespace brdflut {
namespace {

const char* const kMatrixTables[] = {"ltc_sheen_charlie", "ltc_eon"};

// Texels of the 64x64 grid spread over it (normal view, grazing rows, the
// smallest and largest roughness included).
struct LobeTexel { int t, a; };
std::vector<LobeTexel> lobe_texels() {
    return {{0, 10}, {0, 63}, {12, 3}, {20, 20}, {30, 50}, {45, 30}, {58, 15}, {63, 2}, {63, 40}};
}
double lobe_mu(int t) { const double u = t / 63.0; return 1.0 - u * u; }
double r_of(int a) { return a / 63.0; }

TEST(LtcLobes, NormMatchesTheCataloguesAlbedoOfTheLobe) {
    // The fit's n0 and the norm tables against sheen_charlie_albedo and
    // eon_albedo, evaluated at the lobe's (clamped) parameters.
    struct Case { const char* matrix; const char* norm; const char* albedo; };
    for (const Case& c : {Case{"ltc_sheen_charlie", "ltc_sheen_charlie_norm", "sheen_charlie_albedo"},
                          Case{"ltc_eon", "ltc_eon_norm", "eon_albedo"}}) {
        SCOPED_TRACE(c.matrix);
        const TableDefinition& albedo = find_table(c.albedo);
        const TableDefinition& norm = find_table(c.norm);
        const PreparedTable pa = albedo.prepare(default_settings(albedo));
        const PreparedTable pn = norm.prepare(default_settings(norm));
        for (const LobeTexel& x : lobe_texels()) {
            const LtcLobe lobe = ltc_table_lobe(find_table(c.matrix), r_of(x.a), lobe_mu(x.t));
            // The tables' roughness coordinate: Charlie alpha = max(r^2, 0.01), EON sigma = r.
            const double r = r_of(x.a);
            EXPECT_EQ(lobe.param, std::string(c.matrix) == "ltc_eon" ? r : std::max(r * r, kLtcSheenMinAlpha));
            const LtcFit fit = fit_ltc(lobe, ltc_fit_options(0));
            const double ca[2] = {lobe.mu_o, lobe.param};  // (cos_theta, alpha or sigma)
            const double exact = pa.evaluator->evaluate(ca, 0).value[0];
            EXPECT_NEAR(fit.n0, exact, 1e-7 * std::max(1.0, exact)) << "t=" << x.t << " a=" << x.a;
            const double cn[2] = {r_of(x.a), lobe_mu(x.t)};  // (roughness, cos_theta)
            EXPECT_EQ(pn.evaluator->evaluate(cn, 0).value[0], fit.n0);
            EXPECT_GT(fit.n0, 0.0);
        }
    }
}

TEST(LtcLobes, EveryFittedTexelIsALocalMinimumOfTheObjective) {
    for (const char* id : kMatrixTables) {
        for (const LobeTexel& x : lobe_texels()) {
            const LtcLobe lobe = ltc_table_lobe(find_table(id), r_of(x.a), lobe_mu(x.t));
            const LtcFit fit = fit_ltc(lobe);
            const double j0 = ltc_objective(lobe, fit.params);
            EXPECT_DOUBLE_EQ(j0, fit.objective) << id;
            if (fit.objective < 1e-12) continue;  // the exact LTC (EON at sigma = 0): tested below
            // No parameter moved by its probe step lowers the objective.
            EXPECT_LE(ltc_local_minimum_drop(lobe, fit), 1e-9) << id << " t=" << x.t << " a=" << x.a;
        }
    }
}

TEST(LtcLobes, EonAtSigmaZeroIsLambertAndItsFitIsTheIdentity) {
    for (const double mu : {1.0, 0.7, 0.3, 0.05, 0.0}) {
        const LtcLobe lobe = ltc_table_lobe(find_table("ltc_eon"), 0.0, mu);
        EXPECT_NEAR(lobe(Vec3{0.6, 0.0, 0.8}), 0.8 / kPi, 1e-15);
        const LtcFit fit = fit_ltc(lobe);
        EXPECT_NEAR(fit.minv.a, 1.0, 1e-9) << mu;
        EXPECT_NEAR(fit.minv.b, 0.0, 1e-9) << mu;
        EXPECT_NEAR(fit.minv.c, 0.0, 1e-9) << mu;
        EXPECT_NEAR(fit.minv.d, 1.0, 1e-9) << mu;
        EXPECT_NEAR(fit.n0, 1.0, 1e-9);
        EXPECT_EQ(fit.below_horizon, 0.0);
        // ... and a texel of small sigma is close to it, but not equal.
        const LtcFit near = fit_ltc(ltc_table_lobe(find_table("ltc_eon"), 0.05, mu));
        EXPECT_GT(std::abs(near.minv.d - 1.0) + std::abs(near.minv.b), 1e-4) << mu;
        EXPECT_LT(std::abs(near.minv.d - 1.0) + std::abs(near.minv.b), 0.05) << mu;
    }
}

TEST(LtcLobes, FitAtNormalViewIsRotationallySymmetric) {
    // At normal view the lobe is symmetric about the normal, and the shading
    // frame's azimuth is arbitrary: the LTC must be, too (M^-1 diagonal with
    // equal tangent scales). The sheen's lobe there is a ring about the
    // normal; fitted in coordinates about one side of the ring its LTC came
    // out tilted (M^-1[0][2] = 0.09 at r = 0.1).
    for (const char* id : kMatrixTables)
        for (const double r : {0.1, 0.4, 0.7, 1.0}) {
            const LtcFit fit = fit_ltc(ltc_table_lobe(find_table(id), r, 1.0));
            EXPECT_NEAR(fit.minv.a, 1.0, 1e-6) << id << " r=" << r;
            EXPECT_NEAR(fit.minv.b, 0.0, 1e-6 * fit.minv.d) << id << " r=" << r;
            EXPECT_NEAR(fit.minv.c, 0.0, 1e-6) << id << " r=" << r;
        }
}

// No texel of an LTC matrix table sits in a worse minimum than its
// neighbours' fits continued to it. Along a grazing row and a middle column
// of each lobe's table (every other texel), the texel's fit has an objective
// no larger than the descent started from either neighbour's fit, up to the
// objective of the line's median fit: a texel may stop short of the
// continued minimum by less than a typical fit's own misfit (Nelder-Mead
// stops short by up to 1e-6 here, where the medians are 4e-4 to 3e-2), not
// by a basin. A texel that finds a better basin than its neighbours (a jump
// between minima of near-equal depth, which shows as a step in the
// coefficients) passes, as it should: the table holds the best fit found,
// texel by texel.
TEST(LtcLobes, NoTexelSitsInAWorseMinimumThanItsNeighboursContinued) {
    for (const char* id : {"ltc_1", "ltc_sheen_charlie", "ltc_eon", "hdrp_ltc_cook_torrance"}) {
        const TableDefinition& def = find_table(id);
        for (const bool row : {true, false}) {
            SCOPED_TRACE(std::string(id) + (row ? " row t = 56" : " column a = 32"));
            std::vector<LtcLobe> lobes;
            std::vector<LtcFit> fits;
            std::vector<double> objectives;
            for (int i = 0; i < 64; i += 2) {
                lobes.push_back(ltc_table_lobe(def, r_of(row ? i : 32), lobe_mu(row ? 56 : i)));
                fits.push_back(fit_ltc(lobes.back()));
                objectives.push_back(fits.back().objective);
            }
            std::vector<double> sorted = objectives;
            std::sort(sorted.begin(), sorted.end());
            const double allowance = sorted[sorted.size() / 2];
            for (std::size_t k = 0; k < fits.size(); ++k)
                for (const std::size_t n : {k - 1, k + 1}) {
                    if (n >= fits.size()) continue;  // (k - 1 wraps at k = 0)
                    const LtcFit continued = fit_ltc_from(lobes[k], &fits[n].params);
                    EXPECT_LE(fits[k].objective, continued.objective + allowance)
                        << "texel " << 2 * k << " against the fit continued from texel " << 2 * n
                        << " (the line's median objective " << allowance << ")";
                }
        }
    }
}

TEST(LtcLobes, MatrixTableMetadataHoldsTheMaximaOfTheErrorReport) {
    // The matrix tables' metadata maxima against the per-texel channels of
    // their error tables on the same grid, both with the exact light to
    // 1e-5 of n0, each table's fits and reports its own (the shared results
    // cleared between them); the report stored in float.
    for (const char* id : kMatrixTables) {
        SCOPED_TRACE(id);
        const TableDefinition& m = find_table(id);
        const TableDefinition& r = find_table(std::string(id) + "_error");
        TableSettings s = default_settings(m);
        s.axes[0].count = 4;
        s.axes[1].count = 4;
        clear_shared_results();
        const Table tm = generate(m, s);
        clear_shared_results();
        const Table tr = generate(r, s);
        const nlohmann::json& fe = tm.method.at("fit_error");
        double l3 = 0.0, below = 0.0, light = 0.0;
        for (std::size_t k = 0; k < tr.texel_count(); ++k) {
            l3 = std::max(l3, tr.at(k, 0));
            below = std::max(below, tr.at(k, 1));
            light = std::max(light, tr.at(k, 2));
        }
        EXPECT_GT(light, 1e-3);  // not a trivial maximum
        EXPECT_EQ(static_cast<float>(fe.at("light_error_max").get<double>()), static_cast<float>(light));
        EXPECT_EQ(static_cast<float>(fe.at("relative_l3_max").get<double>()), static_cast<float>(l3));
        EXPECT_EQ(static_cast<float>(fe.at("below_horizon_max").get<double>()), static_cast<float>(below));
        EXPECT_DOUBLE_EQ(fe.at("light_tolerance").get<double>(), 1e-5);
        EXPECT_DOUBLE_EQ(tr.method.at("fit_error").at("light_tolerance").get<double>(), 1e-5);
    }
}

TEST(LtcLobes, VerifyChecksOfTheNewTablesPass) {
    for (const char* id : {"ltc_sheen_charlie", "ltc_eon", "ltc_sheen_charlie_norm", "ltc_eon_norm"}) {
        const std::vector<CheckRow> rows = verify_table(find_table(id));
        ASSERT_FALSE(rows.empty()) << id;
        for (const CheckRow& r : rows) EXPECT_TRUE(r.pass) << id << ": " << r.check << " " << r.max_error << " " << r.where;
    }
}

}  // namespace
}  // namespace brdflut

namespace brdflut {
namespace {
TEST(LtcLobes, ALobeOfATableThatIsNotAnLtcTableIsRefusedWithTheLtcTablesNamed) {
    try {
        ltc_table_lobe(find_table("ggx_dfg"), 0.5, 0.5);
        FAIL() << "ggx_dfg accepted as an LTC table";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("'ggx_dfg' is not an LTC table"), std::string::npos) << what;
        EXPECT_NE(what.find("hdrp_ltc_cook_torrance"), std::string::npos) << what;
    }
    // The generic kind is built from its lobe only.
    EXPECT_THROW(LtcLobe(LtcLobeKind::generic, 0.5, 0.3), Error);
    EXPECT_THROW(LtcLobe(nullptr, 0.5, 0.3, 1, 1e-9), Error);
}
}  // namespace
}  // namespace brdflut
