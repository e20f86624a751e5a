// Burley normalized diffusion: the profile's integral, its CDF and inverse
// CDF against quadrature and bisection, the scalings, the slab transmission,
// and the generated tables.
#include <gtest/gtest.h>

#include <cmath>

#include "brdflut/burley.h"
#include "brdflut/catalogue.h"
#include "brdflut/dipole.h"
#include "brdflut/dipole_integrals.h"
#include "brdflut/error.h"
#include "brdflut/exr.h"
#include "brdflut/generate.h"
#include "brdflut/math.h"
#include "brdflut/quadrature.h"
#include "brdflut/skin.h"
#include "test_support.h"

using namespace brdflut;

namespace {

// integral of 2 pi r R(r) dr over [a, b] for a profile given in mm, by
// adaptive Gauss-Kronrod in ln(r) (b may be infinite: cut at 1e4 d).
double integral_2pi_r(const RadialProfile& p, double a, double b) {
    AdaptiveOptions opt;
    opt.abs_tol = 1e-15;
    opt.max_intervals = 4000;
    opt.rule = KronrodRule::k21;
    const double hi = std::min(b, 1e4 * p.scale());
    return integrate_adaptive_panels<1>(
               [&](double t) {
                   const double r = std::exp(t);
                   return std::array<double, 1>{kTwoPi * r * r * p.value(r)};
               },
               std::log(std::max(a, 1e-300)), std::log(hi), 64, opt)
        .value[0];
}

// CDF(x) = u by bisection on the closed form (no cubic, no Newton): on the
// CDF below u = 1/2, on its complement above (where 1 - u is exact and the
// CDF itself, within an ulp of 1, would fix x only to eps / density).
double inverse_by_bisection(double u) {
    auto below = [u](double x) { return u < 0.5 ? burley_cdf(x) < u : burley_cdf_complement(x) > 1.0 - u; };
    double lo = 0.0, hi = 1.0;
    while (below(hi)) hi *= 2.0;
    for (int i = 0; i < 400; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (mid == lo || mid == hi) break;
        if (below(mid)) lo = mid; else hi = mid;
    }
    return 0.5 * (lo + hi);
}

TableSettings settings(const std::string& id) { return default_settings(find_table(id)); }

}  // namespace

TEST(BurleyProfile, IntegratesToTheAlbedoForEveryScaleAndAlbedo) {
    for (double A : {0.05, 0.4, 0.9, 1.0})
        for (double d : {0.01, 0.3, 1.0, 25.0}) {
            const RadialProfile p = RadialProfile::burley(A, d);
            EXPECT_NEAR(integral_2pi_r(p, 0.0, HUGE_VAL), A, 1e-12 * A) << "A " << A << " d " << d;
            EXPECT_DOUBLE_EQ(p.total(), A);
        }
}

TEST(BurleyProfile, CdfIsTheClosedFormOfTheProfilesIntegral) {
    const RadialProfile p = RadialProfile::burley(1.0, 1.0);
    for (double x : {1e-9, 1e-4, 0.01, 0.3, 1.0, 2.5, 7.0, 20.0, 60.0}) {
        const double closed = 1.0 - std::exp(-x) / 4.0 - 3.0 * std::exp(-x / 3.0) / 4.0;
        EXPECT_NEAR(burley_cdf(x), closed, 4e-16) << x;
        EXPECT_NEAR(burley_cdf(x), integral_2pi_r(p, 0.0, x), 1e-13) << x;
        // Near 0 the expm1 form keeps its relative precision: CDF ~ x/2.
        if (x < 1e-3) {
            EXPECT_NEAR(burley_cdf(x) / (0.5 * x - x * x / 6.0), 1.0, 1e-9) << x;
        }
        EXPECT_NEAR(burley_cdf(x) + burley_cdf_complement(x), 1.0, 4e-16) << x;
    }
    EXPECT_EQ(burley_cdf(HUGE_VAL), 1.0);
    EXPECT_EQ(burley_cdf(0.0), 0.0);
}

TEST(BurleyProfile, RadialDensityIsTwoPiRTimesTheProfile) {
    for (double x : {1e-6, 0.1, 1.0, 10.0})
        EXPECT_NEAR(burley_radial_density(x), kTwoPi * x * burley_profile(x), 1e-15) << x;
    EXPECT_DOUBLE_EQ(burley_radial_density(0.0), 0.5);
}

TEST(BurleyInverseCdf, RoundTripsAndMatchesBisectionWithinItsErrorEstimate) {
    double worst = 0.0;
    for (int i = 0; i <= 2000; ++i) {
        for (double u : {i / 2000.0, std::ldexp(1.0, -i % 60), 1.0 - std::ldexp(1.0, -(i % 45) - 1)}) {
            if (u >= 1.0) continue;
            double err = 0.0;
            const double x = burley_inverse_cdf(u, &err);
            const double ref = inverse_by_bisection(u);
            const double diff = std::abs(x - ref);
            EXPECT_LE(diff, err + 4e-16 * std::max(1.0, ref)) << "u " << u;
            EXPECT_LE(diff, 1e-12 * std::max(1.0, ref)) << "u " << u;
            EXPECT_NEAR(burley_cdf(x), u, 2e-16 + 2e-16 * u) << "u " << u;
            worst = std::max(worst, diff / std::max(1.0, ref));
        }
    }
    EXPECT_LT(worst, 1e-13);
    EXPECT_EQ(burley_inverse_cdf(0.0), 0.0);
    EXPECT_TRUE(std::isinf(burley_inverse_cdf(1.0)));
    EXPECT_THROW(burley_inverse_cdf(1.5), Error);
    EXPECT_THROW(burley_inverse_cdf(-0.1), Error);
}

TEST(BurleyScaling, ThePapersThreeFits) {
    // Searchlight: |A - 0.8|^3 on both sides of 0.8 (below 0.8 the cube
    // without the absolute value would fall to 0.14 at A = 0.2 instead of 3.16).
    EXPECT_NEAR(burley_scaling(0.2, BurleyScaling::searchlight), 1.65 + 7.0 * 0.216, 1e-14);
    EXPECT_NEAR(burley_scaling(0.9, BurleyScaling::searchlight), 0.95 + 7.0 * 0.001, 1e-14);
    EXPECT_NEAR(burley_scaling(0.2, BurleyScaling::diffuse_transmission), 1.7 + 3.5 * 0.36, 1e-14);
    EXPECT_NEAR(burley_scaling(0.33, BurleyScaling::dmfp), 3.5, 1e-14);
    EXPECT_EQ(burley_scaling_from_string("dmfp"), BurleyScaling::dmfp);
    EXPECT_THROW(burley_scaling_from_string("perpendicular"), Error);
}

TEST(BurleyTransmission, IsTheReflectanceBeyondTheThickness) {
    for (BurleyScaling sc : {BurleyScaling::searchlight, BurleyScaling::diffuse_transmission, BurleyScaling::dmfp})
        for (double A : {0.1, 0.6, 1.0})
            for (double t : {0.0, 0.05, 0.5, 2.0, 6.0}) {
                const double d = 1.0 / burley_scaling(A, sc);  // l = 1
                const RadialProfile p = RadialProfile::burley(A, d);
                const double beyond = A - integral_2pi_r(p, 0.0, t);
                EXPECT_NEAR(burley_transmission(t, A, sc), beyond, 1e-12) << A << " " << t;
            }
    EXPECT_DOUBLE_EQ(burley_transmission(0.0, 0.7, BurleyScaling::dmfp), 0.7);
}

TEST(DipoleProfile, RadialProfileTotalIsTheDipolesTotalReflectance) {
    const double A = dipole_boundary_term(diffuse_fresnel_reflectance(1.3, DiffuseFresnel::fit));
    for (double albedo : {0.2, 0.8, 0.99}) {
        const Dipole d = Dipole::from_albedo(albedo, A);
        const RadialProfile p = RadialProfile::dipole(d);
        EXPECT_NEAR(p.total(), dipole_total_reflectance(albedo, A), 1e-14);
        EXPECT_NEAR(integral_2pi_r(p, 0.0, 1e3), dipole_total_reflectance(albedo, A), 1e-9) << albedo;
    }
}

TEST(BurleyTables, MatchTheClosedFormsAndAreTheSameForAnyThreadCount) {
    for (const std::string id : {"burley_profile", "burley_inverse_cdf", "burley_scaling", "burley_transmission"}) {
        const TableDefinition& def = find_table(id);
        const Table a = test::generate_fresh(def, settings(id), 1), b = test::generate_fresh(def, settings(id), 2);
        EXPECT_EQ(a.values, b.values) << id;
        EXPECT_EQ(a.errors, b.errors) << id;
    }
    const Table inv = generate(find_table("burley_inverse_cdf"), settings("burley_inverse_cdf"));
    const Axis& u = inv.axes[0];
    for (int i = 0; i < u.count; ++i)
        EXPECT_NEAR(burley_cdf(inv.values[static_cast<std::size_t>(i)]), u.value(i), 1e-15) << i;
}
