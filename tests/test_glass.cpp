// The GGX dielectric (glass) albedos against closed forms, limits,
// reciprocity, an independent Monte Carlo estimate and a second quadrature
// route over the outgoing direction.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "brdflut/catalogue.h"
#include "brdflut/fresnel.h"
#include "brdflut/generate.h"
#include "brdflut/glass_integrals.h"
#include "brdflut/quadrature.h"
#include "test_support.h"

using namespace brdflut;

namespace {

constexpr Visibility kHc = Visibility::height_correlated;
const Visibility kBoth[] = {Visibility::height_correlated, Visibility::separable};

// The second route: E_R and E_T as integrals over the outgoing direction wi
// (mu_i = |cos(theta_i)|, phi_i), with the half vector and the Jacobians of
// Walter 2007 built from (wo, wi):
//   reflection     h = (wo + wi) / |wo + wi|,  f_r mu_i = F D G2 / (4 mu_o)
//   transmission   h = +-(wo + eta wi) / |wo + eta wi| (h.z > 0), valid when
//                  wo.h > 0 > wi.h;  f_t mu_i = (1 - F) D G2 (wo.h) / mu_o
//                  * eta^2 |wi.h| / |wo + eta wi|^2   (energy: eta_o^2 in f_t)
// Nested adaptive Gauss-Kronrod, mu_i split at the specular cosine, phi
// (even) over [0, pi] clustered towards pi where the specular lobe lies.
Estimate<2> outgoing_route(double mu_o, double alpha, double eta, Visibility vis, double tol) {
    const Ggx g{alpha};
    const double sin_o = std::sqrt(1.0 - mu_o * mu_o);
    const Vec3 wo{sin_o, 0.0, mu_o};
    auto integrand = [&](double mu_i, double phi, bool transmit) -> double {
        const double s = std::sqrt(std::max(0.0, 1.0 - mu_i * mu_i));
        const Vec3 wi{s * std::cos(phi), s * std::sin(phi), transmit ? -mu_i : mu_i};
        if (!transmit) {
            Vec3 h{wo.x + wi.x, wo.y + wi.y, wo.z + wi.z};
            const double len = std::sqrt(dot(h, h));
            h = {h.x / len, h.y / len, h.z / len};
            const double c = dot(wo, h);
            if (!(c > 0.0)) return 0.0;
            return fresnel_dielectric(std::min(c, 1.0), eta) * g.D(h.z) * g.G2(mu_o, mu_i, vis) / (4.0 * mu_o);
        }
        Vec3 h{wo.x + eta * wi.x, wo.y + eta * wi.y, wo.z + eta * wi.z};
        const double len2 = dot(h, h);
        const double len = std::sqrt(len2);
        const double sign = h.z < 0.0 ? -1.0 : 1.0;
        h = {sign * h.x / len, sign * h.y / len, sign * h.z / len};
        const double c = dot(wo, h), ci = dot(wi, h);
        if (!(c > 0.0) || !(ci < 0.0)) return 0.0;
        const double F = fresnel_dielectric(std::min(c, 1.0), eta);
        return (1.0 - F) * g.D(h.z) * g.G2(mu_o, mu_i, vis) * c / mu_o * eta * eta * std::abs(ci) / len2;
    };
    Estimate<2> out;
    for (int side = 0; side < 2; ++side) {
        const bool transmit = side == 1;
        double peak = mu_o;  // the specular cosine
        if (transmit) {
            const double st2 = sin_o * sin_o / (eta * eta);
            peak = st2 < 1.0 ? std::sqrt(1.0 - st2) : 0.0;
        }
        AdaptiveOptions outer;
        outer.abs_tol = tol;
        outer.controlled = 1;
        outer.max_intervals = 2000;
        AdaptiveOptions inner = outer;
        inner.abs_tol = 0.01 * tol;
        auto over_phi = [&](double mu_i) {
            // phi = pi (1 - v^2): clustered at phi = pi.
            const Estimate<1> e = integrate_adaptive<1>(
                [&](double v) {
                    const double phi = kPi * (1.0 - v * v);
                    return std::array<double, 1>{2.0 * kPi * 2.0 * v * integrand(mu_i, phi, transmit)};
                },
                0.0, 1.0, inner);
            return std::array<double, 1>{e.value[0]};
        };
        double total = 0.0, err = 0.0;
        for (const auto& piece : {std::pair{0.0, peak}, std::pair{peak, 1.0}}) {
            const double a = piece.first, b = piece.second;  // plain names: lambdas capture them
            if (!(b > a)) continue;
            // smoothstep in each piece: dense at the peak and at the ends.
            const Estimate<1> e = integrate_adaptive<1>(
                [&](double u) {
                    const double m = a + (b - a) * u * u * (3.0 - 2.0 * u);
                    const std::array<double, 1> y = over_phi(m);
                    return std::array<double, 1>{y[0] * (b - a) * 6.0 * u * (1.0 - u)};
                },
                0.0, 1.0, outer);
            total += e.value[0];
            err += e.error[0];
        }
        out.value[static_cast<std::size_t>(side)] = total;
        out.error[static_cast<std::size_t>(side)] = err;
    }
    return out;
}

}  // namespace

TEST(GlassIntegrals, NoInterfaceReflectsNothingAndTransmitsTheDoublyMaskedStraightPath) {
    // eta = 1: F = 0 for every microfacet, the refraction of wo about any h
    // is -wo, so E_R = 0 exactly and E_T = G2(wo, -wo) integral of (wo.h)+ D
    // dw_h / mu_o = G2(wo, -wo) (1 + Lambda(wo)): 1 in the smooth limit.
    for (Visibility vis : kBoth)
        for (double alpha : {0.05, 0.3, 1.0})
            for (double mu : {0.05, 0.4, 0.9}) {
                const Ggx g{alpha};
                const Estimate<2> e = ggx_glass(mu, alpha, 1.0, vis, 1e-11);
                const double expect = g.G2(mu, mu, vis) * (1.0 + g.lambda(mu));
                EXPECT_EQ(e.value[0], 0.0) << "alpha " << alpha << " mu " << mu;
                EXPECT_NEAR(e.value[1], expect, 1e-10) << "alpha " << alpha << " mu " << mu;
            }
    // Smooth: E_T = 1, E_R = 0 exactly.
    const Estimate<2> smooth = ggx_glass(0.4, 0.0, 1.0, kHc);
    EXPECT_EQ(smooth.value[0], 0.0);
    EXPECT_EQ(smooth.value[1], 1.0);
    // And the rough value tends to 1 as alpha -> 0.
    EXPECT_NEAR(ggx_glass(0.4, 1e-4, 1.0, kHc, 1e-12).value[1], 1.0, 1e-6);
}

TEST(GlassIntegrals, SmoothLimitIsFresnelOnBothSidesIncludingTotalInternalReflection) {
    // alpha -> 0: E_R -> F(mu), E_T -> 1 - F(mu); inside (eta = 1/n) below
    // the critical cosine sqrt(1 - 1/n^2) F = 1. The departure shrinks
    // with alpha (it is O(alpha^2) away from the critical angle).
    for (double n : {1.33, 2.5})
        for (double eta : {n, 1.0 / n})
            for (double mu : {0.1, 0.5, 0.8, 1.0}) {
                const double F = fresnel_dielectric(mu, eta);
                double prev = HUGE_VAL;
                for (double alpha : {1e-2, 1e-3, 1e-4}) {
                    const Estimate<2> e = ggx_glass(mu, alpha, eta, kHc, 1e-10);
                    const double d = std::abs(e.value[0] - F) + std::abs(e.value[1] - (1.0 - F));
                    EXPECT_LT(d, alpha == 1e-4 ? 2e-5 : prev) << "eta " << eta << " mu " << mu << " alpha " << alpha;
                    prev = d;
                }
            }
}

TEST(GlassIntegrals, TransmissionAveragesAreReciprocalAcrossTheInterface) {
    // Walter's model obeys reciprocity: T_avg(n) outside = n^2 T_avg(1/n) inside.
    // ggx_glass_average takes the inside from the outside by this identity,
    // so the inside here is integrated by the other route, over mu of the
    // directional albedo seen from inside. The tolerances are set so that
    // both sides are well within 1e-9 relative.
    for (auto [n, alpha] : {std::pair{1.05, 0.05}, std::pair{2.5, 1.0}}) {
        const Estimate<2> out = ggx_glass_average(alpha, n, kHc, 4e-11);
        const Estimate<2> in = ggx_glass_average_over_mu(alpha, 1.0 / n, kHc, 4e-11 / (n * n));
        ASSERT_LT(out.error[1] + n * n * in.error[1], 0.5e-9 * out.value[1]);
        EXPECT_NEAR(out.value[1], n * n * in.value[1], 1e-9 * out.value[1]) << "n " << n << " alpha " << alpha;
    }
}

TEST(GlassIntegrals, AveragesAgreeWithTheIntegralOverMuOfTheDirectionalAlbedo) {
    // Two routes: (theta_h, wo.h, azimuth about h) with the Fresnel factor out
    // of the inner integral, against adaptive quadrature in mu of ggx_glass.
    // Each must be within its own error estimate of the other.
    struct Case {
        double alpha, eta;
        Visibility vis;
    };
    const Case cases[] = {
        {0.0009765625, 1.5, kHc},            // smallest alpha of the default grid
        {0.3, 1.0 / 1.5, kHc},               // inside: total internal reflection
        {0.05, 1.0 / 1.05, kHc},             // n near 1, inside
        {1.0, 2.5, Visibility::separable},   // rough, dense, separable masking
        {0.5, 1.0, kHc},                     // no interface
        {0.02, 1.0 / 2.5, Visibility::separable},
        {0.4, 1.5, Visibility::schlick_smith},  // the azimuth kernel's Schlick-Smith form
        {0.1, 1.0 / 1.5, Visibility::schlick_smith},
    };
    for (const Case& c : cases) {
        const Estimate<2> a = ggx_glass_average(c.alpha, c.eta, c.vis, 1e-9);
        const Estimate<2> b = ggx_glass_average_over_mu(c.alpha, c.eta, c.vis, 1e-8);
        for (std::size_t k = 0; k < 2; ++k) {
            EXPECT_LE(a.error[k], 1e-9) << "alpha " << c.alpha << " eta " << c.eta;
            EXPECT_LE(std::abs(a.value[k] - b.value[k]), a.error[k] + b.error[k])
                << "alpha " << c.alpha << " eta " << c.eta << " channel " << k;
        }
    }
}

TEST(GlassIntegrals, AverageErrorEstimatesAreNeverBelowTheActualError) {
    // At a loose tolerance, where the errors are large enough to see, against
    // a run 1e3 times tighter.
    for (double eta : {1.5, 1.0 / 1.5, 3.0, 1.0 / 1.02})
        for (double alpha : {0.002, 0.1, 0.6, 1.0}) {
            const Estimate<2> a = ggx_glass_average(alpha, eta, kHc, 1e-6);
            const Estimate<2> b = ggx_glass_average(alpha, eta, kHc, 1e-9);
            for (std::size_t k = 0; k < 2; ++k) {
                EXPECT_LE(std::abs(a.value[k] - b.value[k]), a.error[k] + b.error[k])
                    << "eta " << eta << " alpha " << alpha << " channel " << k;
                EXPECT_LE(a.error[k], 1e-6);
            }
        }
}

TEST(GlassIntegrals, AgreesWithMonteCarloWithinFourStandardErrors) {
    struct Case {
        double mu, alpha, eta;
        const char* what;
    };
    const double critical = std::sqrt(1.0 - 1.0 / (1.5 * 1.5));  // inside glass
    const Case cases[] = {
        {0.02, 0.3, 1.5, "grazing outside"},
        {0.02, 0.3, 1.0 / 1.5, "grazing inside"},
        {0.6, 0.0009765625, 1.5, "smallest alpha of the default grid"},
        {0.6, 0.0009765625, 1.0 / 1.5, "smallest alpha inside"},
        {0.5, 0.2, 1.01, "n near 1 outside"},
        {0.5, 0.2, 1.0 / 1.01, "n near 1 inside"},
        {critical * 0.98, 0.1, 1.0 / 1.5, "inside just below the critical cosine"},
        {critical * 1.02, 0.1, 1.0 / 1.5, "inside just above the critical cosine"},
        {0.7, 1.0, 3.0, "alpha 1, n 3"},
    };
    for (Visibility vis : kBoth)
        for (const Case& c : cases) {
            const Estimate<2> q = ggx_glass(c.mu, c.alpha, c.eta, vis, 1e-9);
            const Estimate<2> m = ggx_glass_mc(c.mu, c.alpha, c.eta, vis, 100000, 11);
            for (int k = 0; k < 2; ++k) {
                const double sigma = std::max(m.error[static_cast<std::size_t>(k)], 1e-12);
                EXPECT_LE(std::abs(q.value[static_cast<std::size_t>(k)] - m.value[static_cast<std::size_t>(k)]), 4.0 * sigma)
                    << c.what << " channel " << k << " vis " << to_string(vis);
            }
        }
    // The averages too.
    for (double eta : {1.5, 1.0 / 1.5}) {
        const Estimate<2> q = ggx_glass_average(0.3, eta, kHc, 1e-7);
        const Estimate<2> m = ggx_glass_average_mc(0.3, eta, kHc, 100000, 5);
        for (int k = 0; k < 2; ++k)
            EXPECT_LE(std::abs(q.value[static_cast<std::size_t>(k)] - m.value[static_cast<std::size_t>(k)]),
                      4.0 * m.error[static_cast<std::size_t>(k)])
                << "average eta " << eta << " channel " << k;
    }
}

TEST(GlassIntegrals, MonteCarloErrorCoversNormalsVisibleSamplingAlmostNeverDraws) {
    // Where the visible normals' weight hardly varies but a sliver of normals
    // they almost never draw carries a share of the albedo (the GGX tail at
    // alpha = 1e-3; at n = 1 + 2e-8 the normals with wo.m < 2e-4, where F
    // rises to 1), their standard error alone came out 30 times below the
    // actual error at 1e5 samples. Over several seeds the estimate stays
    // within 4 standard errors of the quadrature.
    const double z = 1e-4, n_near_1 = (1.0 + z * z) / (1.0 - z * z);  // Cycles' first z slice
    struct Case {
        double mu, alpha, eta;
    };
    const Case cases[] = {{0.96875, 0.0009765625, 2.768166089965398},
                          {0.53125, 0.0009765625, 1.0 / 2.768166089965398},
                          {1.0, 1.0, n_near_1},
                          {8.0 / 15.0, 1.0, n_near_1},
                          {8.0 / 15.0, 1.0, 1.0 / n_near_1}};
    for (const Case& c : cases) {
        const Estimate<2> q = ggx_glass(c.mu, c.alpha, c.eta, kHc, 1e-12);
        for (std::uint64_t seed = 1; seed <= 5; ++seed) {
            const Estimate<2> m = ggx_glass_mc(c.mu, c.alpha, c.eta, kHc, 100000, seed);
            for (std::size_t k = 0; k < 2; ++k)
                EXPECT_LE(std::abs(q.value[k] - m.value[k]), 4.0 * m.error[k] + q.error[k] + 1e-12)
                    << "mu " << c.mu << " alpha " << c.alpha << " eta " << c.eta << " seed " << seed << " channel " << k;
        }
    }
}

TEST(GlassIntegrals, AgreesWithAQuadratureOverTheOutgoingDirection) {
    struct Case {
        double mu, alpha, eta;
    };
    const Case cases[] = {
        {0.9, 0.5, 1.5},  {0.3, 0.3, 1.5},  {0.02, 0.6, 1.5},        // outside, grazing
        {0.9, 0.5, 1 / 1.5}, {0.5, 0.4, 1 / 1.5}, {0.3, 0.3, 1 / 1.5},  // inside, TIR at 0.5 and 0.3
        {0.05, 0.8, 1 / 2.5}, {0.7, 1.0, 2.5}, {0.2, 0.25, 1.2},
    };
    // Every visibility term: the route over wi takes G2 from Ggx::G2, the
    // half-vector route from its own kernels' form of it.
    for (Visibility vis : {kHc, Visibility::separable, Visibility::schlick_smith})
        for (const Case& c : cases) {
            const Estimate<2> q = ggx_glass(c.mu, c.alpha, c.eta, vis, 1e-10);
            const Estimate<2> o = outgoing_route(c.mu, c.alpha, c.eta, vis, 1e-9);
            for (int k = 0; k < 2; ++k)
                EXPECT_NEAR(q.value[static_cast<std::size_t>(k)], o.value[static_cast<std::size_t>(k)], 2e-8)
                    << "mu " << c.mu << " alpha " << c.alpha << " eta " << c.eta << " channel " << k << " visibility "
                    << static_cast<int>(vis);
        }
}

TEST(GlassIntegrals, ErrorEstimatesAreNeverBelowTheActualErrorOnADenseGrid) {
    // At a loose tolerance (where the errors are large enough to see)
    // against a run 1e4 times tighter, and at the tables' tolerance against
    // one 100 times tighter.
    int checked = 0;
    for (double tol : {1e-6, kGlassTableTolerance})
        for (double eta : {1.5, 1.0 / 1.5, 3.0, 1.0 / 3.0, 1.02})
            for (double alpha : {0.002, 0.05, 0.4, 1.0})
                for (double mu : {0.0, 0.03, 0.3, 0.74, 0.99}) {
                    const Estimate<2> a = ggx_glass(mu, alpha, eta, kHc, tol);
                    const Estimate<2> b = ggx_glass(mu, alpha, eta, kHc, tol == 1e-6 ? 1e-10 : 2e-10);
                    for (int k = 0; k < 2; ++k) {
                        const std::size_t c = static_cast<std::size_t>(k);
                        const double actual = std::abs(a.value[c] - b.value[c]);
                        EXPECT_LE(actual, a.error[c] + b.error[c])
                            << "tol " << tol << " eta " << eta << " alpha " << alpha << " mu " << mu << " channel " << k;
                        EXPECT_LE(a.error[c], tol) << "tol " << tol << " eta " << eta << " alpha " << alpha << " mu " << mu;
                        ++checked;
                    }
                }
    EXPECT_EQ(checked, 2 * 5 * 4 * 5 * 2);
}

TEST(GlassTables, ByteIdenticalForOneTwoAndAllThreadsAndWithinStoragePrecisionOfATighterRun) {
    for (const char* id : {"ggx_glass_albedo_inside", "ggx_glass_albedo_avg", "ggx_glass_albedo_avg_inside"}) {
        const TableDefinition& def = find_table(id);
        TableSettings s = default_settings(def);
        for (Axis& a : s.axes) a.count = 3;
        // Each run afresh: the averages share their outside transmission.
        const Table t1 = test::generate_fresh(def, s, 1), t2 = test::generate_fresh(def, s, 2),
                    ta = test::generate_fresh(def, s, 0);
        GenerateOptions two;
        two.threads = 2;
        ASSERT_EQ(t1.values.size(), t2.values.size());
        EXPECT_EQ(std::memcmp(t1.values.data(), t2.values.data(), t1.values.size() * sizeof(double)), 0) << id;
        EXPECT_EQ(std::memcmp(t1.values.data(), ta.values.data(), t1.values.size() * sizeof(double)), 0) << id;
        TableSettings tight = s;
        tight.quality = Quality::reference;
        const Table r = generate(def, tight, two);
        for (std::size_t i = 0; i < t1.values.size(); ++i)
            EXPECT_LE(std::abs(static_cast<double>(static_cast<float>(t1.values[i])) - r.values[i]), 1e-7)
                << id << " value " << i;
        EXPECT_LT(error_bound(t1, PixelType::float32), 1e-7) << id;
    }
}

TEST(GlassTables, SharedTransmissionGivesTheValuesOfAFreshRun) {
    // The averages from outside and from inside of one index n share the
    // outside transmission (the inside by reciprocity). Generated after the
    // table that computed it, each must hold what it holds generated alone,
    // and its E_T must be the outside E_T over n^2.
    auto small = [](const char* id) {
        TableSettings s = default_settings(find_table(id));
        for (Axis& a : s.axes) a.count = 3;
        return s;
    };
    const std::pair<const char*, const char*> pairs[] = {
        {"ggx_glass_albedo_avg", "ggx_glass_albedo_avg_inside"},
        {"ggx_glass_albedo_avg_inside", "ggx_glass_albedo_avg"},
        {"cycles_ggx_glass_e_avg", "cycles_ggx_glass_inv_e_avg"},
    };
    for (const auto& [first, second] : pairs) {
        SCOPED_TRACE(second);
        const Table fresh = test::generate_fresh(find_table(second), small(second), 0);
        clear_shared_results();
        const Table before = generate(find_table(first), small(first));
        const Table shared = generate(find_table(second), small(second));
        clear_shared_results();
        EXPECT_EQ(shared.values, fresh.values);
        if (std::string(first) == "ggx_glass_albedo_avg") {
            // ior is the second axis: texel (i, j) at n_j, channels E_R, E_T, E_R + E_T.
            const Axis& n_axis = shared.axes[1];
            for (int j = 0; j < n_axis.count; ++j)
                for (int i = 0; i < shared.axes[0].count; ++i) {
                    const std::size_t texel = static_cast<std::size_t>(j * shared.axes[0].count + i);
                    const double n = n_axis.value(j);
                    EXPECT_EQ(shared.at(texel, 1), before.at(texel, 1) * ((1.0 / n) * (1.0 / n)))
                        << "texel " << i << ", " << j;
                }
        }
    }
}

TEST(GlassIntegrals, SharedReflectionIntegralsGiveTheValuesOfAFreshRun) {
    // The reflection averages from outside share their x integrals at each
    // c between indices of one alpha, and those from inside the total
    // reflection average (F = 1) of one alpha: after other indices (on both
    // sides), a value must be what it is computed alone, and still agree
    // with the other route.
    for (double alpha : {0.01, 0.4})
        for (bool inside : {false, true}) {
            const double eta = inside ? 1.0 / 1.5 : 1.5;
            clear_shared_results();
            const Estimate<1> fresh = ggx_glass_average_reflection(alpha, eta, kHc, 2e-8);
            clear_shared_results();
            for (double n : {1.1, 2.0, 3.0}) {
                ggx_glass_average_reflection(alpha, n, kHc, 2e-8);
                ggx_glass_average_reflection(alpha, 1.0 / n, kHc, 2e-8);
            }
            const Estimate<1> shared = ggx_glass_average_reflection(alpha, eta, kHc, 2e-8);
            clear_shared_results();
            EXPECT_EQ(shared.value[0], fresh.value[0]) << "alpha " << alpha << " eta " << eta;
            EXPECT_EQ(shared.error[0], fresh.error[0]) << "alpha " << alpha << " eta " << eta;
            const Estimate<2> other = ggx_glass_average_over_mu(alpha, eta, kHc, 1e-8);
            EXPECT_LE(std::abs(fresh.value[0] - other.value[0]), fresh.error[0] + other.error[0])
                << "alpha " << alpha << " eta " << eta;
        }
}

TEST(GlassIntegrals, EverySimdWidthGivesTheSameBits) {
    // The ring and azimuth integrands run 4 (AVX2), 2 (SSE2) or 1 node at a
    // time; each width must give exactly the values, errors and work of one
    // at a time, on both sides, under total internal reflection, at grazing
    // views, and for every visibility term.
    test::expect_same_bits_at_every_ggx_simd_width([] {
        clear_shared_results();  // the averages' shared inner integrals are computed afresh
        std::vector<Estimate<2>> out;
        for (Visibility vis : {Visibility::height_correlated, Visibility::separable, Visibility::schlick_smith})
            for (double alpha : {2e-3, 0.1, 0.6})
                for (double eta : {1.0 / 2.4, 1.0 / 1.01, 1.0, 1.0 + 1e-6, 1.5, 40.0}) {
                    for (double mu : {1e-3, 0.3, 0.74, 1.0}) out.push_back(ggx_glass(mu, alpha, eta, vis, 2e-8));
                    out.push_back(ggx_glass_average(alpha, eta, vis, 2e-8));
                }
        return out;
    });
    clear_shared_results();
}
