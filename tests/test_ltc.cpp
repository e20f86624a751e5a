// LTC: the distribution, the polygon integral, the sphere form factor, the
// fit (local optimum, smoothness, norms), Heitz's published table, and
// thread independence of the tables.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "brdflut/catalogue.h"
#include "brdflut/charlie_ek.h"
#include "brdflut/generate.h"
#include "brdflut/ggx_integrals.h"
#include "brdflut/ltc.h"
#include "brdflut/ltc_compare.h"
#include "brdflut/ltc_fit.h"
#include "brdflut/ltc_report.h"
#include "brdflut/quadrature.h"
#include "brdflut/verify.h"
#include "brdflut/zeltner_sheen.h"
#include "brdflut/exr.h"
#include "brdflut/formats.h"
#include "brdflut/lut.h"
#include "integrate/ltc_quadrature.h"
#include "integrate/ltc_simd.h"
#include "test_support.h"

namespace brdflut {
namespace {

Vec3 normalized(const Vec3& v) {
    const double l = std::sqrt(dot(v, v));
    return {v.x / l, v.y / l, v.z / l};
}

// Integral of g(w) over the spherical triangle (a, b, c) by Gauss-Legendre in
// the planar triangle's collapsed coordinates (dw = |n . x| / |x|^3 dA): an
// estimator independent of the edge formula.
template <class G>
double triangle_quadrature(const Vec3& a, const Vec3& b, const Vec3& c, G&& g, int n = 160) {
    const GaussLegendre& gl = gauss_legendre(n);
    const Vec3 ab{b.x - a.x, b.y - a.y, b.z - a.z}, bc{c.x - b.x, c.y - b.y, c.z - b.z};
    const Vec3 nrm{ab.y * bc.z - ab.z * bc.y, ab.z * bc.x - ab.x * bc.z, ab.x * bc.y - ab.y * bc.x};
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double s = 0.5 * (gl.x[i] + 1.0);
        for (int j = 0; j < n; ++j) {
            const double t = 0.5 * (gl.x[j] + 1.0);
            const Vec3 x{a.x + s * ab.x + s * t * bc.x, a.y + s * ab.y + s * t * bc.y, a.z + s * ab.z + s * t * bc.z};
            const double l2 = dot(x, x), l = std::sqrt(l2);
            const double dw = std::abs(dot(nrm, x)) * s / (l2 * l);
            sum += 0.25 * gl.w[i] * gl.w[j] * dw * g(Vec3{x.x / l, x.y / l, x.z / l});
        }
    }
    return sum;
}

// A planar quad (corners of a square of half-size tan(sigma) on the plane
// tangent to c) integrated as two triangles.
template <class G>
double quad_quadrature(const std::array<Vec3, 4>& v, G&& g) {
    return triangle_quadrature(v[0], v[1], v[2], g) + triangle_quadrature(v[0], v[2], v[3], g);
}

std::array<Vec3, 4> square_light(const Vec3& c_in, double sigma) {
    const Vec3 c = normalized(c_in);
    const Vec3 up = std::abs(c.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
    const Vec3 e2 = normalized({up.y * c.z - up.z * c.y, up.z * c.x - up.x * c.z, up.x * c.y - up.y * c.x});
    const Vec3 e1{e2.y * c.z - e2.z * c.y, e2.z * c.x - e2.x * c.z, e2.x * c.y - e2.y * c.x};
    const double t = std::tan(sigma);
    std::array<Vec3, 4> v;
    const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    for (int i = 0; i < 4; ++i)
        v[static_cast<std::size_t>(i)] = {c.x + t * (sx[i] * e1.x + sy[i] * e2.x), c.y + t * (sx[i] * e1.y + sy[i] * e2.y),
                                          c.z + t * (sx[i] * e1.z + sy[i] * e2.z)};
    return v;
}

Vec3 from_angles(double theta, double phi) {
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

TEST(LtcMath, DensityIntegratesToOneOverTheSphere) {
    const LtcInverse minv{0.6, 0.3, -0.2, 0.5};
    const GaussLegendre& gl = gauss_legendre(400);
    double sum = 0.0;
    for (int i = 0; i < 400; ++i) {
        const double z = gl.x[i];
        const double s = std::sqrt(1.0 - z * z);
        for (int k = 0; k < 400; ++k) {
            const double phi = (k + 0.5) * kTwoPi / 400;
            sum += gl.w[i] * (kTwoPi / 400) * ltc_density(minv.matrix(), {s * std::cos(phi), s * std::sin(phi), z});
        }
    }
    EXPECT_NEAR(sum, 1.0, 1e-6);
}

TEST(LtcMath, PolygonClampedCosineMatchesQuadratureIncludingHorizonCrossings) {
    const auto cosine = [](const Vec3& w) { return std::max(w.z, 0.0) / kPi; };
    struct Case { double theta, phi, sigma; };
    const Case cases[] = {{0.0, 0.0, 0.3}, {0.7, 1.0, 0.2}, {1.3, -2.0, 0.4},
                          {1.5, 0.5, 0.3},   // crosses the horizon
                          {1.7, 3.0, 0.35},  // mostly below, crosses it
                          {1.2, 0.0, 1.0}};  // large, crosses it
    for (const Case& c : cases) {
        const std::array<Vec3, 4> v = square_light(from_angles(c.theta, c.phi), c.sigma);
        // The quadrature of the clipped integrand is exact only up to its
        // kink at the horizon: clip first, then fan-triangulate.
        const std::vector<Vec3> clipped = clip_to_horizon(v.data(), 4);
        double ref = 0.0;
        for (std::size_t i = 1; i + 1 < clipped.size(); ++i)
            ref += triangle_quadrature(clipped[0], clipped[i], clipped[i + 1], cosine);
        EXPECT_NEAR(polygon_clamped_cosine(v.data(), 4), ref, 1e-10) << c.theta << " " << c.phi;
        // The same polygon in reverse winding.
        const std::array<Vec3, 4> r{v[3], v[2], v[1], v[0]};
        EXPECT_NEAR(polygon_clamped_cosine(r.data(), 4), ref, 1e-10);
    }
}

TEST(LtcMath, LtcPolygonIntegralMatchesQuadratureOfTheDensity) {
    const Mat3 minv = LtcInverse{0.8, 0.25, -0.3, 0.6}.matrix();
    for (double theta : {0.2, 0.9, 1.45}) {
        const std::array<Vec3, 4> v = square_light(from_angles(theta, 2.5), 0.25);
        const double ref = quad_quadrature(v, [&](const Vec3& w) { return ltc_density(minv, w); });
        EXPECT_NEAR(ltc_polygon_integral(minv, v.data(), 4), ref, 1e-8) << theta;
    }
}

TEST(LtcMath, SphereFormFactorMatchesQuadratureOfTheCap) {
    for (double z : {1.0, 0.6, 0.2, 0.0, -0.15, -0.5}) {
        for (double len : {0.02, 0.3, 0.7}) {
            const double sigma = std::asin(std::sqrt(len));
            const double w = std::acos(z);
            const Vec3 c{std::sin(w), 0.0, std::cos(w)}, t1{std::cos(w), 0.0, -std::sin(w)};
            // Polar coordinates about the cap's centre; the integrand's kink
            // at the horizon limits Gauss-Legendre, so use many nodes.
            const GaussLegendre& gl = gauss_legendre(600);
            double sum = 0.0;
            for (int i = 0; i < 600; ++i) {
                const double b = 0.5 * sigma * (gl.x[i] + 1.0);
                for (int k = 0; k < 600; ++k) {
                    const double phi = (k + 0.5) * kTwoPi / 600;
                    const double sb = std::sin(b), cb = std::cos(b);
                    const double dz = cb * c.z + sb * std::cos(phi) * t1.z;
                    sum += 0.5 * sigma * gl.w[i] * (kTwoPi / 600) * sb * std::max(dz, 0.0) / kPi;
                }
            }
            EXPECT_NEAR(sphere_horizon_form_factor(z, len), sum / len, 2e-6) << z << " " << len;
        }
    }
    EXPECT_DOUBLE_EQ(sphere_horizon_form_factor(0.4, 0.0), 0.4);
    EXPECT_DOUBLE_EQ(sphere_horizon_form_factor(-0.4, 0.0), 0.0);
}

// Texels of the 64x64 Heitz grid spread over it, grazing rows included.
struct Texel { int t, a; };
std::vector<Texel> subset() {
    return {{0, 10}, {0, 40}, {12, 3}, {20, 20}, {30, 50}, {40, 8}, {45, 30}, {52, 63},
            {58, 15}, {61, 45}, {63, 2}, {63, 32}, {63, 60}};
}
double mu_of(int t) { const double u = t / 63.0; return 1.0 - u * u; }
double alpha_of(int a) { const double r = a / 63.0; return r * r; }

TEST(LtcFit, EveryFittedTexelIsALocalMinimumOfTheObjective) {
    for (const Texel& x : subset()) {
        const LtcFit fit = fit_ggx_ltc(mu_of(x.t), alpha_of(x.a), Visibility::height_correlated);
        const double j0 = ltc_objective(mu_of(x.t), alpha_of(x.a), Visibility::height_correlated, fit.params);
        EXPECT_DOUBLE_EQ(j0, fit.objective);
        // No parameter moved by its probe step lowers the objective.
        EXPECT_LE(ltc_local_minimum_drop(LtcLobe(mu_of(x.t), alpha_of(x.a), Visibility::height_correlated), fit), 1e-9)
            << "t=" << x.t << " a=" << x.a;
    }
}

TEST(LtcFit, EveryObjectivePathGivesTheSameBits) {
    // The objective sums its grid four nodes at a time (AVX2), two (SSE2)
    // or one at a time; each must give the same bits, at the fit and at parameters
    // around it, so that the fits are the same whichever path runs. Lobes:
    // GGX smooth and grazing, smooth, rough at normal view, the sheen and
    // EON lobes; on the draft grid and on one padded to whole lanes.
    const int widest = detail::ltc_objective_simd_width();
    const LtcLobe lobes[] = {LtcLobe(0.02, 1e-4, Visibility::height_correlated),
                             LtcLobe(0.6, 0.2, Visibility::separable),
                             LtcLobe(1.0, 1.0, Visibility::height_correlated),
                             LtcLobe(LtcLobeKind::charlie_sheen, 0.3, 0.2),
                             LtcLobe(LtcLobeKind::eon, 0.1, 0.7)};
    LtcFitOptions opt = ltc_fit_options(0);
    LtcFitOptions odd = opt;  // a grid that is not whole groups of four nodes: padded
    odd.azimuth_nodes = 7;
    auto run = [&](int width) {
        detail::set_ltc_objective_simd_width(width);
        std::vector<LtcFit> fits;
        std::vector<double> values;
        for (const LtcLobe& l : lobes) {
            fits.push_back(fit_ltc(l, opt));
            fits.push_back(fit_ltc(l, odd));
            for (int k = 0; k < 40; ++k) {
                std::array<double, 4> p = fits.back().params;
                p[k % 4] += 0.05 * (k / 4 - 4.5);  // below and beyond the horizon too
                values.push_back(ltc_objective(l, p, opt));
            }
        }
        return std::make_pair(fits, values);
    };
    const auto one = run(1);
    for (int width : {2, 4}) {
        if (detail::set_ltc_objective_simd_width(width) != width) continue;
        const auto wide = run(width);
        for (std::size_t n = 0; n < one.first.size(); ++n) {
            EXPECT_EQ(wide.first[n].params, one.first[n].params) << "width " << width << ", lobe " << n;
            EXPECT_EQ(wide.first[n].evaluations, one.first[n].evaluations) << "width " << width << ", lobe " << n;
        }
        for (std::size_t n = 0; n < one.second.size(); ++n)
            EXPECT_EQ(wide.second[n], one.second[n]) << "width " << width << ", point " << n;
    }
    EXPECT_EQ(detail::set_ltc_objective_simd_width(widest), widest);
}

TEST(LtcFit, NormAndFresnelMomentMatchGgxAlbedoAndDfg) {
    const TableDefinition& albedo = find_table("ggx_albedo");
    const TableDefinition& dfg = find_table("ggx_dfg");
    const PreparedTable pa = albedo.prepare(default_settings(albedo));
    const PreparedTable pd = dfg.prepare(default_settings(dfg));
    for (const Texel& x : subset()) {
        // The fit evaluates the lobe at alpha >= 1e-5 and mu >= cos(1.57).
        const double mu = std::max(mu_of(x.t), kLtcMinMu), alpha = std::max(alpha_of(x.a), kLtcMinAlpha);
        const LtcFit fit = fit_ggx_ltc(mu_of(x.t), alpha_of(x.a), Visibility::height_correlated);
        const double c[2] = {mu, alpha};
        EXPECT_NEAR(fit.n0, pa.evaluator->evaluate(c, 0).value[0], 1e-7);
        EXPECT_NEAR(fit.n1, pd.evaluator->evaluate(c, 0).value[1], 1e-7);
    }
}

TEST(LtcTables, Ltc2HoldsTheFitsNormsWithoutFitting) {
    // ltc_2 computes n0 and n1 by the exact integrals alone: the same values
    // as the fit that ltc_1 stores carries.
    const TableDefinition& def = find_table("ltc_2");
    const PreparedTable p = def.prepare(default_settings(def));
    for (const Texel& x : subset()) {
        const double r = std::sqrt(alpha_of(x.a));
        const double c[2] = {r, mu_of(x.t)};
        const TexelValue v = p.evaluator->evaluate(c, 0);
        const LtcFit fit = fit_ggx_ltc(mu_of(x.t), alpha_from_perceptual(r), Visibility::height_correlated);
        EXPECT_EQ(v.value[0], fit.n0) << x.t << " " << x.a;
        EXPECT_EQ(v.value[1], fit.n1) << x.t << " " << x.a;
        EXPECT_EQ(v.error[0], fit.n0_error);
    }
    EXPECT_FALSE(generate(def, [&] {
                     TableSettings s = default_settings(def);
                     s.axes[0].count = 2;
                     s.axes[1].count = 2;
                     return s;
                 }()).method.contains("fit_error"));
}

// The three.js copy of Heitz's ltc_1 / ltc_2 (tests/fixtures/ltc).
std::vector<double> read_fixture(const std::string& name) {
    std::ifstream in(std::string(BRDFLUT_SOURCE_DIR) + "/tests/fixtures/ltc/" + name);
    std::vector<double> v;
    double x;
    while (in >> x) v.push_back(x);
    return v;
}

TEST(LtcHeitz, SphereChannelAndAxesMatchThePublishedLtc2) {
    const std::vector<double> t2 = read_fixture("three_ltc_2.txt");
    ASSERT_EQ(t2.size(), 64u * 64u * 4u);
    const TableDefinition& def = find_table("ltc_2");
    const TableSettings s = default_settings(def);
    double worst = 0.0;
    for (int t = 0; t < 64; t += 3)
        for (int a = 0; a < 64; a += 3) {
            const double r = s.axes[0].value(a), mu = s.axes[1].value(t);
            EXPECT_NEAR(r, a / 63.0, 1e-15);
            EXPECT_NEAR(mu, mu_of(t), 1e-15);
            const double sphere = sphere_horizon_form_factor(2.0 * r - 1.0, std::sqrt(1.0 - mu));
            worst = std::max(worst, std::abs(sphere - t2[static_cast<std::size_t>(4 * (a + 64 * t) + 3)]));
        }
    EXPECT_LT(worst, 1e-4);  // Heitz computes it in float
}

// On an 8x8 spread of the grid (grazing row and r = 1 included): the refit's
// largest light error is lower at three quarters of the texels, its worst
// texel is better than Heitz's worst, and no texel is more than 3 times
// Heitz's error (floor 1e-3). Not twice: at r = 1 in the grazing row
// Heitz's stored n0 is 6 % below the albedo, which offsets his LTC's excess
// light (with the exact n0 his matrix does worse than the refit there).
TEST(LtcHeitz, RefitGivesLessIntegratedLightErrorThanThePublishedTable) {
    const std::vector<double> t1 = read_fixture("three_ltc_1.txt");
    const std::vector<double> t2 = read_fixture("three_ltc_2.txt");
    ASSERT_EQ(t1.size(), 64u * 64u * 4u);
    int wins = 0, n = 0;
    double worst_ratio = 0.0, mine_worst = 0.0, heitz_worst = 0.0, worst_excess = 0.0;
    for (int t = 0; t < 64; t += 9)
        for (int a = 0; a < 64; a += 9) {
            const double mu = mu_of(t), alpha = alpha_of(a);
            const std::size_t k = static_cast<std::size_t>(4 * (a + 64 * t));
            const LtcInverse heitz{t1[k], t1[k + 2], t1[k + 1], t1[k + 3]};
            const LtcFit fit = fit_ggx_ltc(mu, alpha, Visibility::height_correlated);
            const LtcFitOptions draft = ltc_fit_options(0);
            const LtcTexelReport mine = ltc_texel_report(mu, alpha, Visibility::height_correlated, fit.minv.matrix(), fit.n0, draft);
            const LtcTexelReport pub = ltc_texel_report(mu, alpha, Visibility::height_correlated, heitz.matrix(), t2[k], draft);
            ++n;
            if (mine.light_max <= pub.light_max) ++wins;
            worst_ratio = std::max(worst_ratio, mine.light_max / std::max(pub.light_max, 1e-3));
            worst_excess = std::max(worst_excess, mine.light_max - pub.light_max);
            mine_worst = std::max(mine_worst, mine.light_max);
            heitz_worst = std::max(heitz_worst, pub.light_max);
        }
    EXPECT_GE(wins, n * 3 / 4) << wins << " of " << n;
    EXPECT_LT(worst_ratio, 3.0);
    EXPECT_LT(mine_worst, heitz_worst);
    // Nowhere above Heitz's error by more than 0.05 of n0 (the largest excess
    // here is about 0.02, at roughness indices 9 and 54 of the last row;
    // without the light term in the fit it was 0.10 and 0.06 there).
    EXPECT_LT(worst_excess, 0.05);
}

TEST(LtcTables, ByteIdenticalForOneTwoAndAllThreads) {
    for (const char* id : {"ltc_1", "ltc_2", "ltc_ggx_error", "hdrp_ltc_ggx", "ltc_sheen_charlie",
                           "ltc_sheen_charlie_norm", "ltc_sheen_charlie_error", "ltc_eon", "ltc_eon_norm",
                           "ltc_eon_error"}) {
        const TableDefinition& def = find_table(id);
        TableSettings s = default_settings(def);
        s.axes[0].count = 6;
        s.axes[1].count = 5;
        const Table a = test::generate_fresh(def, s, 1), b = test::generate_fresh(def, s, 2),
                    c = test::generate_fresh(def, s, 0);
        EXPECT_EQ(a.values, b.values) << id;
        EXPECT_EQ(a.values, c.values) << id;
        EXPECT_EQ(a.method.dump(), b.method.dump()) << id;
        EXPECT_EQ(a.method.dump(), c.method.dump()) << id;
    }
}

TEST(LtcTables, SharedFitsGiveTheValuesOfFreshOnes) {
    // A matrix table and its error table share each texel's fit and report
    // in one run, keyed by the lobe and the fit's options. Generated after
    // ltc_1 at default settings, each of these must hold what it holds when
    // generated alone: the error table, the other visibility, HDRP's layout
    // (its alpha floor at roughness 0 and 1/3 here), another quality.
    auto small = [](const char* id) {
        TableSettings s = default_settings(find_table(id));
        s.axes[0].count = 4;
        s.axes[1].count = 4;
        return s;
    };
    TableSettings separable = small("ltc_1");
    separable.params["visibility"] = "separable";
    TableSettings draft = small("ltc_ggx_error");
    draft.quality = Quality::draft;
    const std::vector<std::pair<const char*, TableSettings>> after = {
        {"ltc_ggx_error", small("ltc_ggx_error")}, {"ltc_1", separable}, {"hdrp_ltc_ggx", small("hdrp_ltc_ggx")},
        {"ltc_ggx_error", draft}};
    for (const auto& [id, s] : after) {
        SCOPED_TRACE(id);
        clear_shared_results();
        const Table fresh = generate(find_table(id), s);
        clear_shared_results();
        generate(find_table("ltc_1"), small("ltc_1"));
        const Table shared = generate(find_table(id), s);
        EXPECT_EQ(shared.values, fresh.values);
        EXPECT_EQ(shared.method.dump(), fresh.method.dump());
    }
    clear_shared_results();
}

TEST(LtcTables, MatrixTableMetadataHoldsTheMaximaOfTheErrorReport) {
    // ltc_1's metadata maxima against the per-texel channels of
    // ltc_ggx_error on the same grid, both with the exact light to 1e-5 of
    // n0; the fits and reports computed anew for each table (the shared
    // results cleared between them), the report stored in float.
    const TableDefinition& m = find_table("ltc_1");
    const TableDefinition& r = find_table("ltc_ggx_error");
    TableSettings s = default_settings(m);
    s.axes[0].count = 4;
    s.axes[1].count = 5;
    const Table tm = generate(m, s);
    clear_shared_results();
    const Table tr = generate(r, s);
    const nlohmann::json& fe = tm.method.at("fit_error");
    double l3 = 0.0, below = 0.0, light = 0.0;
    for (std::size_t k = 0; k < tr.texel_count(); ++k) {
        l3 = std::max(l3, tr.at(k, 0));
        below = std::max(below, tr.at(k, 1));
        light = std::max(light, tr.at(k, 2));
    }
    EXPECT_GT(light, 1e-3);  // the grid has grazing, rough texels: not a trivial maximum
    EXPECT_EQ(static_cast<float>(fe.at("light_error_max").get<double>()), static_cast<float>(light));
    EXPECT_EQ(static_cast<float>(fe.at("relative_l3_max").get<double>()), static_cast<float>(l3));
    EXPECT_EQ(static_cast<float>(fe.at("below_horizon_max").get<double>()), static_cast<float>(below));
    EXPECT_DOUBLE_EQ(fe.at("light_tolerance").get<double>(), 1e-5);
}

TEST(LtcCompare, AFileOfTheRefitLightsAsTheRefitAndATransposedOneDoesNot) {
    // compare's integrated-light report reads each layout's matrices back:
    // a file that holds the refit (in float) gives the refit's light error
    // at every texel; with the off-diagonal elements of M^-1 swapped (the
    // matrix transposed, the bug users report most) it is far worse.
    test::TempDir dir;
    for (const char* id : {"ltc_1", "hdrp_ltc_ggx"}) {
        SCOPED_TRACE(id);
        const TableDefinition& def = find_table(id);
        TableSettings s = default_settings(def);
        for (Axis& a : s.axes) a.count = 3;
        const std::string path = dir / (std::string(id) + ".exr");
        write_exr(path, generate(def, s), PixelType::float32);
        ExrImage img = read_table_image(path);
        const LutDescription d = describe_from_metadata(img, path);
        const LtcComparison c = compare_ltc_light(img, d, 0);
        ASSERT_EQ(c.texels, 9u);
        EXPECT_EQ(c.refit_better, 0u);
        for (std::size_t k = 0; k < c.texels; ++k) EXPECT_NEAR(c.stored_light[k], c.refit_light[k], 1e-5) << k;
        // Heitz stores (m00, m02, m20, m22): swap G and B; HDRP (m00, m20, m11, m02): swap G and A.
        const std::size_t a = 1, b = std::string(id) == "ltc_1" ? 2 : 3;
        for (std::size_t k = 0; k < c.texels; ++k) std::swap(img.pixels[4 * k + a], img.pixels[4 * k + b]);
        const LtcComparison t = compare_ltc_light(img, d, 0);
        EXPECT_GT(t.stored_light_max, 2.0 * c.refit_light_max + 0.05);
    }
}

TEST(LtcTables, HdrpLayoutIsTheHeitzMatrixRenormalized) {
    const TableDefinition& h = find_table("ltc_1");
    const TableDefinition& u = find_table("hdrp_ltc_ggx");
    TableSettings s = default_settings(h);
    s.axes[0].count = 4;
    s.axes[1].count = 4;
    const Table th = generate(h, s);
    clear_shared_results();  // HDRP's own fits
    const Table tu = generate(u, s);
    for (std::size_t k = 0; k < th.texel_count(); ++k) {
        if (k % 4 == 0) continue;  // roughness 0: HDRP fits at alpha >= 1e-3, Heitz at 1e-5
        const double a = th.at(k, 0), c = th.at(k, 1), b = th.at(k, 2), d = th.at(k, 3);
        EXPECT_NEAR(tu.at(k, 0), a / d, 1e-12 * std::abs(a / d) + 1e-300);
        EXPECT_NEAR(tu.at(k, 1), c / d, 1e-12 * std::abs(c / d) + 1e-300);
        EXPECT_NEAR(tu.at(k, 2), 1.0 / d, 1e-12 / d);
        EXPECT_NEAR(tu.at(k, 3), b / d, 1e-12 * std::abs(b / d) + 1e-300);
    }
}

}  // namespace
}  // namespace brdflut

namespace brdflut {
namespace {
TEST(LtcVerify, ClosedFormAndLocalMinimumChecksPass) {
    for (const char* id : {"ltc_1", "ltc_2", "hdrp_ltc_ggx"}) {
        const std::vector<CheckRow> rows = verify_table(find_table(id));
        ASSERT_FALSE(rows.empty()) << id;
        for (const CheckRow& r : rows) EXPECT_TRUE(r.pass) << id << ": " << r.check << " " << r.max_error << " " << r.where;
    }
}
// The fit's own bank (ltc_fit_light_bank) is as its header describes: eight
// squares of unit directions, none of them a light of the report's bank; at
// grazing view the peak lights straddle the horizon (the case the light
// term is for) and the light beyond the mirror direction lies below it.
// The exact light of a polygon (what the error reports and the fit's light
// term hold an LTC to) against the lobe's albedo by the catalogue's own
// route: four quadrilaterals from the normal to points below the horizon
// tile the upper hemisphere, so their lights add up to n0. Each ray of a
// quadrant ends at the horizon (where the Estevez-Kulla Lambda goes as
// mu_i^c and the ray is integrated in a flattened variable), and the
// quadrants are turned by 45 degrees so that the Charlie lobes' point kink
// at the mirror direction lies inside one of them.
TEST(LtcLights, ExactLightsOfQuadrantsTilingTheHemisphereAddUpToTheAlbedo) {
    auto unit = [](const Vec3& v) {
        const double l = std::sqrt(dot(v, v));
        return Vec3{v.x / l, v.y / l, v.z / l};
    };
    std::vector<LtcLobe> lobes;
    for (double alpha : {0.05, 0.3, 1.0})
        for (double mu : {0.02, 0.35, 0.9}) {
            lobes.emplace_back(mu, alpha, Visibility::height_correlated);
            lobes.emplace_back(LtcLobeKind::charlie_sheen, mu, alpha);
            for (SheenShadowing sh : {SheenShadowing::estevez_kulla, SheenShadowing::estevez_kulla_soft})
                lobes.emplace_back(std::make_shared<const CharlieLobe>(alpha, sh), mu, alpha, 1, 1e-11);
            lobes.emplace_back(std::make_shared<const ZeltnerApproxSheenLobe>(alpha), mu, alpha, 2, 1e-11);
        }
    for (const LtcLobe& lobe : lobes) {
        const LtcNorms norms = ltc_norms(lobe);
        const ltc_detail::Setup s = ltc_detail::make_setup(lobe, norms.n0, 28, 16);
        double sum = 0.0;
        for (int q = 0; q < 4; ++q) {
            auto below = [&](double deg) {
                const double a = (deg + 45.0 + 90.0 * q) * kPi / 180.0;
                return unit(Vec3{std::cos(a), std::sin(a), -0.2});
            };
            const LtcLight quadrant{"quadrant", {Vec3{0.0, 0.0, 1.0}, below(0.0), below(45.0), below(90.0)}};
            sum += ltc_detail::polygon_light(lobe, s.frame, quadrant, 1e-9 * norms.n0);
        }
        EXPECT_NEAR(sum, norms.n0, 2e-9 * norms.n0 + norms.n0_error)
            << to_string(lobe.kind) << " alpha " << lobe.param << " mu " << lobe.mu_o;
    }
}

// A light that is its own mirror image in the plane of incidence is taken
// as twice its half (phi in [0, pi]); cut along that plane into two quads
// that are not, each taken once round, the two halves give the same light
// within the tolerance. Every lobe kind, and each mirrored light of the
// report's bank, from grazing to normal view.
TEST(LtcLights, MirroredLightsAreTwiceTheirHalfAndAgreeWithTheTwoHalvesOnceRound) {
    auto unit = [](const Vec3& v) {
        const double l = std::sqrt(dot(v, v));
        return Vec3{v.x / l, v.y / l, v.z / l};
    };
    auto mid = [&](const Vec3& a, const Vec3& b) { return unit(Vec3{a.x + b.x, a.y + b.y, a.z + b.z}); };
    int mirrored_lights = 0;
    for (double mu : {0.03, 0.5, 0.97})
        for (double alpha : {0.1, 0.6}) {
            std::vector<LtcLobe> lobes;
            lobes.emplace_back(mu, alpha, Visibility::height_correlated);
            lobes.emplace_back(std::make_shared<const CharlieLobe>(alpha, SheenShadowing::estevez_kulla), mu, alpha, 1,
                               1e-10);
            lobes.emplace_back(std::make_shared<const ZeltnerApproxSheenLobe>(alpha), mu, alpha, 2, 1e-10);
            for (const LtcLobe& lobe : lobes) {
                const double n0 = ltc_norms(lobe).n0;
                const ltc_detail::Setup s = ltc_detail::make_setup(lobe, n0, 28, 16);
                for (const LtcLight& l : ltc_light_bank(mu)) {
                    const auto& v = l.vertices;
                    // The square's edges v1 v2 and v3 v0 cross the plane y = 0
                    // at their midpoints when the square is mirrored.
                    const Vec3 a = mid(v[1], v[2]), b = mid(v[3], v[0]);
                    if (!(std::abs(a.y) < 1e-12 && std::abs(b.y) < 1e-12)) continue;
                    ++mirrored_lights;
                    const LtcLight lower{"lower half", {v[0], v[1], a, b}}, upper{"upper half", {b, a, v[2], v[3]}};
                    const double tol = 1e-7 * n0;
                    const double whole = ltc_detail::polygon_light(lobe, s.frame, l, tol);
                    const double halves = ltc_detail::polygon_light(lobe, s.frame, lower, tol) +
                                          ltc_detail::polygon_light(lobe, s.frame, upper, tol);
                    EXPECT_NEAR(whole, halves, 3.0 * tol) << l.name << ", " << to_string(lobe.kind) << " alpha " << alpha
                                                          << " mu " << mu;
                    EXPECT_GT(whole, 0.0) << l.name;
                }
            }
        }
    EXPECT_EQ(mirrored_lights, 3 * 2 * 3 * 8);  // 8 of the bank's 10 lights are centred in the plane
}

TEST(LtcLights, FitBankIsItsOwnAndStraddlesTheHorizonAtGrazingView) {
    for (double mu : {kLtcMinMu, 0.2, 0.39}) {
        const std::vector<LtcLight> fit = ltc_fit_light_bank(mu), report = ltc_light_bank(mu);
        ASSERT_EQ(fit.size(), 8u);
        for (const LtcLight& l : fit) {
            for (const Vec3& v : l.vertices) EXPECT_NEAR(dot(v, v), 1.0, 1e-12) << l.name;
            for (const LtcLight& r : report) {
                double d = 0.0;
                for (std::size_t i = 0; i < 4; ++i) {
                    const Vec3 e{l.vertices[i].x - r.vertices[i].x, l.vertices[i].y - r.vertices[i].y,
                                 l.vertices[i].z - r.vertices[i].z};
                    d = std::max(d, dot(e, e));
                }
                EXPECT_GT(d, 1e-6) << l.name << " is " << r.name;
            }
        }
    }
    const std::vector<LtcLight> grazing = ltc_fit_light_bank(kLtcMinMu);
    for (std::size_t k = 0; k < 3; ++k) {  // the peak lights, 3, 10 and 25 degrees
        double lo = 1.0, hi = -1.0;
        for (const Vec3& v : grazing[k].vertices) {
            lo = std::min(lo, v.z);
            hi = std::max(hi, v.z);
        }
        EXPECT_LT(lo, 0.0) << grazing[k].name;
        EXPECT_GT(hi, 0.0) << grazing[k].name;
    }
    for (const Vec3& v : grazing[4].vertices) EXPECT_LT(v.z, 0.0) << grazing[4].name;
}

}  // namespace
}  // namespace brdflut
