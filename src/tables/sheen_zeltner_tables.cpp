// The analytic volumetric sheen of Zeltner, Burley and Chiang 2022
// (zeltner_sheen.h): its directional albedo, with the single-scattering part
// apart, and its average, through the generic lobe path (generic_lobe.h)
// from the BRDF alone. The checks integrate the two terms by other rules: a
// product Gauss-Legendre rule over the hemisphere for the single scattering
// and a one-dimensional Gauss-Kronrod rule for the multiple scattering
// (separable in the azimuth).
#include <cmath>
#include <memory>

#include "brdflut/random.h"
#include "brdflut/zeltner_sheen.h"
#include "tables/checks.h"
#include "tables/ltc_tables.h"
#include "tables/registry.h"

namespace brdflut {
namespace sheen_zeltner_family {  // this family's own names, apart from the other families' in a unity build
namespace {

// Absolute tolerance at standard quality: with an honest estimate below it
// and float rounding, every stored value (at most 1) is within 1e-7 of the
// exact integral.
constexpr double kTableTolerance = 1e-8;
constexpr tables::Tolerances kTolerances = tables::quadrature_tolerances(kTableTolerance);

// alpha below kMinAlpha is computed at kMinAlpha (sigma = 1e-4, the flakes'
// normals within about 1e-4 rad of the horizon; the albedo is then below
// 3e-4 beyond mu = 1/2); mu below kMinMu at kMinMu (the limit is finite:
// both terms stay bounded at grazing view).
constexpr double kMinAlpha = 0.01;
constexpr double kMinMu = 1e-6;

const char* kQuadratureRule =
    "generic lobe path (generic_lobe.h): wi in polar coordinates (theta, psi) about the normal, adaptive "
    "Gauss-Kronrod (10,21) in both; E_avg: adaptive Gauss-Kronrod over mu; alpha below 0.01 computed at 0.01, "
    "cos_theta below 1e-6 at 1e-6; error per value: QUADPACK estimate plus the integrated inner estimates";
const char* kMcSampler = "cosine-weighted hemisphere";

nlohmann::json zeltner_model() {
    return {{"brdf",
             "Zeltner, Burley and Chiang 2022 analytic volumetric sheen (the talk's approximation of a layer of "
             "fibre-like SGGX microflakes): exact single scattering plus the fitted multiple scattering, no Fresnel"},
            {"layer", "unit thickness and density, single-scattering albedo 1, SGGX S = diag(1, 1, sigma^2), "
                      "sigma = alpha^2, specular microflake phase function"},
            {"single_scattering",
             "D(h) (1 - exp(-(s_o/mu_o + s_i/mu_i))) / (4 (s_o mu_i + s_i mu_o)), s(w) = sqrt(w.x^2 + w.y^2 + "
             "sigma^2 w.z^2), D(m) = sigma^3 / (pi (sigma^2 (1 - m.z^2) + m.z^2)^2)"},
            {"multiple_scattering",
             "exp(b - m sqrt(mu_o^2 + mu_i^2)) T(mu_o) T(mu_i), T(c) = beta + (1 - beta)(1 - (1 - c)^12), "
             "beta = max(0.55, 0.44 + 0.42 sigma), m and b Catmull-Rom in sigma through the talk's fitted values"},
            {"roughness", "alpha, the talk's roughness (sigma = alpha^2), linear on the axis as in its tables"},
            {"source", "tizian/ltc-sheen fitting/src/bsdfs/sheen_approx.h @92624114a8ffc433389256f79a10332e54ba17f6"}};
}

// One term of the lobe alone: 0 the single scattering, 1 the multiple
// scattering. The tables integrate the two apart and store E as their sum,
// so that neither is integrated twice.
class TermLobe final : public GenericLobe {
public:
    TermLobe(double alpha, int term) : lobe_(alpha), term_(static_cast<std::size_t>(term)) {}
    double f(const Vec3& wo, const Vec3& wi) const override { return lobe_.terms(wo, wi)[term_]; }
    bool has_sampler() const override { return true; }
    LobeSample sample(const Vec3& wo, double u1, double u2) const override { return lobe_.sample(wo, u1, u2); }

private:
    ZeltnerApproxSheenLobe lobe_;
    std::size_t term_;
};

enum class Kind { albedo, average };

class ZeltnerEvaluator final : public TexelEvaluator {
public:
    ZeltnerEvaluator(Kind kind, const TableSettings& s)
        : kind_(kind), method_(s.method), samples_(s.samples), seed_(s.seed), abs_tol_(kTolerances.at(s.quality)) {}

    TexelValue evaluate(const double* c, std::uint64_t texel) const override {
        TexelValue out;
        const bool mc = method_ == Method::monte_carlo;
        const double scale = mc ? tables::kMcErrorSigmas : 1.0;
        const std::uint64_t seed = mix_seed(seed_, texel);
        const double mu = kind_ == Kind::average ? 1.0 : std::max(c[0], kMinMu);
        const double alpha = std::max(kind_ == Kind::average ? c[0] : c[1], kMinAlpha);
        GenericOptions opt;
        opt.abs_tol = 0.5 * abs_tol_;  // each term's half: E = E_ss + E_ms stays within abs_tol
        std::array<Estimate<1>, 2> e;
        for (int k = 0; k < 2; ++k) {
            const TermLobe lobe(alpha, k);
            if (kind_ == Kind::average)
                e[k] = mc ? generic_moment_average_mc<1>(lobe, {kWeightOne}, samples_, seed)
                          : generic_albedo_average(lobe, opt);
            else
                e[k] = mc ? generic_moments_mc<1>(lobe, mu, {kWeightOne}, samples_, seed)
                          : generic_albedo(lobe, mu, opt);
            out.evaluations += e[k].evaluations;
        }
        out.value[0] = e[0].value[0] + e[1].value[0];
        out.error[0] = scale * (e[0].error[0] + e[1].error[0]);
        out.value[1] = e[0].value[0];
        out.error[1] = scale * e[0].error[0];
        return out;
    }

private:
    Kind kind_;
    Method method_;
    long long samples_;
    std::uint64_t seed_;
    double abs_tol_;
};

AxisSpec zeltner_alpha_axis(int count) {
    return {Axis{"alpha", 0.0, 1.0, count, Placement::center, Warp::linear}, 0.0, 1.0,
            "alpha, the roughness of Zeltner et al. 2022 (SGGX fibre cross-section sigma = alpha^2); below 0.01 "
            "computed at 0.01"};
}

TableDefinition make(Kind kind, std::string id, std::string description, std::vector<AxisSpec> axes,
                     std::vector<std::string> channels) {
    TableDefinition d;
    d.id = std::move(id);
    d.description = std::move(description);
    d.axes = std::move(axes);
    d.channels = std::move(channels);
    // The average's Monte Carlo route (mu drawn with density 2 mu) would
    // miss the grazing views that carry most of a thin layer's average (at
    // alpha = 0.03 the single scattering is 0.07 at mu = 1e-3 and 2e-7 at
    // mu = 0.1): 1e5 samples see none and report a tiny error. The albedo
    // table keeps its Monte Carlo route; the average is held to a second rule.
    d.supports_monte_carlo = kind == Kind::albedo;
    // A generic-path integral costs about a millisecond a texel: too much
    // for identify's coarse search (catalogue.h); compare --as still works.
    d.searched_by_identify = false;
    d.prepare = [kind](const TableSettings& s) {
        PreparedTable p;
        p.evaluator = std::make_unique<ZeltnerEvaluator>(kind, s);
        p.model = zeltner_model();
        p.method = s.method == Method::monte_carlo ? tables::monte_carlo_method(kMcSampler, s)
                                                   : tables::quadrature_method(kQuadratureRule, kTolerances.at(s.quality));
        return p;
    };
    return d;
}

// ---------------------------------------------------------------------------
// Checks.

using CheckResult = tables::CheckResult;

// The single scattering by a product Gauss-Legendre rule over (theta_i,
// phi_i) in [0, pi/2] x [0, pi] (twice, by symmetry), at alpha >= 0.5 where
// the term is smooth on the scale of the rule: 96 x 96 nodes.
double single_scattering_by_product_rule(double mu_o, double alpha) {
    const ZeltnerApproxSheenLobe lobe(alpha);
    const Vec3 wo = direction_from_mu(mu_o);
    const GaussLegendre& rule = gauss_legendre(96);
    double sum = 0.0;
    for (std::size_t i = 0; i < rule.x.size(); ++i) {
        const double theta = 0.25 * kPi * (rule.x[i] + 1.0), st = std::sin(theta), ct = std::cos(theta);
        for (std::size_t j = 0; j < rule.x.size(); ++j) {
            const double phi = 0.5 * kPi * (rule.x[j] + 1.0);
            const Vec3 wi{st * std::cos(phi), st * std::sin(phi), ct};
            sum += rule.w[i] * rule.w[j] * lobe.terms(wo, wi)[0] * ct * st;
        }
    }
    return 2.0 * (0.25 * kPi) * (0.5 * kPi) * sum;
}

// The multiple scattering does not depend on the azimuth: its albedo is
// 2 pi times a one-dimensional integral over mu_i.
double multiple_scattering_by_1d_rule(double mu_o, double alpha) {
    const ZeltnerApproxSheenLobe lobe(alpha);
    const Vec3 wo = direction_from_mu(mu_o);
    AdaptiveOptions opt;
    opt.abs_tol = 1e-12;
    const Estimate<1> e = integrate_adaptive<1>(
        [&](double mu) { return std::array<double, 1>{lobe.terms(wo, direction_from_mu(mu))[1] * mu}; }, 0.0, 1.0,
        opt);
    return kTwoPi * e.value[0];
}

std::vector<std::array<double, 2>> check_points() { return {{0.05, 0.5}, {0.4, 0.7}, {0.9, 1.0}, {0.6, 0.55}}; }

ClosedFormCheck single_scattering_check() {
    return {"E_ss vs a 96 x 96 Gauss-Legendre rule over the hemisphere (alpha >= 0.5)", kTableTolerance + 1e-9,
            [](const TexelEvaluator& e) {
                return tables::worst_over(e, check_points(), 1, [](const auto& p) {
                    return single_scattering_by_product_rule(p[0], p[1]);
                });
            }};
}

ClosedFormCheck multiple_scattering_check() {
    return {"E - E_ss vs 2 pi * integral of f_ms mu_i dmu_i (the term is isotropic in the azimuth)",
            2.0 * kTableTolerance + 1e-11, [](const TexelEvaluator& e) {
                CheckResult worst{0.0, ""};
                for (const auto& p : std::vector<std::array<double, 2>>{{0.01, 0.05}, {0.3, 0.2}, {0.7, 0.8}, {1.0, 1.0}}) {
                    const TexelValue v = e.evaluate(p.data(), 0);
                    const double err = std::abs(v.value[0] - v.value[1] - multiple_scattering_by_1d_rule(p[0], p[1]));
                    if (!(err <= worst.first)) worst = {err, "at cos_theta = " + std::to_string(p[0]) +
                                                                 ", alpha = " + std::to_string(p[1])};
                }
                return worst;
            }};
}

// The average at alpha = 0.6 against Gauss-Legendre over mu of the albedo
// by the two rules above (each smooth in mu).
ClosedFormCheck average_check() {
    return {"E_avg at alpha = 0.6 vs 2 * integral of E mu dmu (32-point Gauss-Legendre over the two rules above)",
            kTableTolerance + 1e-8, [](const TexelEvaluator& e) {
                const double alpha = 0.6;
                const GaussLegendre& rule = gauss_legendre(32);
                double sum = 0.0;
                for (std::size_t j = 0; j < rule.x.size(); ++j) {
                    const double mu = 0.5 * (rule.x[j] + 1.0);
                    sum += 0.5 * rule.w[j] * 2.0 * mu *
                           (single_scattering_by_product_rule(mu, alpha) + multiple_scattering_by_1d_rule(mu, alpha));
                }
                const double x[2] = {alpha, 0.0};  // the average's one axis (padded: the evaluator reads by kind)
                return CheckResult{std::abs(e.evaluate(x, 0).value[0] - sum), "at alpha = 0.6"};
            }};
}

// ---------------------------------------------------------------------------
// The LTC of the lobe in Heitz's layout (as ltc_sheen_charlie_ek): 64x64,
// columns the talk's alpha at end points (linear, at least 0.01), rows
// cos(theta) = 1 - (j/63)^2, fitted through the generic path; its norm held
// to the two rules above.

std::vector<TableDefinition> heitz_zeltner_ltc_layer() {
    LtcLayer layer;
    layer.name = "sheen_zeltner";
    layer.matrix_description =
        "LTC of the Zeltner 2022 analytic volumetric sheen in ltc_1's layout (alpha >= 0.01)";
    layer.norm_description = "Norm n0 of the Zeltner 2022 analytic volumetric sheen on ltc_sheen_zeltner's grid";
    layer.error_description =
        "Per-texel error of the Zeltner 2022 sheen LTC fit in Heitz's layout (the texels of ltc_sheen_zeltner)";
    layer.roughness_meaning = "the talk's alpha (sigma = alpha^2), linear, computed at 0.01 below it";
    layer.model = [](const std::map<std::string, std::string>&) {
        nlohmann::json m = zeltner_model();
        m["brdf"] = std::string(m["brdf"]) + ", fitted by a linearly transformed cosine";
        m["roughness"] = "alpha = max(the column coordinate, 0.01), the talk's alpha (not squared)";
        return m;
    };
    layer.norms_rule = "n0 by the generic lobe path (as sheen_zeltner_albedo E, to 1e-8)";
    layer.engine_source = "selfshadow/ltc_code fit/fitLTC.cpp (packTab, ltc_1's grid); the lobe of tizian/ltc-sheen "
                          "fitting/src/bsdfs/sheen_approx.h @92624114a8ffc433389256f79a10332e54ba17f6";
    const std::uint64_t key = ltc_lobe_key("zeltner_approx_sheen");
    layer.lobe = [key](double r, double mu, const std::map<std::string, std::string>&) {
        const double alpha = std::max(r, kMinAlpha);
        return LtcLobe(std::make_shared<const ZeltnerApproxSheenLobe>(alpha), std::max(mu, kMinMu), alpha, key,
                       kTableTolerance);
    };
    layer.norm_checks = {{"n0 vs the single-scattering product rule plus the multiple-scattering 1-D rule (alpha >= 0.5)",
                          2.0 * kTableTolerance + 1e-9, [](const TexelEvaluator& e) {
                              const std::vector<std::array<double, 2>> pts = {{0.5, 0.3}, {0.75, 0.9}, {1.0, 0.05}};
                              return tables::worst_over(e, pts, 0, [](const auto& p) {
                                  return single_scattering_by_product_rule(p[1], p[0]) +
                                         multiple_scattering_by_1d_rule(p[1], p[0]);
                              });
                          }}};
    return heitz_ltc_layer(layer);
}

}  // namespace
}  // namespace sheen_zeltner_family

void register_sheen_zeltner_family(FamilyEntries& family) {
    using namespace sheen_zeltner_family;
    family.families.push_back(
        {"", "Volumetric sheen (Zeltner, Burley and Chiang 2022)",
         "The analytic sheen of Zeltner, Burley and Chiang 2022: a unit-thickness layer of fibre-like SGGX "
         "microflakes standing along the normal (cross-section sigma = alpha^2, specular phase function, no "
         "absorption), its single scattering exact and its multiple scattering the talk's fitted term. This is "
         "the reference BRDF the talk fits its two-parameter LTC to (its \"approx\" table); the simulated layer "
         "itself (the \"volume\" table, which Cycles, Unreal, OSL and Babylon.js ship) is the sheen_volume family. "
         "Tables: the "
         "directional albedo with its single-scattering part, and their averages, through the generic lobe path; "
         "the checks integrate the two terms by other rules; and its LTC in Heitz's layout (ltc_sheen_zeltner, "
         "_norm, _error, in the ltc preset)."});
    std::vector<TableDefinition>& out = family.tables;
    out.push_back(make(Kind::albedo, "sheen_zeltner_albedo",
                       "Zeltner 2022 analytic volumetric sheen: albedo E and its single-scattering part E_ss",
                       {tables::cos_theta_axis(32), zeltner_alpha_axis(32)},
                       {"E: integral of f cos(theta_i) dw_i (single and multiple scattering)",
                        "E_ss: the single-scattering part"}));
    out.back().checks = {single_scattering_check(), multiple_scattering_check()};
    out.push_back(make(Kind::average, "sheen_zeltner_albedo_avg",
                       "Zeltner 2022 analytic volumetric sheen: average albedo 2 * integral of E mu dmu, and of E_ss",
                       {zeltner_alpha_axis(16)},
                       {"E_avg: 2 * integral of E(mu) mu dmu", "E_ss avg: the single-scattering part's"}));
    out.back().checks = {average_check()};
    for (TableDefinition& d : heitz_zeltner_ltc_layer()) out.push_back(std::move(d));
}

}  // namespace brdflut
