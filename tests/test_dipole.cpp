// Dipole subsurface tables: the diffuse Fresnel term, the profile and its
// closed-form integrals against quadrature and Monte Carlo, the albedo
// inversion, the generated tables and bad input.
#include <gtest/gtest.h>

#include <cmath>

#include "brdflut/catalogue.h"
#include "brdflut/dipole.h"
#include "brdflut/dipole_integrals.h"
#include "brdflut/error.h"
#include "brdflut/exr.h"
#include "brdflut/fresnel.h"
#include "brdflut/generate.h"
#include "test_support.h"

using namespace brdflut;
using brdflut::test::run_cli;
using brdflut::test::TempDir;

namespace {

// Closed form of the dielectric Fresnel hemispherical average for n > 1
// (light arriving from the less dense side), from the field notes.
double fresnel_average_closed_form(double n) {
    const double n2 = n * n, n4 = n2 * n2;
    return 0.5 + (n - 1) * (3 * n + 1) / (6 * (n + 1) * (n + 1)) +
           n2 * (n2 - 1) * (n2 - 1) / std::pow(n2 + 1, 3) * std::log((n - 1) / (n + 1)) -
           2 * n2 * n * (n2 + 2 * n - 1) / ((n2 + 1) * (n4 - 1)) +
           8 * n4 * (n4 + 1) / ((n2 + 1) * (n4 - 1) * (n4 - 1)) * std::log(n);
}

double A_of(double eta, DiffuseFresnel f) {
    return dipole_boundary_term(diffuse_fresnel_reflectance(eta, f));
}

struct Boundary {
    double eta;
    DiffuseFresnel f;
};
const Boundary kBoundaries[] = {{1.0, DiffuseFresnel::fit},   {1.3, DiffuseFresnel::fit},
                                {2.0, DiffuseFresnel::fit},   {0.75, DiffuseFresnel::exact},
                                {1.3, DiffuseFresnel::exact}, {1.5, DiffuseFresnel::exact},
                                {3.0, DiffuseFresnel::exact}};
const double kAlbedos[] = {0.01, 0.2, 0.5, 0.8, 0.95, 0.99, 0.9999, 1.0};

TableSettings settings(const std::string& id, std::map<std::string, std::string> params = {}) {
    TableSettings s = default_settings(find_table(id));
    for (auto& [k, v] : params) s.params[k] = v;
    return s;
}

}  // namespace

TEST(DipoleFresnel, ExactIsTheFresnelAverageSeenFromInside) {
    // Inside a medium of index n: F_avg(1/n) = 1 - (1 - F_avg(n)) / n^2.
    for (double eta : {1.1, 1.3, 1.5, 2.0, 3.0}) {
        const double inside = 1.0 - (1.0 - fresnel_average_closed_form(eta)) / (eta * eta);
        EXPECT_NEAR(diffuse_fresnel_reflectance_exact(eta), inside, 1e-10) << "eta " << eta;
    }
    // A medium less dense than its surroundings: plain external reflection.
    EXPECT_NEAR(diffuse_fresnel_reflectance_exact(1.0 / 1.5), fresnel_average_closed_form(1.5), 1e-10);
    EXPECT_NEAR(diffuse_fresnel_reflectance_exact(1.0), 0.0, 1e-15);
}

TEST(DipoleFresnel, FitMatchesJensensValueAndTheExactAverageWithinItsAccuracy) {
    EXPECT_NEAR(diffuse_fresnel_reflectance_fit(1.3), 0.444763, 1e-6);
    EXPECT_NEAR(diffuse_fresnel_reflectance_exact(1.3), 0.444457, 1e-6);
    // Measured deviation: under 0.0016 on [1, 2], 0.005 at 2.5, 0.016 at 3.
    for (double eta = 1.0; eta <= 2.0 + 1e-9; eta += 0.05)
        EXPECT_NEAR(diffuse_fresnel_reflectance_fit(eta), diffuse_fresnel_reflectance_exact(eta), 2e-3)
            << "eta " << eta;
    for (double eta : {2.5, 3.0}) {
        const double exact = diffuse_fresnel_reflectance_exact(eta);
        EXPECT_NEAR(diffuse_fresnel_reflectance_fit(eta), exact, 0.02 * exact) << "eta " << eta;
    }
}

TEST(DipoleTotal, QuadratureOfTheProfileMatchesTheClosedForm) {
    for (const Boundary& b : kBoundaries)
        for (double albedo : kAlbedos) {
            const double A = A_of(b.eta, b.f);
            const Dipole d = Dipole::from_albedo(albedo, A);
            const Estimate<1> q = dipole_reflectance_quadrature(d, HUGE_VAL, 1e-13);
            const double closed = dipole_total_reflectance(albedo, A);
            EXPECT_NEAR(q.value[0], closed, 1e-10 * closed) << "eta " << b.eta << " albedo " << albedo;
            EXPECT_LE(std::abs(q.value[0] - closed), q.error[0] + 1e-15) << "albedo " << albedo;
            EXPECT_NEAR(d.total_reflectance(), closed, 1e-15);
        }
}

TEST(DipoleTotal, DoesNotDependOnTheLengthScale) {
    // Marble's red channel in 1/mm and the same medium in 1/m: R_d scales by
    // sigma_t'^2, the total not at all.
    const double A = A_of(1.3, DiffuseFresnel::fit);
    const Dipole mm(2.19, 0.0021, A), m(2190.0, 2.1, A);
    const double closed = dipole_total_reflectance(2.19 / 2.1921, A);
    EXPECT_NEAR(dipole_reflectance_quadrature(mm, HUGE_VAL, 1e-13).value[0], closed, 1e-10);
    EXPECT_NEAR(dipole_reflectance_quadrature(m, HUGE_VAL, 1e-13).value[0], closed, 1e-10);
    EXPECT_NEAR(m.profile(1e-3), 1e6 * mm.profile(1.0), 1e-9 * m.profile(1e-3));
}

TEST(DipoleProfile, ClosedFormRadialIntegralMatchesQuadrature) {
    for (const Boundary& b : kBoundaries)
        for (double albedo : kAlbedos)
            for (double r : {1e-4, 0.01, 0.3, 1.0, 4.0, 30.0, 500.0}) {
                const Dipole d = Dipole::from_albedo(albedo, A_of(b.eta, b.f));
                const Estimate<1> q = dipole_reflectance_quadrature(d, r, 1e-14);
                EXPECT_NEAR(d.reflectance_within(r), q.value[0], 1e-13 + 1e-11 * q.value[0])
                    << "eta " << b.eta << " albedo " << albedo << " r " << r;
            }
}

TEST(DipoleTotal, AgreesWithMonteCarloWithinFourStandardErrors) {
    std::uint64_t seed = 11;
    for (const Boundary& b : {kBoundaries[1], kBoundaries[3], kBoundaries[6]})
        for (double albedo : {0.05, 0.5, 0.9, 0.99, 1.0}) {
            const double A = A_of(b.eta, b.f);
            const Estimate<1> m = dipole_total_reflectance_mc(Dipole::from_albedo(albedo, A), 200000, ++seed);
            EXPECT_NEAR(m.value[0], dipole_total_reflectance(albedo, A), 4.0 * m.error[0])
                << "eta " << b.eta << " albedo " << albedo;
            EXPECT_LT(m.error[0], 0.01 * m.value[0]);  // the estimate is informative
        }
}

TEST(DipoleInverse, InvertsTheTotalReflectanceTo1e12) {
    for (const Boundary& b : kBoundaries) {
        const double A = A_of(b.eta, b.f);
        for (int i = 0; i <= 400; ++i) {
            const double albedo = i < 400 ? i / 400.0 : 1.0;
            for (double a : {albedo, 1.0 - 1e-6 * albedo}) {
                double err = -1.0;
                const double inv = dipole_albedo_from_reflectance(dipole_total_reflectance(a, A), A, &err);
                EXPECT_NEAR(inv, a, 1e-12) << "eta " << b.eta << " albedo " << a;
                EXPECT_GE(err, 0.0);
                EXPECT_LE(err, 1e-12);
                // The estimate bounds the actual error (a' itself is only known to
                // the rounding of its total, a few 1e-16 here).
                EXPECT_LE(std::abs(inv - a), err + 1e-15) << "albedo " << a;
            }
        }
        // Near a' = 1 the total's slope in a' is ~1/sqrt(1 - a'), so rounding a'
        // to double moves the total by up to ~1e-13 there.
        for (int i = 0; i <= 100; ++i) {
            const double R = i / 100.0;
            EXPECT_NEAR(dipole_total_reflectance(dipole_albedo_from_reflectance(R, A), A), R, 1e-12);
        }
        EXPECT_EQ(dipole_albedo_from_reflectance(0.0, A), 0.0);
        EXPECT_EQ(dipole_albedo_from_reflectance(1.0, A), 1.0);
    }
}

TEST(DipoleTotal, RisesFromZeroToOneForEveryBoundary) {
    for (const Boundary& b : kBoundaries) {
        const double A = A_of(b.eta, b.f);
        EXPECT_EQ(dipole_total_reflectance(0.0, A), 0.0);
        EXPECT_EQ(dipole_total_reflectance(1.0, A), 1.0);
        double prev = 0.0;
        for (int i = 1; i <= 1000; ++i) {
            const double t = dipole_total_reflectance(i / 1000.0, A);
            EXPECT_GT(t, prev) << "albedo " << i / 1000.0;
            prev = t;
        }
    }
}

TEST(DipoleProfile, IsPositiveAndDecreasingInRadius) {
    for (const Boundary& b : kBoundaries)
        for (double albedo : kAlbedos) {
            const Dipole d = Dipole::from_albedo(albedo, A_of(b.eta, b.f));
            double prev = d.profile(0.0);
            for (double r = 1e-4; r <= 100.0; r *= 1.1) {
                const double v = d.profile(r);
                EXPECT_GT(v, 0.0) << "albedo " << albedo << " r " << r;
                EXPECT_LT(v, prev) << "albedo " << albedo << " r " << r;
                prev = v;
            }
        }
}

TEST(DipoleProfile, CdfRisesFromZeroToOne) {
    for (const Boundary& b : kBoundaries)
        for (double albedo : {0.0, 0.01, 0.5, 0.99, 1.0}) {
            const Dipole d = Dipole::from_albedo(albedo, A_of(b.eta, b.f));
            EXPECT_EQ(d.cdf(0.0), 0.0);
            double prev = 0.0;
            for (double r = 1e-4; r <= 1e4; r *= 1.2) {
                const double c = d.cdf(r);
                // Strictly rising until it reaches 1 to double precision.
                if (prev < 1.0 - 1e-12) {
                    EXPECT_GT(c, prev) << "albedo " << albedo << " r " << r;
                }
                EXPECT_GE(c, prev) << "albedo " << albedo << " r " << r;
                EXPECT_LE(c, 1.0);
                prev = c;
            }
            EXPECT_EQ(d.cdf(HUGE_VAL), 1.0);
            // Without absorption the tail is (z_r/d_r + z_v/d_v)/2 ~ (z_r + z_v)/(2r).
            EXPECT_GT(d.cdf(1e9), 1.0 - 1e-7) << "albedo " << albedo;
        }
    // Albedo 0 gives the finite limit of albedo -> 0.
    const double A = A_of(1.3, DiffuseFresnel::fit);
    for (double r : {0.1, 1.0, 5.0})
        EXPECT_NEAR(Dipole::from_albedo(0.0, A).cdf(r), Dipole::from_albedo(1e-9, A).cdf(r), 1e-8);
}

TEST(DipoleTables, GeneratedValuesMatchTheModel) {
    TableSettings s = settings("dipole_profile", {{"eta", "1.4"}, {"fdr", "exact"}});
    s.axes[0].count = 9;
    s.axes[1].count = 5;
    s.axes[1].placement = Placement::endpoints;  // albedo 0 and 1 included
    const Table t = generate(find_table("dipole_profile"), s);
    const double A = A_of(1.4, DiffuseFresnel::exact);
    for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 9; ++i) {
            const Dipole d = Dipole::from_albedo(s.axes[1].value(j), A);
            const double r = s.axes[0].value(i);
            const std::size_t k = static_cast<std::size_t>(j * 9 + i);
            EXPECT_EQ(t.at(k, 0), d.profile(r));
            EXPECT_EQ(t.at(k, 1), d.cdf(r));
            EXPECT_TRUE(std::isfinite(t.at(k, 0)) && std::isfinite(t.at(k, 1)));
        }
    EXPECT_EQ(t.model.at("fdr"), "exact");
    EXPECT_EQ(t.model.at("eta"), 1.4);
    EXPECT_NEAR(t.model.at("F_dr").get<double>(), diffuse_fresnel_reflectance_exact(1.4), 1e-15);

    const Table tot = generate(find_table("dipole_total"), settings("dipole_total"));
    const Table inv = generate(find_table("dipole_albedo_inverse"), settings("dipole_albedo_inverse"));
    const double A13 = A_of(1.3, DiffuseFresnel::fit);
    EXPECT_EQ(tot.model.at("fdr"), "fit");
    for (int i = 0; i < 128; ++i) {
        EXPECT_EQ(tot.at(static_cast<std::size_t>(i), 0), dipole_total_reflectance((i + 0.5) / 128, A13));
        const double a = inv.at(static_cast<std::size_t>(i), 0);
        EXPECT_NEAR(dipole_total_reflectance(a, A13), (i + 0.5) / 128, 1e-12);
    }
}

TEST(DipoleTables, EveryDefaultTableIsFiniteAndWithinStoragePrecision) {
    TempDir dir;
    for (const char* id : {"dipole_profile", "dipole_total", "dipole_albedo_inverse", "dipole_profile_rgb"}) {
        const Table t = generate(find_table(id), settings(id));
        EXPECT_LT(error_bound(t, PixelType::float32), 1e-7) << id;
        EXPECT_NO_THROW(write_exr(dir / (std::string(id) + ".exr"), t, PixelType::float32)) << id;
    }
}

TEST(DipoleTables, MonteCarloTotalAgreesWithTheClosedForm) {
    TableSettings s = settings("dipole_total");
    s.axes[0].count = 16;
    s.method = Method::monte_carlo;
    s.samples = 20000;
    const Table m = generate(find_table("dipole_total"), s);
    const double A = A_of(1.3, DiffuseFresnel::fit);
    for (int i = 0; i < 16; ++i) {
        const std::size_t k = static_cast<std::size_t>(i);
        // The stored error is already 4 standard errors.
        EXPECT_NEAR(m.at(k, 0), dipole_total_reflectance((i + 0.5) / 16, A), m.errors[k]) << i;
    }
    EXPECT_EQ(m.method.at("name"), "mc");
}

TEST(DipoleTables, SameBytesForAnyThreadCount) {
    TempDir dir;
    for (const std::string id : {"dipole_profile", "dipole_albedo_inverse"}) {
        TableSettings s = settings(id);
        for (Axis& a : s.axes) a.count = 24;
        GenerateOptions one, two;
        one.threads = 1;
        two.threads = 2;
        write_exr(dir / (id + "1.exr"), generate(find_table(id), s, one), PixelType::float32);
        write_exr(dir / (id + "2.exr"), generate(find_table(id), s, two), PixelType::float32);
        EXPECT_EQ(test::read_file(dir / (id + "1.exr")), test::read_file(dir / (id + "2.exr"))) << id;
    }
}

TEST(DipoleRgb, MaterialCoefficientsGiveTheProfileOfEachChannel) {
    const Table t = generate(find_table("dipole_profile_rgb"), settings("dipole_profile_rgb", {{"material", "marble"}}));
    const MeasuredMaterial& m = find_measured_material("marble");
    const double A = A_of(1.3, DiffuseFresnel::fit);
    for (int i = 0; i < t.width(); i += 17)
        for (int c = 0; c < 3; ++c) {
            const Dipole d(m.sigma_s_prime[static_cast<std::size_t>(c)], m.sigma_a[static_cast<std::size_t>(c)], A);
            EXPECT_EQ(t.at(static_cast<std::size_t>(i), c), d.profile(t.axes[0].value(i)));
        }
    EXPECT_EQ(t.model.at("material"), "marble");

    const Table custom = generate(find_table("dipole_profile_rgb"),
                                  settings("dipole_profile_rgb", {{"sigma-s", "2.19,2.62,3"},
                                                                  {"sigma-a", "0.0021,0.0041,0.0071"}}));
    EXPECT_EQ(custom.values, t.values);
    EXPECT_EQ(custom.model.at("material"), "custom");
}

TEST(DipoleRgb, DefaultRadiusRangeCapturesEveryMeasuredProfile) {
    // [1e-3, 100] mm: below 1e-3 mm the profile is flat to 1e-4 (the
    // smallest z_r is cream's red, 0.135 mm); beyond 100 mm lies less than
    // 3e-4 of the reflectance (the longest decay, skim milk's red, 1/s_tr = 18 mm).
    const double A = A_of(1.3, DiffuseFresnel::fit);
    for (const MeasuredMaterial& m : measured_materials())
        for (std::size_t c = 0; c < 3; ++c) {
            const Dipole d(m.sigma_s_prime[c], m.sigma_a[c], A);
            EXPECT_GT(d.profile(1e-3), (1.0 - 1e-4) * d.profile(0.0)) << m.name << " " << c;
            EXPECT_GT(d.cdf(100.0), 1.0 - 3e-4) << m.name << " " << c;
        }
}

TEST(DipoleErrors, BadInputNamesTheValueAndWhatIsAllowed) {
    auto message = [](auto&& f) -> std::string {
        try {
            f();
        } catch (const Error& e) {
            return e.what();
        }
        return "no error";
    };
    const double A = A_of(1.3, DiffuseFresnel::fit);
    EXPECT_NE(message([&] { Dipole::from_albedo(1.5, A); }).find("allowed: 0 <= albedo <= 1"), std::string::npos);
    EXPECT_NE(message([&] { dipole_total_reflectance(-0.1, A); }).find("allowed: 0 <= albedo <= 1"), std::string::npos);
    EXPECT_NE(message([&] { dipole_albedo_from_reflectance(1.2, A); }).find("allowed: 0 <= reflectance <= 1"),
              std::string::npos);
    EXPECT_NE(message([&] { Dipole(-1.0, 0.1, A); }).find("allowed: a finite value >= 0"), std::string::npos);
    EXPECT_NE(message([&] { Dipole(1.0, -0.1, A); }).find("allowed: a finite value >= 0"), std::string::npos);
    EXPECT_NE(message([&] { validate_dipole_eta(0.0, DiffuseFresnel::exact); }).find("allowed: 0 < eta <= 10"),
              std::string::npos);
    EXPECT_NE(message([&] { validate_dipole_eta(0.9, DiffuseFresnel::fit); }).find("allowed: 1 <= eta <= 3"),
              std::string::npos);
    EXPECT_NE(message([&] { find_measured_material("jelly"); }).find("allowed: apple, chicken1"), std::string::npos);
    EXPECT_NE(message([&] { diffuse_fresnel_from_string("approx"); }).find("allowed: fit, exact"), std::string::npos);
}

TEST(DipoleErrors, CommandLineRejectsBadValuesWithAClearMessage) {
    TempDir dir;
    struct Case {
        std::string args, expect;
    };
    const Case cases[] = {
        {"generate dipole_profile --eta 0", "--eta 0 is out of range"},
        {"generate dipole_profile --eta -2 --fdr exact", "allowed: 0 < eta <= 10"},
        {"generate dipole_total --eta abc", "--eta 'abc' is not a finite number"},
        {"generate dipole_total --fdr approx", "allowed: fit, exact"},
        {"generate dipole_total --range albedo=0:1.2", "allowed: within 0:1"},
        {"generate dipole_albedo_inverse --range reflectance=-0.1:1", "allowed: within 0:1"},
        {"generate dipole_profile_rgb --material jelly", "allowed: apple, chicken1, chicken2"},
        {"generate dipole_profile_rgb --sigma-s 1,2,3 --sigma-a 0.1,-0.2,0", "--sigma-a '0.1,-0.2,0' is not valid"},
        {"generate dipole_profile_rgb --sigma-s 1,2 --sigma-a 0.1,0.2,0.3", "allowed: r,g,b"},
        {"generate dipole_profile_rgb --sigma-s 1,2,3", "--sigma-s and --sigma-a go together"},
        {"generate dipole_profile_rgb --sigma-s 1,0,3 --sigma-a 1,0,1", "both 0 in channel 1"},
        {"generate dipole_profile_rgb --material marble --sigma-s 1,2,3 --sigma-a 1,1,1", "one of them"},
    };
    for (const Case& c : cases) {
        const auto r = run_cli(c.args + " -o '" + (dir / "o") + "'", dir);
        EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.expect), std::string::npos) << c.args << "\n" << r.err;
    }
    const auto ok = run_cli("generate dipole_profile_rgb --material cream --fdr exact --eta 1.5 -q -o '" +
                                (dir / "ok") + "'",
                            dir);
    ASSERT_EQ(ok.exit_code, 0) << ok.err;
    const ExrImage img = read_exr(dir / "ok/dipole_profile_rgb.exr");
    EXPECT_EQ(img.metadata.at("model").at("material"), "cream");
    EXPECT_EQ(img.metadata.at("model").at("fdr"), "exact");
    EXPECT_EQ(img.metadata.at("model").at("eta"), 1.5);
}
