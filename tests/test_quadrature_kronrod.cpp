// The optional Kronrod (15, 31) panels of integrate_adaptive.
#include <gtest/gtest.h>

#include <cmath>

#include "brdflut/quadrature.h"

using namespace brdflut;

TEST(KronrodRule, QK31IsExactToDegree46AndItsEstimateVanishesExactlyToDegree29) {
    // One panel on [-1, 1]: K31 integrates x^k exactly for k <= 3*15 + 1;
    // the embedded G15 for k <= 29, so the estimate from |K31 - G15|
    // vanishes there (down to the rounding floor) and not at degree 30 and up.
    for (int k = 0; k <= 46; ++k) {
        auto f = [k](double x) { return std::array<double, 1>{std::pow(x, k)}; };
        const auto p = detail::kronrod_panel<1>(f, -1.0, 1.0, 1, KronrodRule::k31);
        const double exact = k % 2 == 1 ? 0.0 : 2.0 / (k + 1);
        EXPECT_NEAR(p.value[0], exact, 1e-14) << "degree " << k;
        if (k <= 29) {
            EXPECT_LE(p.error[0], 1e-13) << "degree " << k;
        } else if (k % 2 == 0) {
            EXPECT_GT(p.error[0], 1e-10) << "degree " << k;
        }
    }
}

TEST(KronrodRule, AdaptiveQK31MatchesClosedFormsWithHonestErrors) {
    AdaptiveOptions opt;
    opt.abs_tol = 1e-11;
    opt.rule = KronrodRule::k31;
    // Endpoint singularity and a sharp peak.
    const Estimate<1> a = integrate_adaptive<1>(
        [](double x) { return std::array<double, 1>{std::sqrt(x)}; }, 0.0, 1.0, opt);
    EXPECT_NEAR(a.value[0], 2.0 / 3.0, a.error[0]);
    EXPECT_LE(a.error[0], 1e-11);
    EXPECT_EQ(a.evaluations % 31, 0);
    const double w = 1e-3;
    const Estimate<1> b = integrate_adaptive<1>(
        [w](double x) { return std::array<double, 1>{w / (x * x + w * w)}; }, -1.0, 2.0, opt);
    EXPECT_NEAR(b.value[0], std::atan(2.0 / w) + std::atan(1.0 / w), b.error[0]);
    EXPECT_LE(b.error[0], 1e-11);
}

TEST(KronrodRule, DefaultRuleIsStillQK15) {
    const Estimate<1> e = integrate_adaptive<1>(
        [](double x) { return std::array<double, 1>{std::exp(x)}; }, 0.0, 1.0);
    EXPECT_EQ(e.evaluations, 15);
    EXPECT_NEAR(e.value[0], std::exp(1.0) - 1.0, 1e-14);
}
