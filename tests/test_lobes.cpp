// Disney and Oren-Nayar albedo: closed forms, the white furnace, honest error
// estimates and agreement with an independent Monte Carlo estimate.
#include <gtest/gtest.h>

#include <cmath>

#include "brdflut/catalogue.h"
#include "brdflut/disney.h"
#include "brdflut/generate.h"
#include "brdflut/lobe_integrals.h"
#include "brdflut/oren_nayar.h"
#include "brdflut/quadrature.h"

using namespace brdflut;

namespace {
const double kGrazing = 0.5 / 128;
const double kMus[] = {0.0, kGrazing, 0.03, 0.2, 0.5, 0.8, 0.99, 1.0};

// Fujii's G(theta) written as in the paper, for mu away from 0.
double fujii_g(double mu) {
    const double t = std::acos(mu), s = std::sin(t), c = std::cos(t);
    return s * (t - s * c) + (2.0 / 3.0) * ((s / c) * (1.0 - s * s * s) - s);
}
}  // namespace

TEST(DisneyDiffuse, MatchesClosedFormAtZeroRoughness) {
    for (double mu : kMus) {
        const double expected = 41.0 / 42.0 * (1.0 - 0.5 * std::pow(1.0 - mu, 5));
        EXPECT_NEAR(lobe_albedo(Lobe::disney_diffuse, mu, 0.0).value[0], expected, 1e-13) << mu;
    }
}

TEST(DisneyDiffuse, NormalIncidenceIsLinearInRoughnessAndExceedsOneWhenRough) {
    for (double r : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        const double e = lobe_albedo(Lobe::disney_diffuse, 1.0, r).value[0];
        EXPECT_NEAR(e, 41.0 / 42.0 + 5.0 * r / 84.0, 1e-13) << r;
        // 41/42 + 5r/84 > 1 exactly when r > 2/5: the lobe is not energy conserving.
        if (r > 0.4) {
            EXPECT_GT(e, 1.0) << r;
        }
    }
    // And more so at grazing angles.
    EXPECT_GT(lobe_albedo(Lobe::disney_diffuse, 0.1, 1.0).value[0], 1.2);
}

TEST(DisneyDiffuse, AverageAtZeroRoughnessIsTheSquareOf41Over42) {
    EXPECT_NEAR(lobe_albedo_average(Lobe::disney_diffuse, 0.0).value[0], sqr(41.0 / 42.0), 1e-10);
}

TEST(DisneySheen, NormalIncidenceMatchesADirectIntegral) {
    // mu_o = 1: theta_d = theta_i / 2, E = 2 pi integral of (1 - cos(theta/2))^5 cos sin dtheta.
    AdaptiveOptions opt;
    opt.abs_tol = 1e-14;
    const double direct =
        kTwoPi * integrate_adaptive<1>(
                     [](double t) {
                         return std::array<double, 1>{std::pow(1.0 - std::cos(0.5 * t), 5) *
                                                      std::cos(t) * std::sin(t)};
                     },
                     0.0, 0.5 * kPi, opt)
                     .value[0];
    EXPECT_NEAR(lobe_albedo(Lobe::disney_sheen, 1.0, 0.0).value[0], direct, 1e-12);
}

TEST(Gtr1, ProjectedAreaIntegratesToOne) {
    // 2 pi integral of D mu dmu = pi integral of D dc over c = mu^2, taken in
    // y = ln(1 - c), where the peak at c = 1 (width alpha^2) is a smooth step.
    for (double gloss : {0.0, 0.3, 0.7, 1.0}) {
        const double alpha = clearcoat_alpha(gloss);
        AdaptiveOptions opt;
        opt.abs_tol = 1e-12;
        opt.max_intervals = 2000;
        const double v = kPi * integrate_adaptive<1>(
                                   [&](double y) {
                                       const double one_minus_c = std::exp(y);
                                       return std::array<double, 1>{
                                           gtr1_D(std::sqrt(1.0 - one_minus_c), alpha) * one_minus_c};
                                   },
                                   -80.0, 0.0, opt)
                                   .value[0];
        EXPECT_NEAR(v, 1.0, 1e-10) << "gloss " << gloss;
    }
}

TEST(DisneyClearcoat, AlbedoIsBetweenZeroAndOneAndZeroOnTheHorizon) {
    EXPECT_EQ(lobe_albedo(Lobe::disney_clearcoat, 0.0, 0.5).value[0], 0.0);
    for (double g : {0.0, 0.5, 1.0})
        for (double mu : kMus) {
            const double e = lobe_albedo(Lobe::disney_clearcoat, mu, g).value[0];
            EXPECT_GE(e, 0.0);
            EXPECT_LT(e, 1.0);
        }
    // Near normal incidence the lobe reflects about F0 = 0.04.
    EXPECT_NEAR(lobe_albedo(Lobe::disney_clearcoat, 1.0, 1.0).value[0], 0.04, 0.005);
}

TEST(OrenNayar, ZeroRoughnessIsLambertian) {
    for (Lobe lobe : {Lobe::oren_nayar, Lobe::fujii_oren_nayar, Lobe::eon})
        for (double mu : kMus) {
            EXPECT_NEAR(lobe_albedo(lobe, mu, 0.0).value[0], 1.0, 1e-14) << to_string(lobe);
        }
    EXPECT_NEAR(lobe_albedo_average(Lobe::oren_nayar, 0.0).value[0], 1.0, 1e-10);
}

TEST(OrenNayar, QualitativeAlbedoMatchesClosedForm) {
    // E = A + (2B/pi)[(tan_o/3)(1 - sin_o^3) + sin_o (theta_o - sin_o mu_o)/2]
    for (double sigma : {0.1, 0.5, 1.0, 1.5})
        for (double mu : {kGrazing, 0.03, 0.2, 0.5, 0.8, 0.99, 1.0}) {
            const OrenNayar on{sigma};
            const double t = std::acos(mu), s = std::sin(t);
            const double expected =
                on.A() + 2.0 * on.B() / kPi *
                             ((s / mu) / 3.0 * (1.0 - s * s * s) + 0.5 * s * (t - s * mu));
            EXPECT_NEAR(lobe_albedo(Lobe::oren_nayar, mu, sigma).value[0], expected, 1e-10)
                << "sigma " << sigma << " mu " << mu;
        }
}

TEST(FujiiOrenNayar, AlbedoMatchesClosedForm) {
    for (double sigma : {0.1, 0.5, 1.0})
        for (double mu : {kGrazing, 0.03, 0.2, 0.5, 0.8, 0.99, 1.0}) {
            const FujiiOrenNayar fon{sigma};
            const double closed = fon.A() + sigma * fon.A() / kPi * fujii_g(mu);
            EXPECT_NEAR(fon.albedo(mu), closed, 1e-12) << "mu " << mu;
            EXPECT_NEAR(lobe_albedo(Lobe::fujii_oren_nayar, mu, sigma).value[0], closed, 1e-10)
                << "sigma " << sigma << " mu " << mu;
        }
    // Grazing: E(0) = A (1 + c1 sigma) = 1.
    EXPECT_NEAR(lobe_albedo(Lobe::fujii_oren_nayar, 0.0, 0.7).value[0], 1.0, 1e-10);
}

TEST(FujiiOrenNayar, AverageMatchesClosedForm) {
    for (double sigma : {0.0, 0.25, 0.6, 1.0}) {
        const FujiiOrenNayar fon{sigma};
        const double closed = fon.A() * (1.0 + (2.0 / 3.0 - 28.0 / (15.0 * kPi)) * sigma);
        EXPECT_NEAR(lobe_albedo_average(Lobe::fujii_oren_nayar, sigma).value[0], closed, 1e-10);
    }
}

TEST(Eon, IsAWhiteFurnace) {
    for (double sigma : {0.5 / 128, 0.1, 0.5, 0.9, 1.0})
        for (double mu : kMus)
            EXPECT_NEAR(lobe_albedo(Lobe::eon, mu, sigma).value[0], 1.0, 1e-9)
                << "sigma " << sigma << " mu " << mu;
    for (double sigma : {0.3, 1.0})
        EXPECT_NEAR(lobe_albedo_average(Lobe::eon, sigma).value[0], 1.0, 1e-9);
}

TEST(Lobes, ErrorEstimateBoundsTheDifferenceToAMuchFinerRun) {
    const Lobe lobes[] = {Lobe::disney_diffuse,  Lobe::disney_subsurface, Lobe::disney_sheen,
                          Lobe::disney_clearcoat, Lobe::oren_nayar,       Lobe::fujii_oren_nayar,
                          Lobe::eon};
    for (Lobe lobe : lobes)
        for (double p : {0.5 / 128, 0.5, 1.0})
            for (double mu : {kGrazing, 0.05, 0.4, 0.97}) {
                const Estimate<1> e = lobe_albedo(lobe, mu, p, 1e-9);
                const Estimate<1> ref = lobe_albedo(lobe, mu, p, 1e-13);
                EXPECT_LE(std::abs(e.value[0] - ref.value[0]), e.error[0] + 1e-14)
                    << to_string(lobe) << " p " << p << " mu " << mu;
                EXPECT_LE(e.error[0], 1e-9) << to_string(lobe) << " p " << p << " mu " << mu;
            }
}

TEST(DisneyClearcoat, ErrorEstimateIsHonestOnADenseGridDownToGrazing) {
    // The clearcoat's rule (trapezoid on full circles, clipped arcs in
    // tan(phi/4), K31 over P and ln(tan(theta_h))) across gloss and view
    // angles, grazing included.
    for (double g : {0.5 / 128, 0.2, 0.45, 0.7, 0.85, 127.5 / 128})
        for (double mu : {kGrazing, 0.01, 0.03, 0.08, 0.2, 0.35, 0.6, 0.91, 0.995}) {
            const Estimate<1> e = lobe_albedo(Lobe::disney_clearcoat, mu, g, 1e-9);
            const Estimate<1> ref = lobe_albedo(Lobe::disney_clearcoat, mu, g, 1e-13);
            EXPECT_LE(std::abs(e.value[0] - ref.value[0]), e.error[0] + 1e-14)
                << "g " << g << " mu " << mu;
            EXPECT_LE(e.error[0], 1e-9) << "g " << g << " mu " << mu;
        }
}

TEST(Lobes, AverageErrorEstimateBoundsTheDifferenceToAFinerRun) {
    for (Lobe lobe : {Lobe::disney_subsurface, Lobe::disney_sheen, Lobe::disney_clearcoat,
                      Lobe::oren_nayar, Lobe::eon})
        for (double p : {0.5 / 128, 1.0}) {
            const Estimate<1> e = lobe_albedo_average(lobe, p, 1e-9);
            const Estimate<1> ref = lobe_albedo_average(lobe, p, 1e-12);
            EXPECT_LE(std::abs(e.value[0] - ref.value[0]), e.error[0] + 1e-13)
                << to_string(lobe) << " p " << p;
            EXPECT_LE(e.error[0], 1e-9) << to_string(lobe) << " p " << p;
        }
}

TEST(DisneyClearcoat, AverageMatchesTheAverageOfTheDirectionalAlbedo) {
    // The average is integrated over the half vector and wo directly; here it
    // is taken the long way, 2 * integral of E(mu) mu dmu in theta with the
    // directional albedo's own quadrature (broken at mu = 1/4, 1/16, 1/64).
    const double breaks[] = {0.0, std::acos(0.25), std::acos(1.0 / 16), std::acos(1.0 / 64),
                             0.5 * kPi};
    for (double g : {0.5 / 128, 0.45, 127.5 / 128}) {
        AdaptiveOptions opt;
        opt.abs_tol = 1e-12;
        opt.controlled = 1;
        double value = 0.0, error = 0.0;
        for (int k = 0; k < 4; ++k) {
            const Estimate<2> e = integrate_adaptive<2>(
                [&](double theta) -> std::array<double, 2> {
                    const Estimate<1> in = lobe_albedo(Lobe::disney_clearcoat, std::cos(theta), g, 1e-11);
                    const double w = std::sin(2.0 * theta);
                    return {w * in.value[0], w * in.error[0]};
                },
                breaks[k], breaks[k + 1], opt);
            value += e.value[0];
            error += e.error[0] + e.value[1];
        }
        const Estimate<1> direct = lobe_albedo_average(Lobe::disney_clearcoat, g);
        EXPECT_NEAR(direct.value[0], value, direct.error[0] + error + 1e-14) << "g " << g;
        EXPECT_LE(direct.error[0], 1e-9) << "g " << g;
    }
}

TEST(Lobes, AgreeWithMonteCarloWithinFourStandardErrors) {
    const Lobe lobes[] = {Lobe::disney_diffuse,  Lobe::disney_subsurface, Lobe::disney_sheen,
                          Lobe::disney_clearcoat, Lobe::oren_nayar,       Lobe::fujii_oren_nayar,
                          Lobe::eon};
    // A spread of texels, grazing included; the parameter's range ends too.
    const double mus[] = {kGrazing, 0.1, 0.45, 0.9};
    const double ps[] = {0.5 / 128, 0.6, 1.0};
    std::uint64_t seed = 11;
    for (Lobe lobe : lobes)
        for (double mu : mus)
            for (double p : ps) {
                const Estimate<1> q = lobe_albedo(lobe, mu, p);
                const Estimate<1> m = lobe_albedo_mc(lobe, mu, p, 100000, ++seed);
                EXPECT_NEAR(q.value[0], m.value[0], 4.0 * m.error[0] + q.error[0])
                    << to_string(lobe) << " mu " << mu << " p " << p;
            }
}

TEST(Lobes, AveragesAgreeWithMonteCarloWithinFourStandardErrors) {
    const Lobe lobes[] = {Lobe::disney_diffuse,  Lobe::disney_subsurface, Lobe::disney_sheen,
                          Lobe::disney_clearcoat, Lobe::oren_nayar,       Lobe::fujii_oren_nayar};
    std::uint64_t seed = 500;
    for (Lobe lobe : lobes)
        for (double p : {0.2, 0.9}) {
            const Estimate<1> q = lobe_albedo_average(lobe, p);
            const Estimate<1> m = lobe_albedo_average_mc(lobe, p, 100000, ++seed);
            EXPECT_NEAR(q.value[0], m.value[0], 4.0 * m.error[0] + q.error[0])
                << to_string(lobe) << " p " << p;
        }
}

TEST(LobeTables, ValuesMatchTheIntegralsAtTheAxisParameters) {
    // Catches swapped axes or parameters between a table and its companion.
    for (const std::string id : {"disney_diffuse_albedo", "fujii_oren_nayar_albedo"}) {
        TableSettings s = default_settings(find_table(id));
        s.axes[0].count = 4;
        s.axes[1].count = 3;
        const Table t = generate(find_table(id), s);
        TableSettings sa = default_settings(find_table(id + "_avg"));
        sa.axes[0].count = 3;
        const Table avg = generate(find_table(id + "_avg"), sa);
        const Lobe lobe = id == "disney_diffuse_albedo" ? Lobe::disney_diffuse : Lobe::fujii_oren_nayar;
        for (int j = 0; j < 3; ++j) {
            const double p = s.axes[1].value(j);
            EXPECT_DOUBLE_EQ(avg.at(static_cast<std::size_t>(j), 0),
                             lobe_albedo_average(lobe, p).value[0]);
            for (int i = 0; i < 4; ++i)
                EXPECT_DOUBLE_EQ(t.at(static_cast<std::size_t>(j * 4 + i), 0),
                                 lobe_albedo(lobe, s.axes[0].value(i), p).value[0]);
        }
    }
}
