// The optional Kronrod (15, 31) panels of integrate_adaptive.
#include <gtest/gtest.h>

#include <cmath>

#include "brdflut/quadrature.h"
#include "integrate/half_circle.h"

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

TEST(AdaptivePanels, OnePanelIsIntegrateAdaptiveBitForBit) {
    AdaptiveOptions opt;
    opt.abs_tol = 1e-12;
    opt.rule = KronrodRule::k31;
    auto f = [](double x) { return std::array<double, 2>{1.0 / (1e-4 + x * x), std::cos(30.0 * x)}; };
    const Estimate<2> a = integrate_adaptive<2>(f, -1.0, 2.0, opt);
    const Estimate<2> b = integrate_adaptive_panels<2>(f, -1.0, 2.0, 1, opt);
    EXPECT_GT(a.evaluations, 31);  // bisected, not the single-panel shortcut
    EXPECT_EQ(a.value, b.value);
    EXPECT_EQ(a.error, b.error);
    EXPECT_EQ(a.evaluations, b.evaluations);
    // A panel that meets the tolerance at once is returned as it is.
    auto smooth = [](double x) { return std::array<double, 1>{std::exp(x)}; };
    const Estimate<1> one = integrate_adaptive<1>(smooth, 0.0, 1.0, opt);
    const detail::Interval<1> panel = detail::kronrod_panel<1>(smooth, 0.0, 1.0, opt.controlled, opt.rule);
    EXPECT_EQ(one.evaluations, 31);
    EXPECT_EQ(one.value[0], panel.value[0]);
    EXPECT_EQ(one.error[0], panel.error[0]);
}

TEST(AdaptivePanels, StartingPanelsOnALongRangeSkipTheCoarseOnesAndStayHonest) {
    // Lorentzians of width 0.5 every 2 units over [0, 24]: one panel cannot
    // resolve them, so bisection evaluates every coarser panel on its way down.
    auto f = [](double x) {
        double s = 0.0;
        for (int k = 0; k <= 12; ++k) s += 0.25 / ((x - 2.0 * k) * (x - 2.0 * k) + 0.25);
        return std::array<double, 1>{s};
    };
    double exact = 0.0;
    for (int k = 0; k <= 12; ++k) exact += 0.5 * (std::atan((24.0 - 2.0 * k) / 0.5) + std::atan(2.0 * k / 0.5));
    AdaptiveOptions opt;
    opt.abs_tol = 1e-10;
    opt.rule = KronrodRule::k31;
    const Estimate<1> one = integrate_adaptive_panels<1>(f, 0.0, 24.0, 1, opt);
    const Estimate<1> eight = integrate_adaptive_panels<1>(f, 0.0, 24.0, 8, opt);
    EXPECT_NEAR(one.value[0], exact, one.error[0]);
    EXPECT_NEAR(eight.value[0], exact, eight.error[0]);
    EXPECT_LE(eight.error[0], 1e-10);
    EXPECT_LT(eight.evaluations, one.evaluations);
    EXPECT_EQ(eight.evaluations % 31, 0);
}

TEST(AdaptiveBreaks, BreakPointsAtKinksSaveBisectionAndStayHonest) {
    // Kinks at two points inside [0, 3]: |x - c1| and sqrt(1 + |x - c2|).
    // With breaks there every panel is smooth and converges fast; without
    // them the rule bisects toward each kink. A pair of breaks that is not
    // increasing is skipped.
    const double c1 = 0.7, c2 = 2.2;
    auto f = [&](double x) {
        return std::array<double, 1>{std::abs(x - c1) + std::sqrt(1.0 + std::abs(x - c2))};
    };
    const double exact = 0.5 * (c1 * c1 + (3.0 - c1) * (3.0 - c1)) +
                         (std::pow(1.0 + c2, 1.5) - 1.0 + std::pow(1.0 + (3.0 - c2), 1.5) - 1.0) / 1.5;
    AdaptiveOptions opt;
    opt.abs_tol = 1e-10;
    opt.max_intervals = 2000;
    const double plain[2] = {0.0, 3.0};
    const double cut[5] = {0.0, c1, c1, c2, 3.0};
    const Estimate<1> without = integrate_adaptive_breaks<1>(f, plain, 2, opt);
    const Estimate<1> with = integrate_adaptive_breaks<1>(f, cut, 5, opt);
    EXPECT_NEAR(with.value[0], exact, std::max(with.error[0], 1e-13));
    EXPECT_LE(with.error[0], 1e-10);
    EXPECT_NEAR(without.value[0], exact, std::max(without.error[0], 1e-13));
    EXPECT_LT(with.evaluations, without.evaluations);
    // The same two panels as breaks and as integrate_adaptive_panels.
    const double halves[3] = {0.0, 1.5, 3.0};
    const Estimate<1> a = integrate_adaptive_breaks<1>(f, halves, 3, opt);
    const Estimate<1> b = integrate_adaptive_panels<1>(f, 0.0, 3.0, 2, opt);
    EXPECT_EQ(a.value[0], b.value[0]);
    EXPECT_EQ(a.evaluations, b.evaluations);
}

namespace {
// f(x) = 1 / (1 + x^2), evaluated one node at a time or in batches; counts
// the batches and the nodes they carried.
struct Batched {
    int* batches;
    int* nodes;
    std::array<double, 1> operator()(double x) const { return {1.0 / (1.0 + x * x)}; }
    void batch(const double* x, std::array<double, 1>* y, int n) const {
        ++*batches;
        *nodes += n;
        for (int i = 0; i < n; ++i) y[i] = (*this)(x[i]);
    }
};
}  // namespace

TEST(KronrodRule, ABatchIntegrandGetsEveryNodeOfAPanelAndTheSameResult) {
    for (KronrodRule rule : {KronrodRule::k15, KronrodRule::k31}) {
        AdaptiveOptions opt;
        opt.abs_tol = 1e-13;
        opt.rule = rule;
        int batches = 0, nodes = 0;
        const Estimate<1> b = integrate_adaptive<1>(Batched{&batches, &nodes}, -3.0, 5.0, opt);
        const Estimate<1> s = integrate_adaptive<1>([](double x) { return std::array<double, 1>{1.0 / (1.0 + x * x)}; },
                                                    -3.0, 5.0, opt);
        EXPECT_EQ(b.value, s.value);
        EXPECT_EQ(b.error, s.error);
        EXPECT_EQ(b.evaluations, s.evaluations);
        const int per_panel = rule == KronrodRule::k31 ? 31 : 15;
        EXPECT_EQ(nodes, b.evaluations);
        EXPECT_EQ(batches * per_panel, nodes);
        EXPECT_NEAR(b.value[0], std::atan(5.0) + std::atan(3.0), b.error[0]);
    }
}

TEST(HalfCircleTrapezoid, ABatchIntegrandGetsTheSameResult) {
    // integral over [0, pi] of dphi / (1.5 + cos(phi)) = pi / sqrt(1.25).
    int batches = 0, nodes = 0;
    struct Shifted : Batched {
        std::array<double, 1> operator()(double c) const { return {1.0 / (1.5 + c)}; }
        void batch(const double* c, std::array<double, 1>* y, int n) const {
            ++*batches;
            *nodes += n;
            for (int i = 0; i < n; ++i) y[i] = (*this)(c[i]);
        }
    };
    const std::array<double, 2> b = detail::trapezoid_half_circle<1>(Shifted{{&batches, &nodes}}, 1e-13);
    const std::array<double, 2> s = detail::trapezoid_half_circle<1>(
        [](double c) { return std::array<double, 1>{1.0 / (1.5 + c)}; }, 1e-13);
    EXPECT_EQ(b, s);
    EXPECT_GT(batches, 0);
    EXPECT_GE(nodes, 16);
    EXPECT_NEAR(b[0], kPi / std::sqrt(1.25), 1e-12);
}

TEST(KronrodRule, PanelSumsGiveTheSameBitsInTheSseAndScalarChannels) {
    // With three channels the first two are summed side by side (SSE2) and
    // the third alone: the same function in each must give the same bits,
    // for both rules, with and without bisection, and the same as the
    // function integrated on its own.
    for (KronrodRule rule : {KronrodRule::k15, KronrodRule::k31})
        for (double tol : {1e-3, 1e-13}) {
            AdaptiveOptions opt;
            opt.abs_tol = tol;
            opt.rule = rule;
            auto f = [](double x) {
                const double y = std::exp(-x) / (0.01 + x * x);
                return std::array<double, 3>{y, y, y};
            };
            const Estimate<3> e = integrate_adaptive<3>(f, -0.5, 2.0, opt);
            EXPECT_EQ(e.value[0], e.value[1]);
            EXPECT_EQ(e.value[0], e.value[2]);
            EXPECT_EQ(e.error[0], e.error[1]);
            EXPECT_EQ(e.error[0], e.error[2]);
            const Estimate<1> one = integrate_adaptive<1>(
                [](double x) { return std::array<double, 1>{std::exp(-x) / (0.01 + x * x)}; }, -0.5, 2.0, opt);
            EXPECT_EQ(one.value[0], e.value[2]);
            EXPECT_EQ(one.error[0], e.error[2]);
        }
}

TEST(KronrodRule, QK21IsExactToDegree31AndItsEstimateVanishesExactlyToDegree19) {
    // K21 integrates x^k exactly for k <= 3*10 + 1; the embedded G10 (no
    // node at 0) for k <= 19, so the estimate from |K21 - G10| vanishes there
    // (down to the rounding floor) and not at degree 20 and up.
    for (int k = 0; k <= 31; ++k) {
        auto f = [k](double x) { return std::array<double, 1>{std::pow(x, k)}; };
        const auto p = detail::kronrod_panel<1>(f, -1.0, 1.0, 1, KronrodRule::k21);
        const double exact = k % 2 == 1 ? 0.0 : 2.0 / (k + 1);
        EXPECT_NEAR(p.value[0], exact, 1e-14) << "degree " << k;
        if (k <= 19) {
            EXPECT_LE(p.error[0], 1e-13) << "degree " << k;
        } else if (k % 2 == 0) {
            EXPECT_GT(p.error[0], 1e-10) << "degree " << k;
        }
    }
    // Degree 32 is beyond the Kronrod rule: its value is off.
    auto f32 = [](double x) { return std::array<double, 1>{std::pow(x, 32)}; };
    EXPECT_GT(std::abs(detail::kronrod_panel<1>(f32, -1.0, 1.0, 1, KronrodRule::k21).value[0] - 2.0 / 33.0), 1e-12);
}

TEST(KronrodRule, AdaptiveQK21MatchesClosedFormsWithHonestErrorsAndCountsItsNodes) {
    AdaptiveOptions opt;
    opt.abs_tol = 1e-11;
    opt.rule = KronrodRule::k21;
    const Estimate<1> a = integrate_adaptive<1>(
        [](double x) { return std::array<double, 1>{std::sqrt(x)}; }, 0.0, 1.0, opt);
    EXPECT_NEAR(a.value[0], 2.0 / 3.0, a.error[0]);
    EXPECT_LE(a.error[0], 1e-11);
    EXPECT_GT(a.evaluations, 21);
    EXPECT_EQ(a.evaluations % 21, 0);
    const double w = 1e-3;
    const Estimate<1> b = integrate_adaptive_panels<1>(
        [w](double x) { return std::array<double, 1>{w / (x * x + w * w)}; }, -1.0, 2.0, 3, opt);
    EXPECT_NEAR(b.value[0], std::atan(2.0 / w) + std::atan(1.0 / w), b.error[0]);
    EXPECT_LE(b.error[0], 1e-11);
    EXPECT_EQ(b.evaluations % 21, 0);
}

TEST(KronrodRule, QK21BatchAndChannelsGiveTheSameBitsAsOneNodeAndOneChannel) {
    // The batch path gets all 21 nodes at once and gives exactly the values
    // of one node at a time; two channels summed side by side (SSE2) and a
    // third alone give the same bits as the function on its own.
    AdaptiveOptions opt;
    opt.abs_tol = 1e-13;
    opt.rule = KronrodRule::k21;
    int batches = 0, nodes = 0;
    const Estimate<1> b = integrate_adaptive<1>(Batched{&batches, &nodes}, -3.0, 5.0, opt);
    const Estimate<1> s = integrate_adaptive<1>([](double x) { return std::array<double, 1>{1.0 / (1.0 + x * x)}; },
                                                -3.0, 5.0, opt);
    EXPECT_EQ(b.value, s.value);
    EXPECT_EQ(b.error, s.error);
    EXPECT_EQ(nodes, b.evaluations);
    EXPECT_EQ(batches * 21, nodes);
    EXPECT_NEAR(b.value[0], std::atan(5.0) + std::atan(3.0), b.error[0]);
    for (double tol : {1e-3, 1e-13}) {
        opt.abs_tol = tol;
        auto f = [](double x) {
            const double y = std::exp(-x) / (0.01 + x * x);
            return std::array<double, 3>{y, y, y};
        };
        const Estimate<3> e = integrate_adaptive<3>(f, -0.5, 2.0, opt);
        EXPECT_EQ(e.value[0], e.value[1]);
        EXPECT_EQ(e.value[0], e.value[2]);
        EXPECT_EQ(e.error[0], e.error[2]);
        const Estimate<1> one = integrate_adaptive<1>(
            [](double x) { return std::array<double, 1>{std::exp(-x) / (0.01 + x * x)}; }, -0.5, 2.0, opt);
        EXPECT_EQ(one.value[0], e.value[2]);
        EXPECT_EQ(one.error[0], e.error[2]);
    }
}
