// Charlie sheen with the Estevez-Kulla shadowing (charlie_ek.h): albedo and
// Fresnel moment over the half vector (sheen_charlie_moments), their
// averages through the generic lobe path (generic_lobe.h) from the BRDF
// alone, with or without the terminator softening; HDRP's fabric Lambert
// albedo; HDRP's Charlie LTC layer. The same lobe with Neubelt's visibility
// gives the moments Unreal's cloth table stores. The checks use an
// independent rule over the half vector's polar angles
// (sheen_charlie_check.h).
//
// Estevez and Kulla 2017, "Production Friendly Microfacet Sheen BRDF"
#include <cmath>
#include <memory>

#include "brdflut/charlie_ek.h"
#include "brdflut/random.h"
#include "tables/checks.h"
#include "tables/ltc_tables.h"
#include "tables/registry.h"
#include "tables/shared_results.h"
#include "tables/sheen_charlie_check.h"

namespace brdflut {

// ---------------------------------------------------------------------------
// The independent rule (sheen_charlie_check.h). With h = (sin t cos p,
// sin t sin p, cos t), wi = 2 (wo.h) h - wo and dw_i = 4 (wo.h) dw_h, so
//   integral of f w cos(theta_i) dw_i = integral of f w mu_i 4 (wo.h) sin t dt dp
// over the half vectors with mu_i = 2 (wo.h) cos t - mu_o > 0: for fixed t,
// cos p > (mu_o / (2 cos t) - mu_o cos t) / (sin_o sin t), p in [0, p_max]
// (twice, by symmetry). The azimuth is split where mu_i = 1/2 (Lambda's
// kink); both levels are adaptive Gauss-Kronrod (15,31).
namespace {
std::array<double, 2> charlie_moments_by_half_vector_uncached(double mu_o, double alpha, SheenShadowing shadowing) {
    const CharlieLobe lobe(alpha, shadowing);
    const double sin_o = std::sqrt((1.0 - mu_o) * (1.0 + mu_o));
    const Vec3 wo{sin_o, 0.0, mu_o};
    AdaptiveOptions opt;
    opt.abs_tol = 1e-11;
    opt.max_intervals = 2000;
    opt.rule = KronrodRule::k31;
    // cos(p) at which wo.h takes the value oh, at polar angle t (c, s).
    auto cos_p_at = [&](double oh, double c, double s) { return (oh - mu_o * c) / (sin_o * s); };
    auto over_p = [&](double t) -> std::array<double, 2> {
        const double c = std::cos(t), s = std::sin(t);
        auto integrand = [&](double p) -> std::array<double, 2> {
            const Vec3 h{s * std::cos(p), s * std::sin(p), c};
            const double oh = dot(wo, h);
            const Vec3 wi{2.0 * oh * h.x - wo.x, 2.0 * oh * h.y - wo.y, 2.0 * oh * h.z - wo.z};
            if (!(wi.z > 0.0) || !(oh > 0.0)) return {0.0, 0.0};
            const double v = 2.0 * lobe.f(wo, wi) * wi.z * 4.0 * oh * s;  // twice: p in [-p_max, p_max]
            return {v, v * std::pow(1.0 - oh, 5)};
        };
        if (!(c > 0.0)) return {0.0, 0.0};
        double p_max = kPi, p_kink = -1.0;
        if (sin_o * s > 0.0) {
            const double cos_max = cos_p_at(mu_o / (2.0 * c), c, s);
            if (cos_max >= 1.0) return {0.0, 0.0};
            if (cos_max > -1.0) p_max = std::acos(cos_max);
            const double cos_kink = cos_p_at((0.5 + mu_o) / (2.0 * c), c, s);
            if (cos_kink > -1.0 && cos_kink < 1.0) p_kink = std::acos(cos_kink);
        } else if (2.0 * c * c - 1.0 <= 0.0) {
            return {0.0, 0.0};
        }
        std::array<double, 2> sum{};
        double a = 0.0;
        for (double b : {p_kink, p_max}) {
            if (!(b > a)) continue;
            const Estimate<2> e = integrate_adaptive<2>(integrand, a, b, opt);
            sum[0] += e.value[0];
            sum[1] += e.value[1];
            a = b;
        }
        return sum;
    };
    AdaptiveOptions outer = opt;
    outer.abs_tol = 1e-10;
    // The lobe sits at t near pi/2 on the scale sqrt(alpha): panels toward it.
    std::array<double, 2> total{};
    double a = 0.0;
    for (double frac : {0.5, 0.8, 0.9, 0.95, 0.98, 0.99, 0.995, 1.0}) {
        const double b = 0.5 * kPi * frac;
        const Estimate<2> e = integrate_adaptive<2>(over_p, a, b, outer);
        total[0] += e.value[0];
        total[1] += e.value[1];
        a = b;
    }
    return total;
}
}  // namespace

// The checks of a table's channels (and the presets holding the same
// moments) ask for the same points: each is kept in the shared results.
std::array<double, 2> tables::charlie_moments_by_half_vector(double mu_o, double alpha, SheenShadowing shadowing) {
    static tables::SharedResults<3, std::array<double, 2>> done(1 << 12);
    return done.get({tables::key_bits(mu_o), tables::key_bits(alpha), tables::key_enum(shadowing)},
                    [&] { return charlie_moments_by_half_vector_uncached(mu_o, alpha, shadowing); });
}

namespace sheen_charlie_family {  // this family's own names, apart from the other families' in a unity build
namespace {

// Absolute tolerance of the quadrature at standard quality: with an honest
// estimate below it and float rounding, every stored value up to 1 is
// within 1e-7 of the exact integral.
constexpr double kCharlieTableTolerance = 1e-8;
constexpr tables::Tolerances kTolerances = tables::quadrature_tolerances(kCharlieTableTolerance);

// Roughness below kMinAlpha is computed at kMinAlpha, below the smallest
// alpha of the default grid ((0.5/128)^2 = 1.5e-5, where the tests hold the
// generic path to sheen_charlie_albedo's own quadrature); alpha = 0 is the
// limit 0 (the normals lie in the horizon and reflect every view below it).
constexpr double kMinAlpha = 1e-5;
// View cosines below kMinMu are computed at kMinMu (HDRP's ClampNdotV):
// G / (4 mu_o mu_i) grows as 1/mu_o at grazing view, since Lambda(0) is
// finite, so E(0) is infinite.
constexpr double kMinMu = 1e-4;

// The rules of the three kinds of table.
const char* kMomentsRule =
    "over the half vector (sheen_charlie_moments, charlie_ek.h): v = sin(theta_h)^(2 + 1/alpha), which takes "
    "D, in ln(pi/2 - theta_h), split where the rings start and stop reaching the horizon and crossing mu_i = 1/2 "
    "(Lambda's kink) and at the ring through the normal (Lambda's (1 - mu_i)^c), the start flattened by s^4; the "
    "azimuth split at mu_i = 1/2, the piece that ends at the horizon in t^4; adaptive Gauss-Kronrod (7,15) outside, "
    "(15,31) inside; alpha below 1e-5 computed at 1e-5, alpha = 0 the limit 0; cos_theta below 1e-4 computed at "
    "1e-4; error per value: QUADPACK estimate plus the integrated inner estimates and the bounded tail";
const char* kAverageRule =
    "2 * integral of M(mu) mu dmu by adaptive Gauss-Kronrod over mu, split at mu = 1/2 (Lambda(mu_o)'s kink), each "
    "M(mu) through the generic lobe path (generic_lobe.h: wi in polar coordinates about the normal, split at the "
    "cone mu_i = 1/2 and at the rings through the mirror direction and the normal); alpha below 1e-5 computed at "
    "1e-5, alpha = 0 the limit 0; error per value: QUADPACK estimate plus the integrated inner estimates";
const char* kFabricRule = "the generic lobe path (generic_lobe.h) over the hemisphere; error per value: QUADPACK estimate";
const char* kMcSampler = "equal mixture of the cosine-weighted hemisphere and reflected Charlie normals";

ModelOption shadowing_option() {
    return {"sheen_shadowing",
            "shadowing of the Charlie sheen lobe: estevez_kulla (the Lambda fit of Estevez and Kulla 2017, as HDRP "
            "and glTF), estevez_kulla_soft (with the paper's terminator softening on the light direction), "
            "neubelt (Neubelt's visibility, as Filament and Unreal)",
            "estevez_kulla",
            {"estevez_kulla", "estevez_kulla_soft", "neubelt"}};
}

nlohmann::json charlie_model(SheenShadowing s) {
    nlohmann::json m = {{"brdf", "Charlie sheen, no Fresnel"},
                        {"distribution", "charlie: (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi)"},
                        {"shadowing", to_string(s)},
                        {"roughness", "alpha = perceptual_roughness^2"}};
    if (s == SheenShadowing::neubelt) {
        m["visibility"] = "neubelt: 1 / (4 (mu_i + mu_o - mu_i mu_o))";
    } else {
        m["visibility"] = "G / (4 mu_o mu_i), G = 1 / (1 + Lambda(mu_o) + Lambda_l(mu_i))";
        m["lambda"] =
            "exp(L(mu)) for mu < 1/2, exp(2 L(1/2) - L(1 - mu)) otherwise; L(x) = a/(1 + b x^c) + d x + e, "
            "(a, b, c, d, e) = t (25.3245, 3.32435, 0.16801, -1.27393, -4.85967) + (1 - t) (21.5473, 3.82987, "
            "0.19823, -1.97760, -4.32054), t = (1 - alpha)^2 (Estevez and Kulla 2017)";
        m["terminator"] = s == SheenShadowing::estevez_kulla_soft
                              ? "Lambda_l(mu_i) = Lambda(mu_i)^(1 + 2 (1 - mu_i)^8) (the light direction)"
                              : "none: Lambda_l = Lambda";
    }
    return m;
}

// The weights of the two moments: 1 and (1 - v.h)^5.
constexpr std::array<MomentWeight, 2> kWeights = {MomentWeight{moment_weight::one},
                                                   MomentWeight{moment_weight::schlick}};

std::uint64_t shadowing_key(SheenShadowing s) { return tables::key_enum(s); }

// {E, F} at one texel, computed once per process for each (mu, alpha,
// shadowing, tolerance) and shared by the tables of a run (the presets read
// the same texels).
Estimate<2> moments(double mu, double alpha, SheenShadowing s, double abs_tol, bool* computed = nullptr) {
    if (computed) *computed = true;
    if (!(alpha > 0.0)) return {};
    static tables::SharedResults<4, Estimate<2>> cache(1 << 18);
    return cache.get({tables::key_bits(mu), tables::key_bits(alpha), tables::key_bits(abs_tol), shadowing_key(s)},
                     [&] { return sheen_charlie_moments(std::max(mu, kMinMu), std::max(alpha, kMinAlpha), s, abs_tol); },
                     computed);
}

enum class Kind { moments, average, fabric };

class CharlieEvaluator final : public TexelEvaluator {
public:
    CharlieEvaluator(Kind kind, SheenShadowing s, const TableSettings& st)
        : kind_(kind), shadowing_(s), method_(st.method), samples_(st.samples), seed_(st.seed),
          abs_tol_(kTolerances.at(st.quality)) {}

    TexelValue evaluate(const double* c, std::uint64_t texel) const override {
        TexelValue out;
        const bool mc = method_ == Method::monte_carlo;
        const double scale = mc ? tables::kMcErrorSigmas : 1.0;
        const std::uint64_t seed = mix_seed(seed_, texel);
        Estimate<2> e;
        bool computed = true;
        if (kind_ == Kind::fabric) {
            // The albedo of (1 - alpha/2)/pi by the generic path.
            const FabricLambertLobe lobe(c[1]);
            Estimate<1> a;
            if (mc) {
                a = generic_moments_mc<1>(lobe, c[0], {kWeightOne}, samples_, seed);
            } else {
                GenericOptions opt;
                opt.abs_tol = abs_tol_;
                a = generic_albedo(lobe, c[0], opt);
            }
            out.value[0] = a.value[0];
            out.error[0] = scale * a.error[0];
            out.evaluations = a.evaluations;
            return out;
        }
        if (kind_ == Kind::average) {
            const double alpha = c[0];
            if (alpha > 0.0) {
                const CharlieLobe lobe(std::max(alpha, kMinAlpha), shadowing_);
                if (mc) {
                    e = generic_moment_average_mc<2>(lobe, kWeights, samples_, seed);
                } else {
                    GenericOptions opt;
                    opt.abs_tol = abs_tol_;
                    e = generic_moment_average<2>(lobe, kWeights, opt);
                }
            }
            out.value = {e.value[0], e.value[1], 0.0, 0.0};
            out.error = {scale * e.error[0], scale * e.error[1], 0.0, 0.0};
            out.evaluations = e.evaluations;
            return out;
        }
        const double mu = c[0], alpha = c[1];
        if (mc && alpha > 0.0) {
            e = generic_moments_mc<2>(CharlieLobe(std::max(alpha, kMinAlpha), shadowing_), std::max(mu, kMinMu),
                                      kWeights, samples_, seed);
        } else if (!mc) {
            e = moments(mu, alpha, shadowing_, abs_tol_, &computed);
        }
        if (computed) out.evaluations = e.evaluations;
        // E / (1 + E): its error is at most E's (the derivative is below 1).
        const double enc = e.value[0] / (1.0 + e.value[0]);
        out.value = {e.value[0], e.value[1], enc, 0.0};
        out.error = {scale * e.error[0], scale * e.error[1], scale * e.error[0], 0.0};
        return out;
    }

private:
    Kind kind_;
    SheenShadowing shadowing_;
    Method method_;
    long long samples_;
    std::uint64_t seed_;
    double abs_tol_;
};

AxisSpec charlie_alpha_axis(int count) {
    AxisSpec a = tables::alpha_axis(count);
    a.meaning = "Charlie alpha (the exponent of sin(theta_h) is 1/alpha); the square warp makes the rows linear "
                "in perceptual roughness sqrt(alpha)";
    return a;
}

TableDefinition make(Kind kind, std::string id, std::string description, std::vector<AxisSpec> axes,
                     std::vector<std::string> channels) {
    TableDefinition d;
    d.id = std::move(id);
    d.description = std::move(description);
    d.axes = std::move(axes);
    d.channels = std::move(channels);
    if (kind != Kind::fabric) d.options = {shadowing_option()};
    d.supports_monte_carlo = true;
    // A generic-path integral costs about a millisecond a texel: too much
    // for identify's coarse search (catalogue.h); compare --as still works.
    d.searched_by_identify = false;
    d.prepare = [kind](const TableSettings& s) {
        const SheenShadowing sh = kind == Kind::fabric ? SheenShadowing::estevez_kulla
                                                       : sheen_shadowing_from_string(tables::param(s, "sheen_shadowing"));
        PreparedTable p;
        p.evaluator = std::make_unique<CharlieEvaluator>(kind, sh, s);
        p.model = kind == Kind::fabric
                      ? nlohmann::json{{"brdf", "HDRP fabric Lambert: (1 - alpha/2) / pi (FabricLambert)"},
                                       {"roughness", "alpha = perceptual_roughness^2"}}
                      : charlie_model(sh);
        p.method = s.method == Method::monte_carlo
                       ? tables::monte_carlo_method(kind == Kind::fabric ? "cosine-weighted hemisphere" : kMcSampler, s)
                       : tables::quadrature_method(kind == Kind::moments   ? kMomentsRule
                                                   : kind == Kind::average ? kAverageRule
                                                                           : kFabricRule,
                                                   kTolerances.at(s.quality));
        return p;
    };
    return d;
}

// ---------------------------------------------------------------------------
// Checks: the half-vector rule at texels spread over the table (the
// checks run at the default settings: Estevez-Kulla without softening).

using CheckResult = tables::CheckResult;
constexpr SheenShadowing kCheckShadowing = SheenShadowing::estevez_kulla;
// The rule's own error is below 1e-10; the table's tolerance.
constexpr double kCheckTolerance = kCharlieTableTolerance + 1e-10;

std::vector<std::array<double, 2>> check_points() {
    return {{0.01, 0.05}, {0.2, 0.3}, {0.5, 0.5}, {0.75, 0.02}, {0.999, 0.9}, {0.05, 1.0}};
}

ClosedFormCheck half_vector_check(int channel) {
    return {channel == 0   ? "E vs a nested Gauss-Kronrod rule over the half vector"
            : channel == 1 ? "F (Fresnel moment) vs a nested Gauss-Kronrod rule over the half vector"
                           : "E/(1 + E) vs the half-vector rule's E",
            kCheckTolerance, [channel](const TexelEvaluator& e) {
                return tables::worst_over(e, check_points(), channel, [channel](const auto& p) {
                    const auto r = tables::charlie_moments_by_half_vector(p[0], p[1], kCheckShadowing);
                    return channel == 2 ? r[0] / (1.0 + r[0]) : r[static_cast<std::size_t>(channel)];
                });
            }};
}

// E_avg, F_avg by Gauss-Legendre over the half-vector rule, split at
// mu = 1/2 (Lambda(mu_o) has its kink there): 24 points in mu = u^4 / 2 on
// [0, 1/2] (L's x^c term is smooth in u there), 16 in mu on [1/2, 1].
ClosedFormCheck average_check(int channel) {
    return {channel == 0 ? "E_avg at alpha = 0.5 vs 2 * integral of E mu dmu (Gauss-Legendre over the half-vector "
                           "rule, split at mu = 1/2)"
                         : "F_avg at alpha = 0.5 vs the same rule over F",
            kCheckTolerance + 2e-9, [channel](const TexelEvaluator& e) {
                const double alpha = 0.5;
                const auto ch = static_cast<std::size_t>(channel);
                auto moment = [&](double mu) {
                    return tables::charlie_moments_by_half_vector(std::max(mu, kMinMu), alpha, kCheckShadowing)[ch];
                };
                double sum = 0.0;
                const GaussLegendre& low = gauss_legendre(24);
                for (std::size_t j = 0; j < low.x.size(); ++j) {
                    const double u = 0.5 * (1.0 + low.x[j]), u3 = u * u * u, mu = 0.5 * u3 * u;
                    sum += 0.5 * low.w[j] * 2.0 * mu * 2.0 * u3 * moment(mu);
                }
                const GaussLegendre& high = gauss_legendre(16);
                for (std::size_t j = 0; j < high.x.size(); ++j) {
                    const double mu = 0.75 + 0.25 * high.x[j];
                    sum += 0.25 * high.w[j] * 2.0 * mu * moment(mu);
                }
                return CheckResult{std::abs(e.evaluate(&alpha, 0).value[ch] - sum), "at alpha = 0.5"};
            }};
}

ClosedFormCheck fabric_check() {
    return {"E vs 1 - alpha/2", kCharlieTableTolerance + 1e-12, [](const TexelEvaluator& e) {
                return tables::worst_over(e, tables::grid_points({0.01, 0.3, 1.0}, {0.0, 0.25, 1.0}), 0,
                                          [](const auto& p) { return 1.0 - 0.5 * p[1]; });
            }};
}

// ---------------------------------------------------------------------------
// HDRP's Charlie LTC layer: the lobe without softening, fitted through the
// generic path on HDRP's grid and in its packing, as hdrp_ltc_ggx: 64x64,
// roughness r = i/63 with alpha = max(r^2, 0.002) (BRDF_Charlie.Eval's
// clamp), rows cos(theta) = 1 - (j/63)^2.

constexpr double kHdrpLtcMinAlpha = 0.002;
const char* kHdrpCharlieSource =
    "Unity-Technologies/Graphics com.unity.render-pipelines.high-definition Runtime/Material/LTCAreaLight/BRDF/"
    "BRDF_Charlie.cs @7a50b047ab6b8628a1433ffebc7fe048fc823a46 (the lobe; HDRP's own fit on this grid: "
    "Generated/LtcData.BRDF_Charlie.cs), LTCAreaLight.hlsl (the packing)";

// The Charlie lobe with the Estevez-Kulla shadowing at alpha = max(r^2,
// min_alpha), its model and its norm rule: what HDRP's and Heitz's layouts
// of it share.
void set_charlie_ek_lobe(LtcLayer& layer, double min_alpha, const std::string& roughness) {
    layer.model = [roughness](const std::map<std::string, std::string>&) {
        nlohmann::json m = charlie_model(SheenShadowing::estevez_kulla);
        m["brdf"] = "Charlie sheen with the Estevez-Kulla shadowing, no Fresnel, fitted by a linearly transformed "
                    "cosine";
        m["roughness"] = roughness;
        return m;
    };
    layer.norms_rule = "n0 = sheen_charlie_moments E (over the half vector), to 1e-8";
    const std::uint64_t key = ltc_lobe_key("charlie_estevez_kulla");
    layer.lobe = [key, min_alpha](double r, double mu, const std::map<std::string, std::string>&) {
        const double alpha = std::max(alpha_from_perceptual(r), min_alpha);
        return LtcLobe(std::make_shared<const CharlieLobe>(alpha, SheenShadowing::estevez_kulla),
                       std::max(mu, kMinMu), alpha, key, kCharlieTableTolerance);
    };
}

std::vector<TableDefinition> hdrp_charlie_ltc_layer() {
    LtcLayer layer;
    layer.name = "charlie";
    layer.matrix_description =
        "HDRP LTC Charlie matrix (Estevez-Kulla shadowing): the inverse divided by its m22 (alpha >= 0.002)";
    layer.error_description = "Per-texel error of the Charlie (Estevez-Kulla) LTC fit (the texels of hdrp_ltc_charlie)";
    layer.roughness_meaning = "perceptual roughness r; Charlie alpha = max(r^2, 0.002)";
    set_charlie_ek_lobe(layer, kHdrpLtcMinAlpha,
                        "alpha = max(perceptual_roughness^2, 0.002) (the clamp of HDRP's BRDF_Charlie)");
    layer.engine_source = kHdrpCharlieSource;
    return hdrp_ltc_layer(layer);
}

// The same lobe in Heitz's layout (as ltc_sheen_charlie, the Neubelt
// variant: alpha = max(r^2, 0.01)), with its norm held to the half-vector
// rule.
constexpr double kHeitzLtcMinAlpha = 0.01;

std::vector<TableDefinition> heitz_charlie_ltc_layer() {
    LtcLayer layer;
    layer.name = "sheen_charlie_ek";
    layer.matrix_description =
        "LTC of the Charlie sheen with the Estevez-Kulla shadowing in ltc_1's layout (alpha >= 0.01)";
    layer.norm_description = "Norm n0 of the Charlie sheen with the Estevez-Kulla shadowing on ltc_sheen_charlie_ek's grid";
    layer.error_description =
        "Per-texel error of the Charlie (Estevez-Kulla) LTC fit in Heitz's layout (the texels of ltc_sheen_charlie_ek)";
    layer.roughness_meaning = "perceptual roughness r; Charlie alpha = max(r^2, 0.01)";
    set_charlie_ek_lobe(layer, kHeitzLtcMinAlpha, "alpha = max(perceptual_roughness^2, 0.01)");
    layer.engine_source = "selfshadow/ltc_code fit/fitLTC.cpp (packTab, ltc_1's grid); the lobe of HDRP's "
                          "BRDF_Charlie and glTF's KHR_materials_sheen";
    layer.norm_checks = {
        {"n0 vs a nested Gauss-Kronrod rule over the half vector", kCheckTolerance, [](const TexelEvaluator& e) {
             const std::vector<std::array<double, 2>> pts = {{0.2, 0.3}, {0.55, 0.75}, {0.9, 0.05}, {1.0, 1.0}};
             return tables::worst_over(e, pts, 0, [](const auto& p) {
                 return tables::charlie_moments_by_half_vector(
                     std::max(p[1], kMinMu), std::max(alpha_from_perceptual(p[0]), kHeitzLtcMinAlpha),
                     SheenShadowing::estevez_kulla)[0];
             });
         }}};
    return heitz_ltc_layer(layer);
}

}  // namespace
}  // namespace sheen_charlie_family

void register_sheen_charlie_family(FamilyEntries& family) {
    using namespace sheen_charlie_family;
    family.families.push_back(
        {"", "Charlie sheen with the Estevez-Kulla shadowing",
         "The Charlie distribution D = (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi) with the shadowing of "
         "Estevez and Kulla 2017, G = 1/(1 + Lambda(mu_o) + Lambda(mu_i)), Lambda from their fit "
         "L(x) = a/(1 + b x^c) + d x + e (coefficients interpolated in (1 - alpha)^2), f = D G/(4 mu_o mu_i), "
         "no Fresnel, alpha = perceptual_roughness^2: the sheen of HDRP's fabric and of glTF's "
         "KHR_materials_sheen. `--sheen_shadowing` adds the paper's terminator softening "
         "(Lambda(mu_i)^(1 + 2 (1 - mu_i)^8) on the light direction) or Neubelt's visibility (the Charlie lobe "
         "of Filament and Unreal). Tables: the albedo E, the Fresnel moment F (f weighted by (1 - v.h)^5) and "
         "HDRP's encoding E/(1 + E), their averages over the view, HDRP's fabric Lambert albedo, and HDRP's "
         "Charlie LTC layer with its per-texel error. E and F are integrated over the half vector "
         "(`sheen_charlie_moments`, `src/brdflut/charlie_ek.h`), the averages and the LTC's norms through the "
         "generic lobe path (`src/brdflut/generic_lobe.h`) from the BRDF alone; the checks use a third rule, a "
         "nested one over the half vector's polar angles, and the tests hold the two routes to each other."});
    std::vector<TableDefinition>& out = family.tables;
    out.push_back(make(Kind::moments, "sheen_charlie_moments",
                       "Charlie sheen albedo E, Fresnel moment F and E/(1 + E), Estevez-Kulla shadowing by default",
                       {tables::cos_theta_axis(32), charlie_alpha_axis(32)},
                       {"E: integral of f cos(theta_i) dw_i", "F: integral of f (1 - v.h)^5 cos(theta_i) dw_i",
                        "E / (1 + E) (HDRP's encoding of E)"}));
    out.back().checks = {half_vector_check(0), half_vector_check(1), half_vector_check(2)};
    out.push_back(make(Kind::average, "sheen_charlie_moments_avg",
                       "Charlie sheen average albedo and Fresnel moment: 2 * integral of E(mu) mu dmu, and of F",
                       {charlie_alpha_axis(16)},
                       {"E_avg: 2 * integral of E(mu) mu dmu", "F_avg: 2 * integral of F(mu) mu dmu"}));
    out.back().checks = {average_check(0), average_check(1)};
    out.push_back(make(Kind::fabric, "fabric_lambert_albedo",
                       "HDRP fabric Lambert albedo: (1 - alpha/2)/pi integrated over the hemisphere (1 - alpha/2)",
                       {tables::cos_theta_axis(32), charlie_alpha_axis(32)},
                       {"E: integral of (1 - alpha/2)/pi cos(theta_i) dw_i"}));
    out.back().checks = {fabric_check()};
    for (TableDefinition& d : hdrp_charlie_ltc_layer()) out.push_back(std::move(d));
    for (TableDefinition& d : heitz_charlie_ltc_layer()) out.push_back(std::move(d));
}

}  // namespace brdflut
