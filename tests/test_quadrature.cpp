#include <gtest/gtest.h>

#include <cmath>

#include "brdflut/math.h"
#include "brdflut/quadrature.h"

using namespace brdflut;

TEST(GaussLegendre, IntegratesPolynomialsOfDegreeTwoNMinusOneExactly) {
    for (int n : {1, 2, 5, 16, 33}) {
        const GaussLegendre& r = gauss_legendre(n);
        for (int deg = 0; deg <= 2 * n - 1; ++deg) {
            double s = 0.0;
            for (int i = 0; i < n; ++i) s += r.w[static_cast<std::size_t>(i)] * std::pow(r.x[static_cast<std::size_t>(i)], deg);
            const double exact = deg % 2 ? 0.0 : 2.0 / (deg + 1);
            EXPECT_NEAR(s, exact, 1e-14) << "n=" << n << " degree=" << deg;
        }
    }
}

TEST(GaussKronrod, SinglePanelIsExactForDegreeTwentyOne) {
    AdaptiveOptions opt;
    opt.max_intervals = 1;
    const auto e = integrate_adaptive<1>(
        [](double x) { return std::array<double, 1>{std::pow(x, 21) + std::pow(x, 20)}; }, 0.0, 1.0, opt);
    EXPECT_NEAR(e.value[0], 1.0 / 22 + 1.0 / 21, 1e-15);
    EXPECT_EQ(e.evaluations, 15);
}

TEST(GaussKronrod, AdaptiveMeetsToleranceAndErrorEstimateIsHonest) {
    struct Case {
        double (*f)(double);
        double a, b, exact;
    };
    const Case cases[] = {
        {[](double x) { return std::sqrt(x); }, 0.0, 1.0, 2.0 / 3.0},             // endpoint singularity
        {[](double x) { return 1.0 / (1e-4 + x * x); }, -1.0, 1.0, 2.0 * std::atan(100.0) * 100.0},  // sharp peak
        {[](double x) { return std::exp(-x); }, 0.0, 40.0, 1.0 - std::exp(-40.0)},
        {[](double x) { return std::abs(x - 0.3); }, 0.0, 1.0, 0.5 * (0.09 + 0.49)},  // kink
    };
    for (const Case& c : cases) {
        AdaptiveOptions opt;
        opt.abs_tol = 1e-10;
        opt.max_intervals = 2000;
        const auto e = integrate_adaptive<1>([&](double x) { return std::array<double, 1>{c.f(x)}; }, c.a, c.b, opt);
        const double actual = std::abs(e.value[0] - c.exact);
        EXPECT_LE(actual, std::max(e.error[0], 1e-15 * std::abs(c.exact))) << "exact " << c.exact;
        EXPECT_LE(e.error[0], 1e-10 + 1e-13 * std::abs(c.exact));
    }
}

TEST(GaussKronrod, ResultDoesNotDependOnCallOrder) {
    auto f = [](double x) { return std::array<double, 2>{std::sin(x) * std::exp(x), std::cos(3 * x)}; };
    const auto a = integrate_adaptive<2>(f, 0.0, 10.0);
    const auto b = integrate_adaptive<2>(f, 0.0, 10.0);
    EXPECT_EQ(a.value, b.value);
    EXPECT_EQ(a.error, b.error);
}
