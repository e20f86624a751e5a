// Separable subsurface kernels: Unreal's offsets and cells, the weights
// against closed forms, the profile's cell masses against a polar route
// through the closed-form reflectance within a radius, the separable error
// against an independent sum, a single Gaussian being separable, and the
// tables.
#include <gtest/gtest.h>

#include <cmath>

#include "brdflut/burley.h"
#include "brdflut/catalogue.h"
#include "brdflut/error.h"
#include "brdflut/generate.h"
#include "brdflut/math.h"
#include "brdflut/quadrature.h"
#include "brdflut/separable_sss.h"
#include "test_support.h"

using namespace brdflut;
using brdflut::test::burley_skin;

namespace {

// The mass of R over [0, a] x [0, b] in polar coordinates: the integral over
// theta of within(rho(theta)) / (2 pi), rho the distance to the rectangle's
// far edge, with within() the profile's closed-form reflectance in a disk.
double corner_mass(const RadialProfile& p, double a, double b) {
    if (a <= 0.0 || b <= 0.0) return 0.0;
    const double split = std::atan2(b, a);
    AdaptiveOptions opt{1e-14, 2000};
    const auto I1 = integrate_adaptive<1>(
        [&](double t) { return std::array<double, 1>{p.within(a / std::cos(t))}; }, 0.0, split, opt);
    const auto I2 = integrate_adaptive<1>(
        [&](double t) { return std::array<double, 1>{p.within(b / std::sin(t))}; }, split, kPi / 2, opt);
    return (I1.value[0] + I2.value[0]) / kTwoPi;
}

double polar_rectangle(const RadialProfile& p, double x0, double x1, double y0, double y1) {
    return corner_mass(p, x1, y1) - corner_mass(p, x0, y1) - corner_mass(p, x1, y0) + corner_mass(p, x0, y0);
}

// d'Eon's Gaussians: the mass over [x0, x1] x [y0, y1] is a product of erf
// differences per Gaussian.
double erf_rectangle(std::size_t ch, double x0, double x1, double y0, double y1) {
    double m = 0.0;
    for (const SkinGaussian& g : deon_skin_gaussians()) {
        const double s = std::sqrt(2.0 * g.variance);
        m += g.weight[ch] * 0.25 * (std::erf(x1 / s) - std::erf(x0 / s)) * (std::erf(y1 / s) - std::erf(y0 / s));
    }
    return m;
}

}  // namespace

TEST(SeparableSss, OffsetsAndCellsFollowUnrealsRule) {
    // Unreal: o = Range sign(t) |t|^2 on t = -1 + 2i/(2n - 2), areas
    // (|o_i - o_(i-1)| + |o_(i+1) - o_i|) / 2, the ends having one side.
    for (int n : {13, 9, 6}) {
        const double range = 2 * n - 1 > 20 ? 3.0 : 2.0;
        const std::vector<double> o = separable_tap_offsets(n, range, 2.0);
        std::vector<double> full;
        for (int i = 0; i < 2 * n - 1; ++i) {
            const double t = -1.0 + 2.0 * i / (2 * n - 2);
            full.push_back(range * (t < 0 ? -1.0 : 1.0) * t * t);
        }
        ASSERT_EQ(o.size(), static_cast<std::size_t>(n));
        const std::vector<double> u = separable_cell_edges(o);
        for (int i = 0; i < n; ++i) {
            const std::size_t k = static_cast<std::size_t>(n - 1 + i);  // tap i in the mirrored kernel
            EXPECT_NEAR(o[static_cast<std::size_t>(i)], full[k], 1e-15);
            const double left = std::abs(full[k] - full[k - 1]);
            const double right = k + 1 < full.size() ? std::abs(full[k + 1] - full[k]) : 0.0;
            const double width = i == 0 ? 2.0 * u[1] : u[static_cast<std::size_t>(i) + 1] - u[static_cast<std::size_t>(i)];
            EXPECT_NEAR(width, 0.5 * (left + right), 1e-15) << n << " tap " << i;
        }
    }
    EXPECT_THROW(separable_tap_offsets(1, 3.0, 2.0), Error);
    EXPECT_THROW(separable_tap_offsets(5, 0.0, 2.0), Error);
}

TEST(SeparableSss, WeightsMatchTheClosedFormsOfEachShape) {
    const std::vector<double> o = separable_tap_offsets(13, 3.0, 2.0);
    const std::vector<double> u = separable_cell_edges(o);
    const SkinProfile deon = deon_skin_profile(), burley = burley_skin();
    struct Case {
        const char* name;
        const SkinProfile& p;
        KernelShape shape;
        std::function<double(std::size_t, double, double)> raw;  // integral of the shape over [a, b]
    };
    const std::vector<Case> cases = {
        {"gaussians line", deon, KernelShape::line,
         [](std::size_t c, double a, double b) {
             double w = 0.0;
             for (const SkinGaussian& g : deon_skin_gaussians()) {
                 const double s = std::sqrt(2.0 * g.variance);
                 w += g.weight[c] / (kTwoPi * g.variance) * std::sqrt(kPi * g.variance / 2.0) *
                      (std::erf(b / s) - std::erf(a / s));
             }
             return w;
         }},
        {"gaussians radial", deon, KernelShape::radial,
         [](std::size_t c, double a, double b) {
             double w = 0.0;
             for (const SkinGaussian& g : deon_skin_gaussians())
                 w += g.weight[c] / kTwoPi *
                      (std::exp(-a * a / (2.0 * g.variance)) - std::exp(-b * b / (2.0 * g.variance)));
             return w;
         }},
        {"gaussians marginal", deon, KernelShape::marginal,
         [](std::size_t c, double a, double b) {
             double w = 0.0;
             for (const SkinGaussian& g : deon_skin_gaussians()) {
                 const double s = std::sqrt(2.0 * g.variance);
                 w += g.weight[c] * 0.5 * (std::erf(b / s) - std::erf(a / s));
             }
             return w;
         }},
        {"burley radial", burley, KernelShape::radial,
         [&](std::size_t c, double a, double b) {
             // x R(x) = A (e^(-x/d) + e^(-x/(3d))) / (8 pi d)
             const double d = burley[c].scale(), A = burley[c].total();
             return A / (8.0 * kPi) *
                    (std::exp(-a / d) - std::exp(-b / d) + 3.0 * (std::exp(-a / (3 * d)) - std::exp(-b / (3 * d))));
         }},
    };
    for (const Case& cs : cases) {
        const SeparableKernel k = separable_kernel(cs.p, cs.shape, KernelWeights::cell, o, 1e-12);
        for (std::size_t c = 0; c < 3; ++c) {
            double sum = 0.0;
            std::vector<double> raw(o.size());
            for (std::size_t i = 0; i < o.size(); ++i) {
                raw[i] = (i == 0 ? 2.0 : 1.0) * cs.raw(c, u[i], u[i + 1]);
                sum += (i == 0 ? 1.0 : 2.0) * raw[i];
            }
            for (std::size_t i = 0; i < o.size(); ++i) {
                const double diff = std::abs(k.weight[i][c] - raw[i] / sum);
                EXPECT_LE(diff, 1e-12) << cs.name << " tap " << i << " channel " << c;
                EXPECT_LE(diff, k.error[i][c] + 1e-15) << cs.name << ": the estimate covers the difference";
            }
        }
    }
}

TEST(SeparableSss, PointWeightsAreTheCellWidthTimesTheShape) {
    const std::vector<double> o = separable_tap_offsets(9, 2.0, 2.0);
    const std::vector<double> u = separable_cell_edges(o);
    const SkinProfile p = deon_skin_profile();
    const SeparableKernel k = separable_kernel(p, KernelShape::line, KernelWeights::point, o, 1e-12);
    for (std::size_t c = 0; c < 3; ++c) {
        double sum = 0.0;
        for (std::size_t i = 0; i < o.size(); ++i) sum += (i == 0 ? 2.0 * u[1] : 2.0 * (u[i + 1] - u[i])) * p[c].value(o[i]);
        for (std::size_t i = 0; i < o.size(); ++i)
            EXPECT_NEAR(k.weight[i][c], (i == 0 ? 2.0 * u[1] : u[i + 1] - u[i]) * p[c].value(o[i]) / sum, 1e-15);
    }
}

TEST(SeparableSss, BurleysInfiniteCentreIsRefusedWithTheReason) {
    const std::vector<double> o = separable_tap_offsets(6, 2.0, 2.0);
    for (auto [shape, weights] : {std::pair{KernelShape::line, KernelWeights::cell},
                                  std::pair{KernelShape::line, KernelWeights::point},
                                  std::pair{KernelShape::marginal, KernelWeights::point}}) {
        try {
            separable_kernel(burley_skin(), shape, weights, o, 1e-10);
            ADD_FAILURE() << to_string(shape) << " " << to_string(weights) << " was not refused";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("infinite"), std::string::npos) << e.what();
        }
    }
    EXPECT_NO_THROW(separable_kernel(burley_skin(), KernelShape::marginal, KernelWeights::cell, o, 1e-10));
}

TEST(SeparableSss, CellMassesMatchAPolarRouteThroughTheReflectanceWithinARadius) {
    const SkinProfile deon = deon_skin_profile(), burley = burley_skin();
    const double rects[][4] = {{0.0, 0.3, 0.0, 0.3}, {0.0, 0.05, 0.4, 1.1}, {0.2, 0.9, 0.7, 3.0}, {1.5, 3.0, 2.0, 3.0}};
    for (std::size_t c = 0; c < 3; ++c)
        for (const auto& r : rects) {
            for (const SkinProfile* p : {&deon, &burley}) {
                const Estimate<1> e = radial_profile_rectangle((*p)[c], r[0], r[1], r[2], r[3], 1e-13);
                const double want = polar_rectangle((*p)[c], r[0], r[1], r[2], r[3]);
                EXPECT_NEAR(e.value[0], want, 1e-12) << (p == &deon ? "gaussians" : "burley") << " channel " << c;
                EXPECT_LE(std::abs(e.value[0] - want), e.error[0] + 1e-13);
            }
            EXPECT_NEAR(radial_profile_rectangle(deon[c], r[0], r[1], r[2], r[3], 1e-13).value[0],
                        erf_rectangle(c, r[0], r[1], r[2], r[3]), 1e-13);
        }
}

TEST(SeparableSss, MisplacedEnergyMatchesAnIndependentSumOverTheCells) {
    // d'Eon's Gaussians, Unreal's point weights and the marginal cell
    // weights: the total-variation distance from erf cell masses.
    const std::vector<double> o = separable_tap_offsets(13, 3.0, 2.0);
    const std::vector<double> u = separable_cell_edges(o);
    const SkinProfile p = deon_skin_profile();
    std::vector<double> edges;  // the mirrored cells' edges
    for (std::size_t i = u.size() - 1; i >= 1; --i) edges.push_back(-u[i]);
    for (std::size_t i = 1; i < u.size(); ++i) edges.push_back(u[i]);
    for (auto [shape, weights] : {std::pair{KernelShape::line, KernelWeights::point},
                                  std::pair{KernelShape::marginal, KernelWeights::cell}}) {
        const SeparableKernel k = separable_kernel(p, shape, weights, o, 1e-12);
        const SeparableError e = separable_error(p, k, 1e-12);
        const std::size_t n = o.size(), taps = 2 * n - 1;
        auto w_of = [&](std::size_t a, std::size_t c) { return k.weight[a >= n - 1 ? a - (n - 1) : n - 1 - a][c]; };
        for (std::size_t c = 0; c < 3; ++c) {
            double square = 0.0, tv = 0.0;
            for (std::size_t a = 0; a < taps; ++a)
                for (std::size_t b = 0; b < taps; ++b)
                    square += erf_rectangle(c, edges[a], edges[a + 1], edges[b], edges[b + 1]);
            for (std::size_t a = 0; a < taps; ++a)
                for (std::size_t b = 0; b < taps; ++b)
                    tv += std::abs(w_of(a, c) * w_of(b, c) -
                                   erf_rectangle(c, edges[a], edges[a + 1], edges[b], edges[b + 1]) / square);
            EXPECT_NEAR(e.misplaced[c], 0.5 * tv, 1e-10) << to_string(shape) << " channel " << c;
            EXPECT_LE(std::abs(e.misplaced[c] - 0.5 * tv), e.error[c] + 1e-14);
            EXPECT_NEAR(e.outside[c], 1.0 - square / p[c].total(), 1e-12);
        }
    }
}

TEST(SeparableSss, OneGaussianIsSeparableExactlyAndASumIsNot) {
    const RadialProfile g = RadialProfile::gaussians({{1.0, 0.4}});
    const SkinProfile one = {g, g, g};
    const std::vector<double> o = separable_tap_offsets(9, 2.0, 2.0);
    for (KernelShape shape : {KernelShape::line, KernelShape::marginal}) {
        const SeparableError e = separable_error(one, separable_kernel(one, shape, KernelWeights::cell, o, 1e-12), 1e-12);
        for (std::size_t c = 0; c < 3; ++c) EXPECT_LE(e.misplaced[c], 1e-11) << to_string(shape);
    }
    // Point weights are a midpoint rule: not the cell masses, even for one
    // Gaussian; and a sum of Gaussians of different widths is not separable.
    const SeparableError point =
        separable_error(one, separable_kernel(one, KernelShape::line, KernelWeights::point, o, 1e-12), 1e-12);
    EXPECT_GT(point.misplaced[0], 1e-4);
    const SkinProfile deon = deon_skin_profile();
    const SeparableError sum =
        separable_error(deon, separable_kernel(deon, KernelShape::marginal, KernelWeights::cell, o, 1e-12), 1e-12);
    EXPECT_GT(sum.misplaced[0], 0.05);
}

TEST(SeparableSssTables, TapsOffsetsAndNormalizationAndSameForAnyThreadCount) {
    for (const std::string id : {"sss_kernel_gaussians", "sss_kernel_burley", "unreal_sss_kernel"}) {
        const TableDefinition& def = find_table(id);
        const TableSettings s = default_settings(def);
        const Table a = test::generate_fresh(def, s, 1), b = test::generate_fresh(def, s, 2);
        EXPECT_EQ(a.values, b.values) << id;
        const bool unreal = id == "unreal_sss_kernel";
        const std::vector<std::pair<int, double>> kernels =
            unreal ? std::vector<std::pair<int, double>>{{13, 3.0}, {9, 2.0}, {6, 2.0}}
                   : std::vector<std::pair<int, double>>{{13, 3.0}};
        std::size_t base = 0;
        for (auto [n, radius] : kernels) {
            std::array<double, 3> sum{};
            for (int i = 0; i < n; ++i) {
                const std::size_t at = (base + static_cast<std::size_t>(i)) * 4;
                EXPECT_NEAR(a.values[at + 3], radius * std::pow(i / (n - 1.0), 2.0), 1e-15) << id << " tap " << i;
                for (std::size_t c = 0; c < 3; ++c) sum[c] += (i == 0 ? 1.0 : 2.0) * a.values[at + c];
            }
            for (std::size_t c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], 1.0, 1e-14) << id;
            base += static_cast<std::size_t>(n);
        }
        ASSERT_TRUE(a.method.contains("separable_error")) << id;
    }
}

TEST(SeparableSssTables, MisdescribedTapAxesAndBadOptionsAreRefusedByName) {
    const TableDefinition& def = find_table("sss_kernel_gaussians");
    TableSettings s = default_settings(def);
    s.axes[0].max = 0.5;
    EXPECT_THROW(def.prepare(s), Error);
    s = default_settings(def);
    s.axes[0].count = 40;
    EXPECT_THROW(def.prepare(s), Error);
    s = default_settings(def);
    s.params["radius"] = "0";
    try {
        def.prepare(s);
        ADD_FAILURE() << "radius 0 was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("--radius 0"), std::string::npos) << e.what();
    }
    s = default_settings(def);
    s.params["spacing"] = "5";
    try {
        def.prepare(s);
        ADD_FAILURE() << "spacing 5 was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("allowed: 0.25 to 4"), std::string::npos) << e.what();
    }
    const TableDefinition& transmission = find_table("unreal_sss_transmission");
    TableSettings t = default_settings(transmission);
    t.params["extinction-scale"] = "-1";
    try {
        transmission.prepare(t);
        ADD_FAILURE() << "extinction scale -1 was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("allowed: 0 to 100"), std::string::npos) << e.what();
    }
    const TableDefinition& unreal = find_table("unreal_sss_kernel");
    TableSettings u = default_settings(unreal);
    u.params["falloff"] = "1,0.001,0.3";
    EXPECT_THROW(unreal.prepare(u), Error);
    u = default_settings(unreal);
    u.params["kernel-rule"] = "nope";
    EXPECT_THROW(validate_settings(unreal, u), Error);
    // A coarser grid over Unreal's row takes the texels it lands on.
    u = default_settings(unreal);
    const Table full = test::generate_fresh(unreal, u, 1);
    u.axes[0].count = 4;
    const Table four = test::generate_fresh(unreal, u, 1);
    for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t c = 0; c < 4; ++c) EXPECT_EQ(four.values[i * 4 + c], full.values[i * 9 * 4 + c]);
}

TEST(SeparableSssTables, UnrealsExactRuleMisplacesLessThanItsEngineRule) {
    const TableDefinition& def = find_table("unreal_sss_kernel");
    TableSettings s = default_settings(def);
    const Table engine = test::generate_fresh(def, s, 1);
    s.params["kernel-rule"] = "exact";
    const Table exact = test::generate_fresh(def, s, 1);
    for (std::size_t k = 0; k < 3; ++k)
        for (std::size_t c = 0; c < 3; ++c) {
            const double e = engine.method["separable_error"][k]["misplaced"][c];
            const double x = exact.method["separable_error"][k]["misplaced"][c];
            EXPECT_LT(x, e) << "kernel " << k << " channel " << c;
        }
}

TEST(SeparableSssTables, UnrealTransmissionIsBurleysTransmissionAtTheOffsetDistanceWithAlbedoOne) {
    const TableDefinition& def = find_table("unreal_sss_transmission");
    TableSettings s = default_settings(def);
    const std::array<double, 3> A = {0.8, 0.5, 0.3}, l = {1.0, 0.5, 0.25};
    for (const char* rule : {"engine", "exact"}) {
        s.params["transmission-rule"] = rule;
        const bool engine = std::string(rule) == "engine";
        const Table t = test::generate_fresh(def, s, 2);
        ASSERT_EQ(t.values.size(), 32u * 4u);
        for (std::size_t i = 0; i < 32; ++i) {
            const double r = 50.0 * static_cast<double>(i) / 32.0;  // Unreal's i/32 of 50 mm
            const bool last = i == 31;
            for (std::size_t c = 0; c < 3; ++c) {
                const double want = engine && last ? 0.0 : burley_transmission((r + (engine ? 0.6 : 0.0)) / l[c], A[c], BurleyScaling::dmfp) / A[c];
                EXPECT_NEAR(t.values[i * 4 + c], want, 1e-15 + 1e-14 * want) << rule << " texel " << i << " channel " << c;
            }
            EXPECT_NEAR(t.values[i * 4 + 3], engine && last ? 0.0 : std::exp(-r), 1e-15) << rule << " texel " << i;
        }
    }
}

TEST(SeparableSssTables, UnrealsFiveGaussiansAreTheRedChannelOfDeonsSkinFitBeyondTheNarrowest) {
    // Unreal's SeparableSSS_Profile quotes d'Eon and Luebke's red channel,
    // dropping the narrowest Gaussian: a second source for those numbers.
    const TableDefinition& def = find_table("unreal_sss_kernel");
    const PreparedTable p = def.prepare(default_settings(def));
    const auto& unreal = p.model.at("gaussians");
    const std::vector<SkinGaussian>& deon = deon_skin_gaussians();
    ASSERT_EQ(unreal.size() + 1, deon.size());
    for (std::size_t i = 0; i < unreal.size(); ++i) {
        EXPECT_EQ(unreal[i].at("variance_mm2").get<double>(), deon[i + 1].variance) << i;
        EXPECT_EQ(unreal[i].at("weight").get<double>(), deon[i + 1].weight[0]) << i;
    }
}
