// Beckmann split-sum and albedo tables, computed through the generic lobe
// path (generic_lobe.h) from the BRDF alone: no Beckmann-specific
// quadrature. The checks at the end use an independent rule over the half
// vector's slope.
//
// Beckmann and Spizzichino 1963; Walter et al. 2007; Heitz 2014 (beckmann.h).
#include <cmath>
#include <memory>
#include <sstream>

#include "brdflut/beckmann.h"
#include "brdflut/error.h"
#include "brdflut/generic_lobe.h"
#include "brdflut/random.h"
#include "brdflut/verify.h"
#include "tables/checks.h"
#include "tables/ltc_tables.h"
#include "tables/registry.h"
#include "tables/shared_results.h"

namespace brdflut {
namespace beckmann_family {  // this family's own names, apart from the other families' in a unity build
namespace {

// Absolute tolerance of the quadrature at standard quality: with an honest
// estimate below it and float rounding (at most 6e-8 below 1), every stored
// value is within 1e-7 of the exact integral.
constexpr double kBeckmannTableTolerance = 1e-8;
constexpr tables::Tolerances kTolerances = tables::quadrature_tolerances(kBeckmannTableTolerance);

// Alphas in (0, kMinAlpha) are computed at kMinAlpha. The lobe then lies
// within 1.2e-5 rad of the mirror direction and, for view cosines >= 1/256,
// the integrals differ from their values at the smaller alpha by
// O(kMinAlpha^2) (1e-11); the generic path's direction rounding
// (generic_lobe.h) keeps its error estimate below 3e-8 there. At exactly grazing view (mu = 0, only
// with end-point placement) the 1e-7 target holds for alpha >= 5e-5; below,
// the stored error bound says how far it is. alpha = 0 is the mirror limit.
constexpr double kMinAlpha = 2e-6;

const char* kQuadratureRule =
    "generic lobe path (generic_lobe.h): wi in polar coordinates (theta, psi) about the mirror direction; "
    "theta split at the horizon clip, at the width w = 2 alpha, at aspect w and at the far end of the "
    "clipped band, adaptive Gauss-Kronrod (10,21) in theta^2 from the peak to aspect w and in ln(theta) "
    "beyond (from panels of at most 2 units), ends at the horizon clip flattened by polynomial maps; "
    "nested with the azimuth clipped "
    "analytically to the upper hemisphere and integrated in psi' with tan(psi) = rho tan(psi'), "
    "rho = clamp(aspect w / theta, aspect, 1), aspect = min(1, mu_o + alpha) (adaptive Gauss-Kronrod "
    "(10,21)); E_avg: adaptive Gauss-Kronrod (10,21) in mu = b u^2 below b = 2 alpha and in ln(mu) above; "
    "alpha below 2e-6 computed at 2e-6; error per value: QUADPACK estimate plus the integrated inner "
    "estimates plus a bound on the rounding of the directions";
const char* kMcSampler = "Beckmann normals from D cos(theta_h), reflected";

nlohmann::json beckmann_model(Visibility vis) {
    nlohmann::json m = {{"brdf", "Beckmann microfacet, single scattering"},
            {"distribution", "beckmann"},
            {"ndf", "D = exp(-tan^2(theta_h) / alpha^2) / (pi alpha^2 cos^4(theta_h))"},
            {"lambda", "(erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)), a = 1 / (alpha tan(theta))"},
            {"visibility", to_string(vis)},
            {"fresnel", "1"},
            {"roughness",
             "alpha = perceptual_roughness^2; alpha = sqrt(2) times the RMS slope along one axis "
             "(the RMS of the slope's length)"}};
    if (vis == Visibility::schlick_smith)
        m["schlick_smith"] = "G1 = mu / (mu (1 - k) + k), k = alpha sqrt(2/pi) (Schlick 1994)";
    return m;
}

AxisSpec beckmann_alpha_axis() {
    AxisSpec a = tables::alpha_axis();
    a.meaning = "Beckmann alpha (sqrt(2) RMS slope per axis); the square warp makes the rows linear in "
                "perceptual roughness sqrt(alpha)";
    return a;
}

enum class Kind { dfg, albedo, albedo_avg };

// {A, B} at one texel: quadrature through the generic path.
Estimate<2> split_sum(double mu, double alpha, Visibility vis, double abs_tol) {
    Estimate<2> out;
    if (!(alpha > 0.0)) {  // mirror limit
        const double fc = schlick_weight(std::clamp(mu, 0.0, 1.0));
        out.value = {1.0 - fc, fc};
        return out;
    }
    const BeckmannLobe lobe(std::max(alpha, kMinAlpha), vis);
    GenericOptions opt;
    opt.abs_tol = abs_tol;
    return generic_moments<2>(lobe, mu, kSplitSumWeights, opt);
}

Estimate<1> albedo_average(double alpha, Visibility vis, double abs_tol) {
    Estimate<1> out;
    if (!(alpha > 0.0)) {
        out.value[0] = 1.0;
        return out;
    }
    const BeckmannLobe lobe(std::max(alpha, kMinAlpha), vis);
    GenericOptions opt;
    opt.abs_tol = abs_tol;
    return generic_albedo_average(lobe, opt);
}

// Split sums computed in this process, shared by the tables of one run:
// beckmann_albedo is A + B of beckmann_dfg's texels.
tables::SharedResults<4, Estimate<2>>& split_sum_cache() {
    static tables::SharedResults<4, Estimate<2>> cache(1 << 18);
    return cache;
}

class BeckmannEvaluator final : public TexelEvaluator {
public:
    BeckmannEvaluator(Kind kind, Visibility vis, const TableSettings& s)
        : kind_(kind), vis_(vis), method_(s.method), samples_(s.samples), seed_(s.seed),
          abs_tol_(kTolerances.at(s.quality)) {}

    TexelValue evaluate(const double* c, std::uint64_t texel) const override {
        TexelValue out;
        const bool mc = method_ == Method::monte_carlo;
        const std::uint64_t seed = mix_seed(seed_, texel);
        if (kind_ == Kind::albedo_avg) {
            const double alpha = c[0];
            Estimate<1> e;
            if (!mc) {
                e = albedo_average(alpha, vis_, abs_tol_);
            } else if (alpha > 0.0) {
                e = generic_moment_average_mc<1>(BeckmannLobe(std::max(alpha, kMinAlpha), vis_), {kWeightOne},
                                                 samples_, seed);
            } else {
                e.value[0] = 1.0;
            }
            out.value[0] = e.value[0];
            out.error[0] = mc ? tables::kMcErrorSigmas * e.error[0] : e.error[0];
            out.evaluations = e.evaluations;
            return out;
        }
        const double mu = c[0], alpha = c[1];
        bool computed = true;
        Estimate<2> e;
        if (!mc) {
            e = split_sum_cache().get({tables::key_bits(mu), tables::key_bits(alpha), tables::key_bits(abs_tol_),
                                       tables::key_enum(vis_)},
                                      [&] { return split_sum(mu, alpha, vis_, abs_tol_); }, &computed);
        } else if (alpha > 0.0) {
            e = generic_moments_mc<2>(BeckmannLobe(std::max(alpha, kMinAlpha), vis_), mu, kSplitSumWeights,
                                      samples_, seed);
        } else {
            e = split_sum(mu, alpha, vis_, abs_tol_);
        }
        if (computed) out.evaluations = e.evaluations;
        const double scale = mc ? tables::kMcErrorSigmas : 1.0;
        if (kind_ == Kind::dfg) {
            out.value = {e.value[0], e.value[1], 0.0, 0.0};
            out.error = {scale * e.error[0], scale * e.error[1], 0.0, 0.0};
        } else {
            out.value[0] = e.value[0] + e.value[1];
            out.error[0] = scale * (e.error[0] + e.error[1]);
        }
        return out;
    }

private:
    Kind kind_;
    Visibility vis_;
    Method method_;
    long long samples_;
    std::uint64_t seed_;
    double abs_tol_;
};

TableDefinition make(Kind kind, std::string id, std::string description, std::vector<AxisSpec> axes,
                     std::vector<std::string> channels) {
    TableDefinition d;
    d.id = std::move(id);
    d.description = std::move(description);
    d.axes = std::move(axes);
    d.channels = std::move(channels);
    d.options = {tables::visibility_option()};
    d.supports_monte_carlo = true;
    // A generic-path integral costs about a millisecond a texel (the average
    // much more): too much for identify's coarse search (see catalogue.h);
    // `compare --as` still checks a file against these tables.
    d.searched_by_identify = false;
    d.prepare = [kind](const TableSettings& s) {
        const Visibility vis = visibility_from_string(tables::param(s, "visibility"));
        PreparedTable p;
        p.evaluator = std::make_unique<BeckmannEvaluator>(kind, vis, s);
        p.model = beckmann_model(vis);
        p.method = s.method == Method::monte_carlo
                       ? tables::monte_carlo_method(kMcSampler, s)
                       : tables::quadrature_method(kQuadratureRule, kTolerances.at(s.quality));
        return p;
    };
    return d;
}

// ---------------------------------------------------------------------------
// Independent checks.
//
// The split sums by a fixed product Gauss-Legendre rule over the slope of
// the half vector, a parametrization the generic path does not use: with
// slope s = tan(theta_h) (cos(phi), sin(phi)) = alpha rho (cos(phi), sin(phi)),
// D cos(theta_h) dw_h = exp(-rho^2) rho drho dphi / pi, and
//
//   integral of f w cos(theta_i) dw_i = integral of G2 (wo.h) w(wo.h) / (mu_o cos(theta_h)) D cos(theta_h) dw_h
//
// over the half vectors whose reflection stays above the horizon. rho runs
// to 6.5 (the weight is below 5e-19 beyond), split where the reflection
// starts to clip (the phi integral has a (rho - rho_a)^(3/2) kink there);
// phi runs over [0, phi_max]
// exactly. Agrees with the generic path to 1e-14 for alpha = 0.6 and
// mu_o >= 0.01 (7e-10 at mu_o = 1e-4, where the weight of E_avg is 2e-4).
std::array<double, 2> slope_space_split_sum(double mu_o, double alpha, Visibility vis) {
    const Beckmann model{alpha};
    const double sin_o = std::sqrt((1.0 - mu_o) * (1.0 + mu_o));
    const GaussLegendre& gl = gauss_legendre(20);
    constexpr int kPanels = 8;
    auto phi_integral = [&](double rho) -> std::array<double, 2> {
        const double t = alpha * rho;
        const double c = 1.0 / std::sqrt(1.0 + t * t), s = t * c;
        // mu_i = 2 (wo.h) c - mu_o with wo.h = sin_o s cos(phi) + mu_o c.
        double phi_max = kPi;
        if (sin_o * s > 0.0) {
            const double cos_max = (mu_o / (2.0 * c) - mu_o * c) / (sin_o * s);
            if (cos_max >= 1.0) return {0.0, 0.0};
            if (cos_max > -1.0) phi_max = std::acos(cos_max);
        } else if (2.0 * c * c - 1.0 <= 0.0) {
            return {0.0, 0.0};
        }
        std::array<double, 2> sum{};
        for (int p = 0; p < kPanels; ++p) {
            const double a = phi_max * p / kPanels, b = phi_max * (p + 1) / kPanels;
            const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
            for (std::size_t j = 0; j < gl.x.size(); ++j) {
                const double phi = mid + half * gl.x[j];
                const double o_h = sin_o * s * std::cos(phi) + mu_o * c;
                const double mu_i = 2.0 * o_h * c - mu_o;
                if (!(mu_i > 0.0) || !(o_h > 0.0)) continue;
                const double v = model.G2(mu_o, mu_i, vis) * o_h / (mu_o * c) * half * gl.w[j];
                const double fc = schlick_weight(o_h);
                sum[0] += v * (1.0 - fc);
                sum[1] += v * fc;
            }
        }
        return sum;
    };
    // rho where clipping starts (t_a = mu_o / (1 + sin_o)) and where it
    // leaves nothing (t_b = (1 + sin_o) / mu_o), within the end of the range.
    const double rho_end = 6.5;
    const double rho_a = std::min(mu_o / (1.0 + sin_o) / alpha, rho_end);
    const double rho_b = std::min((1.0 + sin_o) / mu_o / alpha, rho_end);
    const bool closes = rho_b < rho_end;
    std::array<double, 2> total{};
    // Full rings on [0, rho_a] in rho; the clipped band on [rho_a, rho_b]
    // in rho = rho_a exp(L m(v)), L = ln(rho_b / rho_a): the clip angle
    // changes on the scale of rho_a itself (small at grazing view), and m
    // flattens the kinks at rho_a (v^2) and, where the band closes before
    // the end of the range, at rho_b (v^2 (3 - 2 v)).
    const double L = rho_a > 0.0 ? std::log(rho_b / rho_a) : 0.0;
    auto piece = [&](bool band) {
        if (!(band ? L > 0.0 : rho_a > 0.0)) return;
        for (int p = 0; p < kPanels; ++p) {
            const double a = double(p) / kPanels, b = double(p + 1) / kPanels;
            const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
            for (std::size_t j = 0; j < gl.x.size(); ++j) {
                const double u = mid + half * gl.x[j];
                const double m = closes ? u * u * (3.0 - 2.0 * u) : u * u;
                const double dm = closes ? 6.0 * u * (1.0 - u) : 2.0 * u;
                const double rho = band ? rho_a * std::exp(L * m) : rho_a * u;
                const double jac = band ? rho * L * dm : rho_a;
                const std::array<double, 2> f = phi_integral(rho);
                // Twice phi in [0, pi] over 2 pi: 1 / pi.
                const double w = std::exp(-rho * rho) * rho * kInvPi * jac * half * gl.w[j];
                total[0] += 2.0 * f[0] * w;
                total[1] += 2.0 * f[1] * w;
            }
        }
    };
    piece(false);
    piece(true);
    return total;
}

using CheckResult = std::pair<double, std::string>;

std::string at_point(double mu, double alpha) {
    std::ostringstream s;
    s.precision(6);
    s << "at (mu = " << mu << ", alpha = " << alpha << ")";
    return s.str();
}

// The largest |table - expected| over (mu, alpha) points; channel -1: A + B.
template <class Expected>
CheckResult worst(const TexelEvaluator& e, const std::vector<std::array<double, 2>>& pts, int channel,
                  Expected expected) {
    CheckResult r{0.0, ""};
    for (const auto& p : pts) {
        const TexelValue v = e.evaluate(p.data(), 0);
        const double got = channel < 0 ? v.value[0] + v.value[1] : v.value[static_cast<std::size_t>(channel)];
        const double err = std::abs(got - expected(p));
        if (err > r.first || !std::isfinite(err)) r = {err, at_point(p[0], p[1])};
    }
    return r;
}

std::vector<std::array<double, 2>> mirror_points() {
    std::vector<std::array<double, 2>> pts;
    for (double mu : {0.1, 0.3, 0.6, 1.0}) pts.push_back({mu, kMinAlpha});
    return pts;
}

std::vector<std::array<double, 2>> slope_points() {
    std::vector<std::array<double, 2>> pts;
    for (double alpha : {0.1, 0.4, 1.0})
        for (double mu : {0.05, 0.35, 1.0}) pts.push_back({mu, alpha});
    return pts;
}

// The checks evaluate the table at its default settings.
constexpr Visibility kCheckVisibility = Visibility::height_correlated;

std::vector<ClosedFormCheck> beckmann_checks(const std::string& table_id) {
    if (table_id == "beckmann_dfg")
        return {
            {"B at alpha = 2e-6 vs the mirror limit (1 - mu)^5", 1e-6,
             [](const TexelEvaluator& e) {
                 return worst(e, mirror_points(), 1, [](const auto& p) { return schlick_weight(p[0]); });
             }},
            {"A + B at alpha = 2e-6 vs the mirror limit 1", 1e-6,
             [](const TexelEvaluator& e) { return worst(e, mirror_points(), -1, [](const auto&) { return 1.0; }); }},
            {"A vs a product Gauss-Legendre rule over the half vector's slope", 1e-8,
             [](const TexelEvaluator& e) {
                 return worst(e, slope_points(), 0,
                              [](const auto& p) { return slope_space_split_sum(p[0], p[1], kCheckVisibility)[0]; });
             }},
            {"B vs a product Gauss-Legendre rule over the half vector's slope", 1e-8,
             [](const TexelEvaluator& e) {
                 return worst(e, slope_points(), 1,
                              [](const auto& p) { return slope_space_split_sum(p[0], p[1], kCheckVisibility)[1]; });
             }},
        };
    if (table_id == "beckmann_albedo")
        return {
            {"E at alpha = 2e-6 vs the mirror limit 1", 1e-6,
             [](const TexelEvaluator& e) { return worst(e, mirror_points(), 0, [](const auto&) { return 1.0; }); }},
            {"E vs a product Gauss-Legendre rule over the half vector's slope", 1e-8,
             [](const TexelEvaluator& e) {
                 return worst(e, slope_points(), 0, [](const auto& p) {
                     const auto ab = slope_space_split_sum(p[0], p[1], kCheckVisibility);
                     return ab[0] + ab[1];
                 });
             }},
        };
    if (table_id == "beckmann_albedo_avg")
        return {
            {"E_avg at alpha = 2e-6 vs the mirror limit 1", 1e-6,
             [](const TexelEvaluator& e) {
                 const double alpha = kMinAlpha;
                 const double err = std::abs(e.evaluate(&alpha, 0).value[0] - 1.0);
                 return CheckResult{err, "at alpha = 2e-6"};
             }},
            {"E_avg vs 2 * integral of E(mu) mu dmu, Gauss-Legendre in mu = u^4 over the slope rule", 1e-8,
             [](const TexelEvaluator& e) {
                 // E(mu) ~ 1 + c mu ln(mu) near 0: in mu = u^4 the integrand is
                 // u^11 ln(u) at worst, which Gauss-Legendre resolves.
                 const GaussLegendre& gl = gauss_legendre(32);
                 const double alpha = 0.6;
                 double sum = 0.0;
                 for (std::size_t j = 0; j < gl.x.size(); ++j) {
                     const double u = 0.5 * (1.0 + gl.x[j]);
                     const double u2 = u * u, mu = u2 * u2;
                     const auto ab = slope_space_split_sum(mu, alpha, kCheckVisibility);
                     sum += 0.5 * gl.w[j] * 2.0 * mu * 4.0 * u2 * u * (ab[0] + ab[1]);
                 }
                 return CheckResult{std::abs(e.evaluate(&alpha, 0).value[0] - sum), "at alpha = 0.6"};
             }},
        };
    return {};
}

// ---------------------------------------------------------------------------
// HDRP's Cook-Torrance LTC layer (the AxF material's): the Beckmann lobe with
// the V-cavity G, fitted through the generic path (LtcLobe's generic kind)
// on HDRP's grid and in its packing, as hdrp_ltc_ggx: 64x64, roughness
// r = i/63 with alpha = max(r^2, 0.002) (BRDF_CookTorrance.Eval's clamp),
// rows cos(theta) = 1 - (j/63)^2.

constexpr double kCookTorranceMinAlpha = 0.002;
const char* kCookTorranceSource =
    "Unity-Technologies/Graphics com.unity.render-pipelines.high-definition Runtime/Material/LTCAreaLight/"
    "BRDF/BRDF_CookTorrance.cs @85949ee7c210cef38bebb29810f2f7cad75c28f5 (the lobe; HDRP's own fit on this "
    "grid: Generated/LtcData.BRDF_CookTorrance.cs), LTCAreaLight.hlsl (the packing)";

std::vector<TableDefinition> cook_torrance_ltc_layer() {
    LtcLayer layer;
    layer.name = "cook_torrance";
    layer.matrix_description =
        "HDRP LTC Cook-Torrance matrix (Beckmann, V-cavity G): the inverse divided by its m22 (alpha >= 0.002)";
    layer.error_description = "Per-texel error of the Cook-Torrance LTC fit (the texels of hdrp_ltc_cook_torrance)";
    layer.roughness_meaning = "perceptual roughness r; Beckmann alpha = max(r^2, 0.002)";
    layer.model = [](const std::map<std::string, std::string>&) {
        nlohmann::json m = beckmann_model(Visibility::height_correlated);
        m["brdf"] = "Cook-Torrance: Beckmann microfacet with the V-cavity shadowing-masking, single scattering, "
                    "fitted by a linearly transformed cosine";
        m["visibility"] = "v_cavity: G = min(1, 2 (n.h) min(n.v, n.l) / (v.h)) (Cook and Torrance 1982)";
        m.erase("lambda");
        m["roughness"] = "alpha = max(perceptual_roughness^2, 0.002) (the clamp of HDRP's BRDF_CookTorrance)";
        return m;
    };
    layer.engine_source = kCookTorranceSource;
    layer.norms_rule = "n0 by the generic lobe path (as beckmann_albedo, to 1e-8)";
    const std::uint64_t key = ltc_lobe_key("beckmann_v_cavity");
    layer.lobe = [key](double r, double mu, const std::map<std::string, std::string>&) {
        const double alpha = std::max(alpha_from_perceptual(r), kCookTorranceMinAlpha);
        return LtcLobe(std::make_shared<const BeckmannLobe>(BeckmannLobe::v_cavity(alpha)), mu, alpha, key,
                       kBeckmannTableTolerance);
    };
    return hdrp_ltc_layer(layer);
}

}  // namespace
}  // namespace beckmann_family

void register_beckmann_family(FamilyEntries& family) {
    using namespace beckmann_family;
    family.families.push_back(
        {"", "Beckmann microfacet",
        "The Beckmann distribution D = exp(-tan^2(theta_h)/alpha^2)/(pi alpha^2 cos^4(theta_h)) (alpha = "
        "sqrt(2) times the RMS slope along one axis) with the exact Smith Lambda (erf form), "
        "height-correlated or separable, or Schlick's G1 with k = alpha sqrt(2/pi) (`--visibility`), F = "
        "1: split sums, albedo and average albedo, as Mitsuba 3, the MDL SDK, appleseed and HDRP's AxF "
        "use the model. HDRP's Cook-Torrance LTC layer (Beckmann D with the V-cavity G of Cook and "
        "Torrance 1982, alpha >= 0.002) is fitted in HDRP's grid and packing, with its per-texel error "
        "table. Every table is built through the generic lobe path from the BRDF alone "
        "(`src/brdflut/generic_lobe.h`): no Beckmann-specific quadrature."});
    std::vector<TableDefinition>& out = family.tables;
    out.push_back(make(Kind::dfg, "beckmann_dfg",
                       "Beckmann split-sum terms: specular = F0 * A + B (F = 1 inside the integral)",
                       {tables::cos_theta_axis(), beckmann_alpha_axis()},
                       {"A: integral of f (1 - (1 - v.h)^5) cos(theta_i) dw_i",
                        "B: integral of f (1 - v.h)^5 cos(theta_i) dw_i"}));
    out.push_back(make(Kind::albedo, "beckmann_albedo", "Beckmann directional albedo E(mu, alpha) = A + B",
                       {tables::cos_theta_axis(), beckmann_alpha_axis()},
                       {"E: integral of f cos(theta_i) dw_i with F = 1"}));
    out.push_back(make(Kind::albedo_avg, "beckmann_albedo_avg",
                       "Beckmann average albedo E_avg(alpha) = 2 * integral of E(mu) mu dmu",
                       {beckmann_alpha_axis()}, {"E_avg: 2 * integral of E(mu) mu dmu"}));
    for (TableDefinition& d : out)
        if (d.checks.empty()) d.checks = beckmann_checks(d.id);
    for (TableDefinition& d : cook_torrance_ltc_layer()) out.push_back(std::move(d));

    const std::pair<std::string, std::string> hc{"visibility", "height_correlated"},
        sep{"visibility", "separable"};
    family.furnace_models.insert(
        family.furnace_models.end(),
        {{"beckmann", "Beckmann single scattering, height-correlated Smith G2", "beckmann_albedo",
          "beckmann_albedo_avg", {hc}, false, false, 0},
         {"beckmann_separable", "Beckmann single scattering, separable Smith G1 G1", "beckmann_albedo",
          "beckmann_albedo_avg", {sep}, false, false, 0}});
}

}  // namespace brdflut
