// GGX distribution and split-sum integrals against closed forms and an
// independent Monte Carlo estimate.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "brdflut/catalogue.h"
#include "brdflut/generate.h"
#include "brdflut/ggx_integrals.h"
#include "brdflut/microfacet.h"
#include "brdflut/quadrature.h"
#include "integrate/ggx_simd.h"
#include "test_support.h"

using namespace brdflut;

namespace {
const Visibility kGgxVisibilities[] = {Visibility::height_correlated, Visibility::separable};

}  // namespace

TEST(GgxDistribution, ProjectedAreaIntegratesToOne) {
    for (double alpha : {0.05, 0.2, 0.5, 1.0}) {
        const Ggx g{alpha};
        // In cos(theta_m): D is peaked at mu = 1 with width alpha^2; split there.
        AdaptiveOptions opt;
        opt.abs_tol = 1e-12;
        opt.max_intervals = 4000;
        const double v = kTwoPi * integrate_adaptive<1>([&](double mu) { return std::array<double, 1>{g.D(mu) * mu}; },
                                                        0.0, 1.0, opt)
                                      .value[0];
        EXPECT_NEAR(v, 1.0, 1e-9) << "alpha " << alpha;
    }
}

TEST(GgxDistribution, WeakWhiteFurnaceGivesCosineOfView) {
    // integral of G1(v) max(0, v.h) D(h) dw_h = mu_v. The clipping v.h > 0 is
    // done analytically (cos(phi) > -mu_v mu_h / (sin_v sin_h)) and the mu_h
    // range is split where it starts (mu_h = sin_v), so both rules see smooth
    // integrands.
    for (double alpha : {0.3, 0.7, 1.0})
        for (double mu_v : {0.1, 0.5, 0.95}) {
            const Ggx g{alpha};
            const double sin_v = std::sqrt(1 - mu_v * mu_v);
            AdaptiveOptions opt;
            opt.abs_tol = 1e-13;
            opt.max_intervals = 2000;
            auto over_phi = [&](double mu) {
                const double sin_h = std::sqrt(1 - mu * mu);
                const double c = sin_h > 0 ? -mu_v * mu / (sin_v * sin_h) : -2.0;
                const double phi_max = c <= -1.0 ? kPi : std::acos(c);
                // integral over |phi| < phi_max of (sin_v sin_h cos(phi) + mu_v mu) dphi
                const double inner = 2.0 * (sin_v * sin_h * std::sin(phi_max) + mu_v * mu * phi_max);
                return std::array<double, 1>{g.G1(mu_v) * g.D(mu) * inner};
            };
            double s = 0.0;
            s += integrate_adaptive<1>(over_phi, 0.0, sin_v, opt).value[0];
            s += integrate_adaptive<1>(over_phi, sin_v, 1.0, opt).value[0];
            EXPECT_NEAR(s, mu_v, 1e-10) << "alpha " << alpha << " mu " << mu_v;
        }
}

TEST(GgxSplitSum, AlbedoMatchesClosedFormAtAlphaOne) {
    // alpha = 1, height-correlated: f = 1 / (2 pi (mu_o + mu_i)),
    // E(mu) = 1 - mu ln(1 + 1/mu).
    for (int i = 0; i < 64; ++i) {
        const double mu = (i + 0.5) / 64.0;
        const Estimate<2> e = ggx_split_sum(mu, 1.0, Visibility::height_correlated);
        EXPECT_NEAR(e.value[0] + e.value[1], 1.0 - mu * std::log1p(1.0 / mu), 1e-9) << "mu " << mu;
    }
    EXPECT_NEAR(ggx_split_sum(1.0, 1.0, Visibility::height_correlated).value[0] +
                    ggx_split_sum(1.0, 1.0, Visibility::height_correlated).value[1],
                1.0 - std::log(2.0), 1e-9);
}

TEST(GgxSplitSum, AverageAlbedoMatchesClosedFormAtAlphaOne) {
    const Estimate<1> e = ggx_albedo_average(1.0, Visibility::height_correlated);
    EXPECT_NEAR(e.value[0], 4.0 / 3.0 * (1.0 - std::log(2.0)), 1e-9);
}

TEST(GgxSplitSum, MirrorLimitAsAlphaGoesToZero) {
    for (Visibility vis : kGgxVisibilities)
        for (double mu : {0.05, 0.3, 0.7, 1.0}) {
            const Estimate<2> e = ggx_split_sum(mu, 1e-6, vis);
            EXPECT_NEAR(e.value[0] + e.value[1], 1.0, 1e-4) << "mu " << mu;
            EXPECT_NEAR(e.value[1], std::pow(1.0 - mu, 5), 1e-4) << "mu " << mu;
            const Estimate<2> z = ggx_split_sum(mu, 0.0, vis);
            EXPECT_DOUBLE_EQ(z.value[1], std::pow(1.0 - mu, 5));
            EXPECT_DOUBLE_EQ(z.value[0] + z.value[1], 1.0);
        }
}

TEST(GgxSplitSum, NormalIncidenceLossIsAlphaSquaredForSmallAlpha) {
    // At mu_o = 1 the reflected direction stays above the horizon exactly for
    // tan(theta_h) < 1, which has probability 1 / (1 + alpha^2) under D cos;
    // there (wo.h) / (mu_o cos(theta_h)) = 1 and G2 < 1 matters only where
    // mu_i = cos(2 theta_h) < alpha, a band of probability O(alpha^3), so
    // E(1) = 1 / (1 + alpha^2) - O(alpha^3) (about 1.35 alpha^3). Monte Carlo cannot
    // see this loss (an event of probability alpha^2); this oracle can.
    for (Visibility vis : kGgxVisibilities)
        for (double alpha : {(0.5 / 128) * (0.5 / 128), 1e-4, 1e-3}) {
            const Estimate<2> e = ggx_split_sum(1.0, alpha, vis);
            const double a2 = alpha * alpha;
            const double expected = 1.0 / (1.0 + a2);
            const double slack = 2.0 * a2 * alpha + 1e-15;
            EXPECT_NEAR(e.value[0] + e.value[1], expected, e.error[0] + e.error[1] + slack)
                << "alpha " << alpha;
            // The loss itself, to 1%: the quadrature resolves the steep tail.
            EXPECT_NEAR(1.0 - (e.value[0] + e.value[1]), a2 / (1.0 + a2), 0.01 * a2) << "alpha " << alpha;
        }
}

TEST(GgxSplitSum, GrazingIncidenceGivesTheLimitNotZero) {
    // alpha = 1: E(mu) = 1 - mu ln(1 + 1/mu) -> 1 as mu -> 0.
    const Estimate<2> one = ggx_split_sum(0.0, 1.0, Visibility::height_correlated);
    EXPECT_NEAR(one.value[0] + one.value[1], 1.0, 1e-10);
    // Every alpha and visibility: continuous at mu = 0.
    for (Visibility vis : kGgxVisibilities)
        for (double alpha : {1e-3, 0.1, 0.5}) {
            const Estimate<2> z = ggx_split_sum(0.0, alpha, vis);
            const Estimate<2> near = ggx_split_sum(1e-12, alpha, vis);
            for (int c = 0; c < 2; ++c) {
                EXPECT_TRUE(std::isfinite(z.value[c]));
                EXPECT_NEAR(z.value[c], near.value[c], 1e-7) << "alpha " << alpha;
            }
            EXPECT_GT(z.value[0] + z.value[1], 0.1) << "alpha " << alpha;
        }
}

TEST(GgxSplitSum, SeparableLosesMoreEnergyThanHeightCorrelated) {
    for (double alpha : {0.2, 0.6, 1.0})
        for (double mu : {0.1, 0.5, 0.9}) {
            const auto hc = ggx_split_sum(mu, alpha, Visibility::height_correlated);
            const auto sep = ggx_split_sum(mu, alpha, Visibility::separable);
            EXPECT_LT(sep.value[0] + sep.value[1], hc.value[0] + hc.value[1]);
        }
}

TEST(GgxSplitSum, ErrorEstimateBoundsTheDifferenceToAMuchFinerRun) {
    for (Visibility vis : kGgxVisibilities)
        for (double alpha : {0.5 / 128 * 0.5 / 128, 1e-3, 0.05, 0.3, 0.9})
            for (double mu : {0.5 / 128, 0.02, 0.3, 0.99}) {
                const Estimate<2> e = ggx_split_sum(mu, alpha, vis, 1e-9);
                const Estimate<2> ref = ggx_split_sum(mu, alpha, vis, 1e-13);
                for (int c = 0; c < 2; ++c) {
                    EXPECT_LE(std::abs(e.value[c] - ref.value[c]), e.error[c] + 1e-14)
                        << "alpha " << alpha << " mu " << mu << " channel " << c;
                    EXPECT_LE(e.error[c], 1e-9);
                }
            }
}

TEST(GgxSplitSum, ErrorEstimateIsHonestOnADenseSpreadAtTheTablesTolerances) {
    // Texel centres of the default grid from grazing (mu = 0.5/128) to
    // normal, from the smallest alpha on the grid ((0.5/128)^2) to 1, at the
    // tables' tolerance and at the functions' default, against 1e-12.
    const double mus[] = {0.5 / 128, 1.5 / 128, 4.5 / 128, 0.1, 0.25, 0.5, 0.75, 0.9, 127.5 / 128};
    const double roughness[] = {0.5 / 128, 1.5 / 128, 4.5 / 128, 0.1, 0.2, 0.35, 0.5, 0.7, 0.85, 127.5 / 128};
    for (Visibility vis : kGgxVisibilities)
        for (double r : roughness)
            for (double mu : mus) {
                const double alpha = r * r;
                const Estimate<2> ref = ggx_split_sum(mu, alpha, vis, 1e-12);
                for (double tol : {kGgxTableTolerance, kGgxAbsTolerance}) {
                    const Estimate<2> e = ggx_split_sum(mu, alpha, vis, tol);
                    for (int c = 0; c < 2; ++c) {
                        EXPECT_LE(std::abs(e.value[c] - ref.value[c]), e.error[c] + ref.error[c])
                            << "alpha " << alpha << " mu " << mu << " tol " << tol << " channel " << c;
                        EXPECT_LE(e.error[c], tol) << "alpha " << alpha << " mu " << mu;
                    }
                }
            }
}

TEST(GgxSplitSum, EverySimdWidthGivesTheSameBits) {
    // The phi integrands run 4 (AVX2), 2 (SSE2) or 1 node at a time; each
    // width must give exactly the values, errors and work of one at a time.
    test::expect_same_bits_at_every_ggx_simd_width([] {
        std::vector<Estimate<2>> out;
        for (Visibility vis : kGgxVisibilities)
            for (double alpha : {(0.5 / 128) * (0.5 / 128), 3e-3, 0.08, 0.45, 1.0})
                for (double mu : {0.5 / 128, 0.04, 0.3, 0.8, 1.0})
                    out.push_back(ggx_split_sum(mu, alpha, vis, kGgxTableTolerance));
        return out;
    });
}

TEST(GgxSplitSum, AgreesWithMonteCarloWithinFourStandardErrors) {
    const double grazing = 0.5 / 128, smallest_alpha = (0.5 / 128) * (0.5 / 128);
    const double mus[] = {grazing, 0.05, 0.3, 0.7, 1.0};
    const double alphas[] = {smallest_alpha, 0.01, 0.1, 0.4, 1.0};
    std::uint64_t seed = 7;
    for (Visibility vis : kGgxVisibilities)
        for (double mu : mus)
            for (double alpha : alphas) {
                const Estimate<2> q = ggx_split_sum(mu, alpha, vis);
                const long long samples = 200000;
                const Estimate<2> m = ggx_split_sum_mc(mu, alpha, vis, samples, ++seed);
                for (int c = 0; c < 2; ++c) {
                    // Both are estimates: allow the quadrature's own error estimate too.
                    const double tol = 4.0 * m.error[c] + q.error[c];
                    EXPECT_NEAR(q.value[c], m.value[c], tol)
                        << "mu " << mu << " alpha " << alpha << " channel " << c << " vis " << to_string(vis);
                }
            }
}

TEST(GgxAverage, AgreesWithMonteCarloWithinFourStandardErrors) {
    // Down to the smallest alpha of the default grid: the energy lost there
    // (~alpha^2, from the steep microfacets of GGX's long tail) is only seen
    // because the sampler's wide stratum makes those microfacets common.
    std::uint64_t seed = 100;
    for (Visibility vis : kGgxVisibilities)
        for (double alpha : {(0.5 / 128) * (0.5 / 128), 1e-4, 0.01, 0.05, 0.3, 0.8}) {
            const Estimate<1> q = ggx_albedo_average(alpha, vis);
            const Estimate<1> m = ggx_albedo_average_mc(alpha, vis, 400000, ++seed);
            EXPECT_NEAR(q.value[0], m.value[0], 4.0 * m.error[0] + q.error[0]) << "alpha " << alpha;
        }
}

TEST(GgxAverage, ErrorEstimateBoundsTheDifferenceToAMuchFinerRun) {
    for (Visibility vis : kGgxVisibilities)
        for (double r : {0.5 / 128, 2.5 / 128, 0.1, 0.3, 0.6, 127.5 / 128}) {
            const double alpha = r * r;
            const Estimate<1> ref = ggx_albedo_average(alpha, vis, 1e-12);
            for (double tol : {kGgxTableTolerance, kGgxAbsTolerance}) {
                const Estimate<1> e = ggx_albedo_average(alpha, vis, tol);
                EXPECT_LE(std::abs(e.value[0] - ref.value[0]), e.error[0] + ref.error[0])
                    << "alpha " << alpha << " tol " << tol;
                EXPECT_LE(e.error[0], tol) << "alpha " << alpha;
            }
        }
}

TEST(GgxAverage, MirrorLimitIsOne) {
    EXPECT_EQ(ggx_albedo_average(0.0, Visibility::height_correlated).value[0], 1.0);
    EXPECT_NEAR(ggx_albedo_average(1e-6, Visibility::height_correlated).value[0], 1.0, 1e-9);
}

TEST(GgxTables, SharedSplitSumsNeverChangeAValue) {
    // ggx_albedo reuses the split sums of ggx_dfg generated in the same
    // process: its values must be exactly those of a fresh computation,
    // whatever was generated before and with how many threads.
    auto settings = [](const char* id) {
        TableSettings s = default_settings(find_table(id));
        for (Axis& a : s.axes) a.count = 12;
        return s;
    };
    auto fresh = [](const Table& t, std::size_t k) {
        const int i = static_cast<int>(k % 12), j = static_cast<int>(k / 12);
        const Estimate<2> e = ggx_split_sum(t.axes[0].value(i), t.axes[1].value(j),
                                            Visibility::height_correlated, kGgxTableTolerance);
        return e;
    };
    GenerateOptions one, two;
    one.threads = 1;
    two.threads = 2;
    const Table albedo_first = generate(find_table("ggx_albedo"), settings("ggx_albedo"), two);
    const Table dfg = generate(find_table("ggx_dfg"), settings("ggx_dfg"), one);
    const Table albedo_after = generate(find_table("ggx_albedo"), settings("ggx_albedo"), two);
    ASSERT_EQ(albedo_first.values.size(), 144u);
    for (std::size_t k = 0; k < 144; ++k) {
        const Estimate<2> e = fresh(dfg, k);
        EXPECT_EQ(dfg.at(k, 0), e.value[0]) << "texel " << k;
        EXPECT_EQ(dfg.at(k, 1), e.value[1]) << "texel " << k;
        EXPECT_EQ(albedo_first.at(k, 0), e.value[0] + e.value[1]) << "texel " << k;
        EXPECT_EQ(albedo_after.at(k, 0), albedo_first.at(k, 0)) << "texel " << k;
        EXPECT_EQ(albedo_after.errors[k], albedo_first.errors[k]) << "texel " << k;
    }
}

TEST(GgxTables, StoredValuesAreWithinOneFloatStepOfTheIntegral) {
    // The error bound of every value (estimate + rounding to float) is at
    // most 1e-7, and the float values are within it of a 1e-12 run.
    for (const char* id : {"ggx_dfg", "ggx_albedo_avg"}) {
        TableSettings s = default_settings(find_table(id));
        for (Axis& a : s.axes) a.count = 9;
        const Table t = generate(find_table(id), s);
        EXPECT_LE(error_bound(t, PixelType::float32), 1e-7) << id;
        for (std::size_t k = 0; k < t.texel_count(); ++k) {
            const int i = static_cast<int>(k % 9);
            double ref[2];
            if (t.axes.size() == 1) {
                ref[0] = ggx_albedo_average(t.axes[0].value(i), Visibility::height_correlated, 1e-12).value[0];
            } else {
                const Estimate<2> e = ggx_split_sum(t.axes[0].value(i), t.axes[1].value(static_cast<int>(k / 9)),
                                                    Visibility::height_correlated, 1e-12);
                ref[0] = e.value[0];
                ref[1] = e.value[1];
            }
            for (int c = 0; c < t.channel_count(); ++c) {
                const double stored = round_to_storage(t.at(k, c), PixelType::float32);
                EXPECT_LE(std::abs(stored - ref[c]), 1e-7) << id << " texel " << k;
            }
        }
    }
}

TEST(GgxMonteCarlo, IsReproducibleForASeed) {
    const auto a = ggx_split_sum_mc(0.4, 0.3, Visibility::height_correlated, 1000, 42);
    const auto b = ggx_split_sum_mc(0.4, 0.3, Visibility::height_correlated, 1000, 42);
    const auto c = ggx_split_sum_mc(0.4, 0.3, Visibility::height_correlated, 1000, 43);
    EXPECT_EQ(a.value, b.value);
    EXPECT_NE(a.value, c.value);
}
