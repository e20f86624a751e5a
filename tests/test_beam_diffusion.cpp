// Photon beam diffusion (pbrt-v4's BSSRDFTable): the grids against pbrt's,
// the single-scattering profile against a direct quadrature of its defining
// integral, pbrt's midpoint rules converging to the exact profile, the
// limits, rho_eff's monotonicity and its Fresnel losses, the Catmull-Rom
// helpers on functions they reproduce, and the inversion's round trip.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "brdflut/beam_diffusion.h"
#include "brdflut/catalogue.h"
#include "brdflut/fresnel.h"
#include "brdflut/math.h"
#include "brdflut/quadrature.h"
#include "test_support.h"

using namespace brdflut;
using brdflut::test::run_cli;
using brdflut::test::TempDir;

namespace {

std::unique_ptr<TexelEvaluator> evaluator(const std::string& id, const std::string& construction = "exact") {
    const TableDefinition& def = find_table(id);
    TableSettings s = default_settings(def);
    s.params["construction"] = construction;
    return def.prepare(s).evaluator;
}

// Sr_ss from its definition: the integral over t in [t_c, t_c + 60] of
// the integrand, adaptive Gauss-Kronrod (7,15) in t itself (a coarse pass for
// its size, then to 1e-12 of it).
double ss_direct(double r, double rho, double g, double eta) {
    const BeamDiffusion b(rho, g, eta);
    AdaptiveOptions opt;
    opt.abs_tol = 0.0;
    opt.max_intervals = 50;
    const double tc = b.t_crit(r);
    const auto f = [&](double t) { return std::array<double, 1>{b.ss_integrand(t, r)}; };
    const double size = integrate_adaptive<1>(f, tc, tc + 60.0, opt).value[0];
    opt.abs_tol = 1e-12 * size;  // then to 1e-12 of its size
    opt.max_intervals = 20000;
    return integrate_adaptive<1>(f, tc, tc + 60.0, opt).value[0];
}

}  // namespace

TEST(BeamDiffusion, AxesHoldPbrtGrids) {
    const TableDefinition& def = find_table("beam_diffusion_profile");
    const Axis& radius = def.axes[0].axis;
    const Axis& albedo = def.axes[1].axis;
    const std::vector<double> r = pbrt_radius_samples(64), rho = pbrt_rho_samples(100);
    ASSERT_EQ(radius.count, 64);
    ASSERT_EQ(albedo.count, 100);
    EXPECT_EQ(radius.value(0), 0.0);
    for (int j = 1; j < 64; ++j) EXPECT_NEAR(radius.value(j) / r[static_cast<std::size_t>(j)], 1.0, 1e-13) << j;
    for (int i = 0; i < 100; ++i) EXPECT_NEAR(albedo.value(i), rho[static_cast<std::size_t>(i)], 1e-15) << i;
    // The positions invert the grid: texel centres at their own index.
    for (int j : {0, 1, 2, 40, 63}) EXPECT_NEAR(radius.position_of_value(radius.value(j)), j, 1e-9) << j;
    for (int i : {0, 1, 50, 99}) EXPECT_NEAR(albedo.position_of_value(albedo.value(i)), i, 1e-9) << i;
    // Between texel 0 (r = 0) and texel 1 (r_1) the position is linear in r.
    EXPECT_NEAR(radius.position_of_value(0.5 * 2.5e-3), 0.5, 1e-12);
}

TEST(BeamDiffusion, ZeroThenEndpointsValidates) {
    Axis a{"radius", 0.0, 1.0, 8, Placement::zero_then_endpoints, Warp::log};
    EXPECT_ANY_THROW(a.validate());  // log needs min > 0
    a.min = 0.1;
    EXPECT_NO_THROW(a.validate());
    a.count = 1;
    EXPECT_ANY_THROW(a.validate());
    a.count = 2;  // 0 and min
    EXPECT_NO_THROW(a.validate());
    EXPECT_EQ(a.value(0), 0.0);
    EXPECT_EQ(a.value(1), 0.1);
    EXPECT_EQ(placement_from_string("zero_then_endpoints"), Placement::zero_then_endpoints);
    EXPECT_EQ(to_string(Placement::zero_then_endpoints), "zero_then_endpoints");
}

TEST(BeamDiffusion, SingleScatteringMatchesItsDefiningIntegral) {
    for (double eta : {1.0, 1.33, 1.6})
        for (double g : {0.0, 0.7, -0.4})
            for (double r : {2.5e-3, 0.05, 0.8, 6.0}) {
                const BeamDiffusion b(0.8, g, eta);
                const Estimate<1> e = b.weighted_ss(r, 1e-12);
                const double direct = kTwoPi * r * ss_direct(r, 0.8, g, eta);
                EXPECT_NEAR(e.value[0] / direct, 1.0, 1e-9) << "eta " << eta << " g " << g << " r " << r;
                EXPECT_LE(std::abs(e.value[0] - direct), 10.0 * e.error[0] + 1e-12 * direct);
            }
}

TEST(BeamDiffusion, SingleScatteringLimitAtZeroRadius) {
    for (double eta : {1.0, 1.33, 2.0}) {
        const BeamDiffusion b(1.0, 0.3, eta);
        const double at_zero = b.weighted_ss(0.0, 1e-12).value[0];
        EXPECT_GT(at_zero, 0.0);
        EXPECT_NEAR(b.weighted_ss(1e-9, 1e-12).value[0] / at_zero, 1.0, 1e-7) << eta;
    }
}

TEST(BeamDiffusion, PbrtMidpointRulesConvergeToTheExactProfile) {
    // pbrt's rules are midpoint rules of the same integrals: with many
    // points they approach the exact values; with its 100 they do not.
    for (double rho : {0.3, 0.95})
        for (double r : {0.1, 1.0, 5.0}) {
            const BeamDiffusion b(rho, 0.0, 1.33);
            const double ss = b.weighted_ss(r, 1e-12).value[0], ms = b.weighted_ms(r, 1e-12).value[0];
            EXPECT_NEAR(b.weighted_ss_midpoint(r, 200000) / ss, 1.0, 1e-6) << rho << " " << r;
            EXPECT_NEAR(b.weighted_ms_midpoint(r, 200000) / ms, 1.0, 1e-6) << rho << " " << r;
            EXPECT_GT(std::abs(b.weighted_ss_midpoint(r) / ss - 1.0), 1e-5) << rho << " " << r;
        }
}

TEST(BeamDiffusion, FastExpIsPbrtsApproximation) {
    for (double x : {-80.0, -3.3, -1.0, -0.1, 0.0})
        EXPECT_NEAR(pbrt_fast_exp(x) / std::exp(x), 1.0, 2e-4) << x;
    EXPECT_EQ(pbrt_fast_exp(-100.0), 0.0);  // below 2^-126
}

TEST(BeamDiffusion, VanishesWithTheAlbedo) {
    for (double r : {0.0, 2.5e-3, 0.4, 8.0}) {
        const BeamDiffusion zero(0.0, 0.0, 1.33);
        EXPECT_EQ(zero.weighted_ss(r, 1e-10).value[0], 0.0);
        EXPECT_EQ(zero.weighted_ms(r, 1e-10).value[0], 0.0);
        // Single scattering is linear in rho (sigma_t = 1), multiple
        // scattering vanishes faster (rho'^2).
        const double rho = 1e-6;
        const BeamDiffusion small(rho, 0.0, 1.33), one(1.0, 0.0, 1.33);
        EXPECT_NEAR(small.weighted_ss(r, 1e-12).value[0], rho * one.weighted_ss(r, 1e-12).value[0],
                    1e-12 * one.weighted_ss(r, 1e-12).value[0]);
        EXPECT_LE(small.weighted_ms(r, 1e-12).value[0], 2.0 * rho * rho * one.weighted_ms(r, 1e-12).value[0] + 1e-300);
    }
}

TEST(BeamDiffusion, RhoEffRisesAndLosesToFresnel) {
    double prev = 0.0;
    for (double rho : pbrt_rho_samples(25)) {
        const Estimate<2> e = BeamDiffusion(rho, 0.0, 1.33).rho_eff(1e-10);
        const double v = e.value[0] + e.value[1];
        if (rho > 0.0) {
            EXPECT_GT(v, prev) << rho;
        }
        prev = v;
    }
    // A larger index keeps more light inside: rho_eff(1) falls with eta.
    auto at_one = [](double eta) {
        const Estimate<2> e = BeamDiffusion(1.0, 0.0, eta).rho_eff(1e-10);
        return e.value[0] + e.value[1];
    };
    const double e1 = at_one(1.0), e133 = at_one(1.33), e15 = at_one(1.5), e2 = at_one(2.0);
    EXPECT_GT(e1, e133);
    EXPECT_GT(e133, e15);
    EXPECT_GT(e15, e2);
    // The model's rho_eff at rho = 1 is above 1 for pbrt's default index: the
    // sum of its single- and multiple-scattering terms does not conserve
    // energy exactly (pbrt-v4's own table gives 1.019 there).
    EXPECT_GT(e133, 1.0);
    EXPECT_LT(e133, 1.05);
}

TEST(BeamDiffusion, CatmullRomReproducesLinearFunctions) {
    const std::vector<double> x = pbrt_radius_samples(64);
    std::vector<double> f;
    for (double v : x) f.push_back(0.25 + 3.0 * v);
    const double b = x.back();
    EXPECT_NEAR(catmull_rom_integral(x, f), 0.25 * b + 1.5 * b * b, 1e-12 * b * b);
    for (double y : {0.3, 1.7, 40.0, 500.0}) EXPECT_NEAR(catmull_rom_invert(x, f, y), (y - 0.25) / 3.0, 1e-12 * y);
    EXPECT_EQ(catmull_rom_invert(x, f, -1.0), 0.0);
    EXPECT_EQ(catmull_rom_invert(x, f, 1e9), b);
}

TEST(BeamDiffusion, InversionRoundTrips) {
    const auto inv = evaluator("beam_diffusion_albedo");
    for (double target : {0.02, 0.25, 0.66, 0.9, 1.0}) {
        const TexelValue v = inv->evaluate(&target, 0);
        const Estimate<2> e = BeamDiffusion(v.value[0], 0.0, 1.33).rho_eff(1e-12);
        EXPECT_NEAR(e.value[0] + e.value[1], target, 1e-10) << target;
        EXPECT_LT(v.error[0], 1e-8) << target;
    }
    // Beyond rho_eff(1): clamped to 1; at 0: 0.
    double beyond = 1.2, zero = 0.0;
    EXPECT_EQ(inv->evaluate(&beyond, 0).value[0], 1.0);
    EXPECT_EQ(inv->evaluate(&zero, 0).value[0], 0.0);
    // pbrt's inversion of its own rho_eff table lands near the exact one.
    const auto pbrt = evaluator("beam_diffusion_albedo", "pbrt_midpoint");
    double mid = 0.5;
    EXPECT_NEAR(pbrt->evaluate(&mid, 0).value[0], inv->evaluate(&mid, 0).value[0], 1e-2);
}

TEST(BeamDiffusion, PbrtConstructionTruncatesRhoEffAtItsLastRadius) {
    // At rho = 1 (no absorption) the profile falls only as 1/r^2: pbrt's
    // integral stops at r_63 = 203 and misses the 1/r tail beyond.
    const auto exact = evaluator("beam_diffusion_rho_eff");
    const auto pbrt = evaluator("beam_diffusion_rho_eff", "pbrt_midpoint");
    double one = 1.0;
    const double e = exact->evaluate(&one, 0).value[0], p = pbrt->evaluate(&one, 0).value[0];
    EXPECT_GT(e - p, 0.005);
    EXPECT_LT(e - p, 0.03);
}

TEST(BeamDiffusion, CompareReportsTheRelativeErrorOfPbrtsTable) {
    // compare --relative on pbrt's rho_eff against the largest relative
    // difference of the two constructions' evaluators at the same albedos.
    TempDir dir;
    const auto gen = run_cli("generate beam_diffusion_rho_eff --construction pbrt_midpoint --size 9 -q -o '" +
                                 (dir / "p") + "'", dir);
    ASSERT_EQ(gen.exit_code, 0) << gen.err;
    const auto cmp = run_cli("compare '" + (dir / "p/beam_diffusion_rho_eff.exr") +
                                 "' --as beam_diffusion_rho_eff --size 9 --relative --json", dir);
    ASSERT_EQ(cmp.exit_code, 1) << cmp.err;  // pbrt's values are not the exact ones
    const auto j = nlohmann::json::parse(cmp.out);
    const auto exact = evaluator("beam_diffusion_rho_eff");
    const auto pbrt = evaluator("beam_diffusion_rho_eff", "pbrt_midpoint");
    Axis a = find_table("beam_diffusion_rho_eff").axes[0].axis;
    a.count = 9;
    for (std::size_t c = 0; c < 3; ++c) {
        double worst = 0.0;
        for (int i = 0; i < 9; ++i) {
            const double rho = a.value(i);
            const double e = exact->evaluate(&rho, 0).value[c];
            const double p = static_cast<float>(pbrt->evaluate(&rho, 0).value[c]);
            if (e != 0.0) worst = std::max(worst, std::abs(p - e) / std::abs(e));
        }
        const double reported = j.at("channels").at(c).at("max_rel_error").get<double>();
        EXPECT_GT(reported, 1e-4) << c;
        EXPECT_NEAR(reported, worst, 1e-6 * worst) << c;
    }
    // The text report names where the largest relative error lies.
    const auto text = run_cli("compare '" + (dir / "p/beam_diffusion_rho_eff.exr") +
                                  "' --as beam_diffusion_rho_eff --size 9 --relative", dir);
    EXPECT_NE(text.out.find("max |error|/|exact|"), std::string::npos);
    EXPECT_NE(text.out.find("albedo = 1"), std::string::npos) << text.out;
}
