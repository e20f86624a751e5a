// Pre-integrated skin: the ring and sphere integrals against a different
// quadrature, Monte Carlo, their limits and energy identities, the
// divergence of the ring for Burley's profile, and the generated tables.
#include <gtest/gtest.h>

#include <cmath>

#include "brdflut/burley.h"
#include "brdflut/catalogue.h"
#include "brdflut/dipole.h"
#include "brdflut/error.h"
#include "brdflut/generate.h"
#include "brdflut/math.h"
#include "brdflut/quadrature.h"
#include "brdflut/random.h"
#include "brdflut/skin.h"
#include "test_support.h"

using namespace brdflut;
using brdflut::test::burley_skin;

namespace {

SkinProfile dipole_skin() {
    const MeasuredMaterial& m = find_measured_material("skin1");
    const double A = dipole_boundary_term(diffuse_fresnel_reflectance(1.3, DiffuseFresnel::fit));
    return {RadialProfile::dipole(Dipole(m.sigma_s_prime[0], m.sigma_a[0], A)),
            RadialProfile::dipole(Dipole(m.sigma_s_prime[1], m.sigma_a[1], A)),
            RadialProfile::dipole(Dipole(m.sigma_s_prime[2], m.sigma_a[2], A))};
}

struct Case {
    const char* name;
    SkinProfile profile;
    SkinGeometry geometry;
};

std::vector<Case> cases() {
    return {{"burley sphere", burley_skin(), SkinGeometry::sphere},
            {"dipole ring", dipole_skin(), SkinGeometry::ring},
            {"dipole sphere", dipole_skin(), SkinGeometry::sphere},
            {"gaussians ring", deon_skin_profile(), SkinGeometry::ring},
            {"gaussians sphere", deon_skin_profile(), SkinGeometry::sphere}};
}

const double kNdotL[] = {-1.0, -0.55, -0.1, 0.0, 0.23, 0.5, 0.81, 1.0};
const double kCurvature[] = {0.002, 0.04, 0.3, 0.77, 2.0, 10.0};

}  // namespace

TEST(Skin, ClampedCosineAzimuthMeanMatchesQuadrature) {
    for (double a : {-0.9, -0.3, 0.0, 0.2, 0.7})
        for (double b : {0.0, 0.1, 0.5, 0.95}) {
            const auto I = integrate_adaptive<1>(
                [&](double phi) { return std::array<double, 1>{std::max(0.0, a + b * std::cos(phi))}; }, 0.0, kPi,
                AdaptiveOptions{1e-14, 2000});
            // The kink at cos(phi) = -a/b is handled by the adaptive split.
            EXPECT_NEAR(clamped_cosine_azimuth_mean(a, b), I.value[0] / kPi, 1e-11) << a << " " << b;
        }
}

TEST(Skin, AdaptiveQuadratureMatchesGradedGaussLegendreWithinItsEstimate) {
    double worst = 0.0;
    for (const Case& c : cases())
        for (double nl : kNdotL)
            for (double k : kCurvature) {
                const Estimate<3> e = preintegrated_skin(c.profile, c.geometry, nl, k, 1e-10);
                const std::array<double, 3> g = preintegrated_skin_gauss(c.profile, c.geometry, nl, k);
                for (std::size_t ch = 0; ch < 3; ++ch) {
                    const double diff = std::abs(e.value[ch] - g[ch]);
                    EXPECT_LE(diff, e.error[ch] + 1e-12) << c.name << " N.L " << nl << " curvature " << k;
                    EXPECT_LE(e.error[ch], 1e-9) << c.name << " N.L " << nl << " curvature " << k;
                    worst = std::max(worst, diff);
                }
            }
    EXPECT_LT(worst, 1e-9);
}

TEST(Skin, AgreesWithMonteCarloWithinFourStandardErrors) {
    int i = 0;
    for (const Case& c : cases())
        for (double nl : {-0.2, 0.7})
            for (double k : {0.1, 0.9}) {
                const Estimate<3> q = preintegrated_skin(c.profile, c.geometry, nl, k, 1e-10);
                const Estimate<3> mc = preintegrated_skin_mc(c.profile, c.geometry, nl, k, 40000, 7 + i++);
                for (std::size_t ch = 0; ch < 3; ++ch) {
                    EXPECT_GT(mc.error[ch], 0.0);
                    EXPECT_LE(std::abs(q.value[ch] - mc.value[ch]), 4.0 * mc.error[ch])
                        << c.name << " N.L " << nl << " curvature " << k << " channel " << ch;
                }
            }
}

TEST(Skin, FlatLimitIsTheClampedCosine) {
    for (const Case& c : cases())
        for (double nl : kNdotL) {
            const Estimate<3> zero = preintegrated_skin(c.profile, c.geometry, nl, 0.0, 1e-10);
            const Estimate<3> flat = preintegrated_skin(c.profile, c.geometry, nl, 1e-5, 1e-10);
            for (std::size_t ch = 0; ch < 3; ++ch) {
                EXPECT_EQ(zero.value[ch], std::max(0.0, nl));
                // Away from the terminator the blur changes cos+ by O((curvature * width)^2);
                // at it, by O(curvature * width).
                const double tol = std::abs(nl) > 0.05 ? 1e-8 : 1e-4;
                EXPECT_NEAR(flat.value[ch], std::max(0.0, nl), tol) << c.name << " N.L " << nl;
            }
        }
}

TEST(Skin, EnergyOfTheNormalizedTableIsThatOfTheClampedCosine) {
    // Sphere: the integral of D over the sphere is its projected area,
    // integral of D dN.L over [-1, 1] = 1/2. Ring: integral of D dtheta over
    // [0, pi] = 1. Times the profile's albedo, the energy is the albedo's.
    for (const Case& c : cases())
        for (double k : {0.01, 0.2, 1.5}) {
            const bool ring = c.geometry == SkinGeometry::ring;
            AdaptiveOptions opt;
            opt.abs_tol = 1e-11;
            opt.max_intervals = 400;
            const Estimate<3> I = integrate_adaptive<3>(
                [&](double t) { return preintegrated_skin(c.profile, c.geometry, ring ? std::cos(t) : t, k, 1e-12).value; },
                ring ? 0.0 : -1.0, ring ? kPi : 1.0, opt);
            for (std::size_t ch = 0; ch < 3; ++ch)
                EXPECT_NEAR(I.value[ch], ring ? 1.0 : 0.5, 1e-9) << c.name << " curvature " << k << " channel " << ch;
        }
}

TEST(Skin, SphereDenominatorIsTheProfilesReflectanceWithinTwoRadii) {
    for (const Case& c : cases())
        for (double k : {0.05, 1.0, 20.0}) {
            const double rho = 1.0 / k;
            for (const RadialProfile& p : c.profile) {
                const auto I = integrate_adaptive<1>(
                    [&](double a) {
                        return std::array<double, 1>{p.radial(2.0 * rho * std::sin(0.5 * a)) * rho * std::cos(0.5 * a)};
                    },
                    0.0, kPi, AdaptiveOptions{1e-14, 4000});
                EXPECT_NEAR(I.value[0], p.within(2.0 * rho), 1e-12 * p.total()) << c.name << " " << k;
            }
        }
}

TEST(Skin, BurleysRingIntegralDivergesAndIsRefused) {
    const SkinProfile p = burley_skin();
    EXPECT_THROW(preintegrated_skin(p, SkinGeometry::ring, 0.3, 0.5, 1e-10), Error);
    // A midpoint rule over x (MaterialX's, with 32 samples) gives a value
    // that depends on its sample count and tends to cos+(theta) as the
    // samples are refined: the log-divergent peak at x = 0 takes over.
    const double theta = std::acos(-0.2), rho = 2.0;
    auto midpoint = [&](int n) {
        double num = 0.0, den = 0.0;
        for (int i = 0; i < n; ++i) {
            const double x = -kPi + (i + 0.5) * kTwoPi / n;
            const double R = p[0].value(2.0 * rho * std::abs(std::sin(0.5 * x)));
            num += R * std::max(0.0, std::cos(theta + x));
            den += R;
        }
        return num / den;
    };
    const double d32 = midpoint(32), d1k = midpoint(1024), d1m = midpoint(1 << 20);
    EXPECT_GT(d32, d1k);
    EXPECT_GT(d1k, d1m);
    EXPECT_GT(d1m, 0.0);  // cos+(theta) = 0 here: the limit, reached like 1/ln(n)
}

TEST(SkinTables, HeldOutTexelsWithin1e7OfAnIndependentQuadratureAndSameForAnyThreadCount) {
    for (const std::string id : {"skin_preintegrated_burley", "skin_preintegrated_dipole", "skin_preintegrated_gaussians"}) {
        const TableDefinition& def = find_table(id);
        TableSettings s = default_settings(def);
        s.axes[0].count = 12;
        s.axes[1].count = 10;
        const Table a = test::generate_fresh(def, s, 1), b = test::generate_fresh(def, s, 2);
        EXPECT_EQ(a.values, b.values) << id;
        const bool burley = id == "skin_preintegrated_burley";
        const SkinProfile p = burley ? burley_skin() : id == "skin_preintegrated_dipole" ? dipole_skin() : deon_skin_profile();
        const SkinGeometry g = burley ? SkinGeometry::sphere : SkinGeometry::ring;
        for (int j : {1, 4, 9})
            for (int i : {0, 5, 7, 11}) {
                const double nl = s.axes[0].value(i), k = s.axes[1].value(j);
                const std::array<double, 3> want = preintegrated_skin_gauss(p, g, nl, k);
                for (std::size_t ch = 0; ch < 3; ++ch) {
                    const std::size_t at = (static_cast<std::size_t>(j) * 12 + static_cast<std::size_t>(i)) * 3 + ch;
                    EXPECT_NEAR(a.values[at], want[ch], 1e-7) << id << " texel " << i << "," << j;
                    EXPECT_NEAR(static_cast<float>(a.values[at]), want[ch], 1e-7) << id << " stored as float";
                }
            }
    }
}

TEST(SkinTables, MaterialxConstructionIsPennersRingByItsThirtyTwoPointMidpointRule) {
    const TableDefinition& def = find_table("skin_preintegrated_burley");
    TableSettings s = default_settings(def);
    s.axes[0].count = 9;
    s.axes[1].count = 7;
    s.params["skin-construction"] = "materialx";
    const Table t = test::generate_fresh(def, s, 2);
    const SkinProfile p = burley_skin();
    double farthest = 0.0;
    for (int j = 0; j < 7; ++j)
        for (int i = 0; i < 9; ++i) {
            const double nl = s.axes[0].value(i), k = s.axes[1].value(j);
            const double rho = 1.0 / std::max(k, 0.01);
            for (std::size_t ch = 0; ch < 3; ++ch) {
                // x_n = -pi + (n + 1/2) 2 pi/32; the ring's chord 2 rho |sin(x/2)|.
                double num = 0.0, den = 0.0;
                for (int n = 0; n < 32; ++n) {
                    const double x = -kPi + (n + 0.5) * kPi / 16.0;
                    const double r = 2.0 * rho * std::abs(std::sin(x / 2.0));
                    const double R = p[ch].value(r);  // the same shape up to a constant factor
                    num += R * std::max(0.0, std::cos(std::acos(nl) + x));
                    den += R;
                }
                const std::size_t at = (static_cast<std::size_t>(j) * 9 + static_cast<std::size_t>(i)) * 3 + ch;
                EXPECT_NEAR(t.values[at], num / den, 1e-13) << "texel " << i << "," << j;
                const double exact = preintegrated_skin(p, SkinGeometry::sphere, nl, k, 1e-12).value[ch];
                farthest = std::max(farthest, std::abs(t.values[at] - exact));
            }
        }
    // MaterialX's rule is not the sphere's integral.
    EXPECT_GT(farthest, 1e-3);
    s.method = Method::monte_carlo;
    EXPECT_THROW(def.prepare(s), Error);
}
