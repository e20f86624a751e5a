// LTC area-light tables fitted to the GGX, Charlie sheen and EON lobes, in the
// layouts engines load.
//
// Heitz, Dupuy, Hill and Neubelt 2016, "Real-Time Polygonal-Light Shading
//   with Linearly Transformed Cosines" (ltc_1, ltc_2: selfshadow/ltc_code
//   fit/fitLTC.cpp packTab, loaded by three.js, Blender EEVEE, Godot)
// Unity HDRP LTCAreaLight.hlsl (LTCSampleMatrix: the transposed inverse
//   divided by its m22, as _m00_m02_m11_m20 of the transpose)
#include <algorithm>
#include <array>
#include <cstdio>
#include <memory>
#include <vector>

#include "brdflut/error.h"
#include "brdflut/ggx_integrals.h"
#include "brdflut/ltc.h"
#include "brdflut/ltc_fit.h"
#include "brdflut/ltc_report.h"
#include "check/ltc_checks.h"
#include "tables/checks.h"
#include "tables/ltc_tables.h"
#include "tables/registry.h"
#include "tables/shared_results.h"

namespace brdflut {
namespace {

enum class Layout {
    heitz_matrix,  // ltc_1: (m00, m02, m20, m22) of M^-1 / M^-1[1][1], glm m[col][row]
    heitz_norms,   // ltc_2: (n0, n1, 0, sphere form factor)
    norm,          // n0 alone (the lobes without a Fresnel moment)
    hdrp_matrix,   // (m00, m20, m11, m02) of M^-1 / M^-1[2][2], HLSL _mRC
    report,        // ltc_ggx_error and the other lobes' _error: the per-texel error figures
};

// The figures each texel's fit leaves for the table-wide summary, one slot
// per texel (written only by that texel's evaluation). The matrix tables
// also record each texel's error report (relative L3 error, integrated-light
// error over the bank) for the maxima in their metadata.
struct FitFigures {
    std::vector<double> objective, below_horizon, relative_l3, light_max;
};

// A texel's fit and its error report (the exact light at the quality's
// tolerance), shared by the tables of one run that fit the same lobe:
// ltc_1, ltc_ggx_error and hdrp_ltc_ggx (where its alpha floor does not
// apply), each lobe's matrix table and its _error table. Keyed by the lobe
// and the fit's options; 65,536 texels at most (~15 MB).
struct TexelFit {
    LtcFit fit;
    LtcTexelReport report;
};
tables::SharedResults<7, TexelFit>& texel_fit_cache() {
    static tables::SharedResults<7, TexelFit> cache(1 << 16);
    return cache;
}
TexelFit texel_fit(const LtcLobe& lobe, const LtcFitOptions& opt) {
    using tables::key_bits;
    return texel_fit_cache().get(
        {tables::key_enum(lobe.kind), tables::key_enum(lobe.vis), key_bits(lobe.mu_o), key_bits(lobe.param),
         static_cast<std::uint64_t>(opt.radial_nodes), static_cast<std::uint64_t>(opt.azimuth_nodes),
         key_bits(opt.light_tolerance)},
        [&] {
            TexelFit t;
            t.fit = fit_ltc(lobe, opt);
            t.report = ltc_texel_report(lobe, t.fit.minv.matrix(), t.fit.n0, opt);
            return t;
        });
}

bool is_matrix(Layout l) { return l == Layout::heitz_matrix || l == Layout::hdrp_matrix; }
// The norm tables hold exact integrals and the sphere form factor, not the
// fit: they do not fit.
bool fits(Layout l) { return l != Layout::heitz_norms && l != Layout::norm; }

// The lobe of a texel: the roughness coordinate r mapped to the lobe's
// parameter (GGX and Charlie alpha = r^2, HDRP's GGX at alpha >= 1e-3; EON
// sigma = r), clamped by LtcLobe.
LtcLobe texel_lobe(LtcLobeKind kind, Layout layout, double r, double mu, Visibility vis) {
    if (kind == LtcLobeKind::eon) return LtcLobe(kind, mu, r, vis);
    const double alpha = std::max(alpha_from_perceptual(r), layout == Layout::hdrp_matrix ? 1e-3 : 0.0);
    return LtcLobe(kind, mu, alpha, vis);
}

class LtcEvaluator final : public TexelEvaluator {
public:
    LtcEvaluator(LtcLobeKind kind, Layout layout, Visibility vis, const LtcFitOptions& opt,
                 std::shared_ptr<FitFigures> figures)
        : kind_(kind), layout_(layout), vis_(vis), opt_(opt), figures_(std::move(figures)) {}

    // coords: (roughness, cos_theta) in the definition's order.
    TexelValue evaluate(const double* c, std::uint64_t texel) const override {
        const double r = c[0], mu = c[1];
        const LtcLobe lobe = texel_lobe(kind_, layout_, r, mu, vis_);
        TexelValue out;
        if (!fits(layout_)) {
            const LtcNorms n = ltc_norms(lobe);
            if (layout_ == Layout::norm) {
                out.value[0] = n.n0;
                out.error[0] = n.n0_error;
                return out;
            }
            // The sphere table's own axes are the texel's normalized
            // coordinates: z = 2 u_x - 1 = 2 r - 1, len = u_y = sqrt(1 - mu).
            out.value = {n.n0, n.n1, 0.0, sphere_horizon_form_factor(2.0 * r - 1.0, safe_sqrt(1.0 - mu))};
            out.error = {n.n0_error, n.n1_error, 0.0, 0.0};
            return out;
        }
        const TexelFit tf = texel_fit(lobe, opt_);
        const LtcFit& fit = tf.fit;
        if (figures_ && texel < figures_->objective.size()) {
            figures_->objective[texel] = fit.objective;
            figures_->below_horizon[texel] = fit.below_horizon;
            if (is_matrix(layout_)) {
                figures_->relative_l3[texel] = tf.report.relative_l3;
                figures_->light_max[texel] = tf.report.light_max;
            }
        }
        const LtcInverse& m = fit.minv;
        switch (layout_) {
            case Layout::heitz_matrix:
                out.value = {m.a, m.c, m.b, m.d};
                break;
            case Layout::hdrp_matrix:
                out.value = {m.a / m.d, m.c / m.d, 1.0 / m.d, m.b / m.d};
                break;
            case Layout::report: {
                const LtcTexelReport& rep = tf.report;
                out.value = {rep.relative_l3, rep.below_horizon, rep.light_max, rep.light_mean};
                break;
            }
            case Layout::heitz_norms:
            case Layout::norm:
                break;
        }
        return out;
    }

private:
    LtcLobeKind kind_;
    Layout layout_;
    Visibility vis_;
    LtcFitOptions opt_;
    std::shared_ptr<FitFigures> figures_;
};

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

std::string number_text(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", v);
    return b;
}

std::string rule(LtcLobeKind kind) {
    const char* norms = kind == LtcLobeKind::ggx             ? "n0, n1 by the ggx_dfg quadrature"
                        : kind == LtcLobeKind::charlie_sheen ? "n0 by the sheen_charlie_albedo quadrature"
                                                             : "n0 by the eon_albedo quadrature";
    return std::string(
               "per texel: Nelder-Mead in double on all four parameters of a y-symmetric LTC from an initial "
               "guess computed from the texel's own lobe (its peak and half-maximum widths), restarted until it "
               "stops improving; objective int |p - D|^3 / (p + D) dw / int p^2 dw (Heitz's error measure)") +
           (ltc_mass_weight(kind) == 0.0
                ? std::string()
                : " + " + number_text(ltc_mass_weight(kind)) +
                      " int (p - D)^2 / (p + D) dw (the triangular discrimination, which bounds every polygon's "
                      "light error)") +
           ", by Gauss-Legendre product quadrature in stereographic coordinates about the lobe's " +
           (kind == LtcLobeKind::ggx ? "peak" : "normal") +
           ", split at the horizon; + " + number_text(kLtcFitLightWeight) + " max(0, 1 - mu / " +
           number_text(kLtcFitLightMu) + ")^2 times the sum of squared differences of the "
           "LTC's light (closed form) and the lobe's (exact polygon quadrature to light_tolerance) over the "
           "eight lights of ltc_fit_light_bank; " + norms;
}

const char* kNormRule = "no fit: exact integrals (n0, n1) and the closed-form sphere form factor";

AxisSpec roughness_axis(LtcLobeKind kind) {
    if (kind == LtcLobeKind::eon)
        return {Axis{"sigma", 0.0, 1.0, 64, Placement::endpoints, Warp::linear}, 0.0, 1.0,
                "EON (Fujii/OpenPBR) roughness sigma in [0, 1]"};
    return {Axis{"roughness", 0.0, 1.0, 64, Placement::endpoints, Warp::linear}, 0.0, 1.0,
            kind == LtcLobeKind::ggx ? "perceptual roughness r; GGX alpha = max(r^2, 1e-5)"
                                     : "perceptual roughness r; Charlie alpha = max(r^2, 0.01)",
            "", "alpha"};
}

// Rows uniform in sqrt(1 - cos theta): cos_theta from 1 down to 0, squared
// warp (mu = 1 - u^2), end points; the lobe is evaluated at mu >= cos(1.57).
AxisSpec view_axis() {
    return {Axis{"cos_theta", 1.0, 0.0, 64, Placement::endpoints, Warp::square}, 0.0, 1.0,
            "cos(theta_o); rows at u = sqrt(1 - cos(theta_o)); the lobe is fitted at cos(theta_o) >= cos(1.57)"};
}

const char* kFrame = "normal +z, view (sin theta, 0, cos theta); M^-1 acts on column vectors in this frame";

nlohmann::json ltc_model(LtcLobeKind kind, Visibility vis, const std::string& layout) {
    if (kind == LtcLobeKind::charlie_sheen) {
        nlohmann::json m = tables::charlie_sheen_model();
        m["brdf"] = "Charlie sheen (Estevez and Kulla 2017), no Fresnel, fitted by a linearly transformed cosine";
        m["roughness"] = "alpha = max(perceptual_roughness^2, 0.01)";
        m["layout"] = layout;
        m["frame"] = kFrame;
        return m;
    }
    if (kind == LtcLobeKind::eon)
        return {{"brdf", "EON rough diffuse at rho = 1 (Portsmouth et al. 2025; FON plus the multiple-scattering "
                         "lobe with FON's exact albedo, as eon_albedo), fitted by a linearly transformed cosine"},
                {"roughness", "sigma in [0, 1]; sigma = 0 is Lambert"},
                {"layout", layout},
                {"frame", kFrame}};
    return {{"brdf", "GGX microfacet, single scattering, fitted by a linearly transformed cosine"},
            {"distribution", "ggx"},
            {"visibility", to_string(vis)},
            {"fresnel", "1 (n1 carries the Schlick moment)"},
            {"roughness", layout == "hdrp" ? "alpha = max(perceptual_roughness^2, 1e-3)"
                                           : "alpha = max(perceptual_roughness^2, 1e-5)"},
            {"layout", layout},
            {"frame", kFrame}};
}

// The error report of the lobe's tables.
std::string report_table(LtcLobeKind kind) {
    return kind == LtcLobeKind::ggx ? "ltc_ggx_error" : kind == LtcLobeKind::eon ? "ltc_eon_error" : "ltc_sheen_charlie_error";
}

int quality_level(Quality q) { return q == Quality::draft ? 0 : q == Quality::reference ? 2 : 1; }

struct Entry {
    LtcLobeKind lobe;
    Layout layout;
    std::string id, preset, description, layout_text;
    std::vector<std::string> channels;
};

// The stored inverse matrix by rows (TableDefinition::shader_matrix), as the
// evaluator packs it: Heitz (a, c, b, d) of [[a, 0, b], [0, 1, 0], [c, 0, d]];
// HDRP (a, c, 1, b) / d.
const std::array<std::string, 9> kHeitzMatrix = {"R", "0", "B", "0", "1", "0", "G", "0", "A"};
const std::array<std::string, 9> kHdrpMatrix = {"R", "0", "A", "0", "B", "0", "G", "0", "1"};

TableDefinition make(const Entry& e) {
    TableDefinition d;
    d.id = e.id;
    d.description = e.description;
    d.axes = {roughness_axis(e.lobe), view_axis()};
    d.channels = e.channels;
    // The fitter's GGX lobe takes the two Smith forms (not Schlick's).
    if (e.lobe == LtcLobeKind::ggx) d.options = {tables::visibility_option({"height_correlated", "separable"})};
    d.preset = e.preset;
    d.searched_by_identify = false;  // a fit per texel: see catalogue.h
    if (is_matrix(e.layout)) {
        d.shader_result = "ltc_inverse";
        d.shader_matrix = e.layout == Layout::heitz_matrix ? kHeitzMatrix : kHdrpMatrix;
    }
    const LtcLobeKind kind = e.lobe;
    const Layout layout = e.layout;
    const std::string layout_text = e.layout_text;
    const std::string preset = e.preset;
    d.prepare = [kind, layout, layout_text, preset](const TableSettings& s) {
        if (s.method == Method::monte_carlo)
            throw Error("LTC tables are fitted by quadrature only; --method monte_carlo is not allowed");
        const Visibility vis = kind == LtcLobeKind::ggx ? visibility_from_string(tables::param(s, "visibility"))
                                                        : Visibility::height_correlated;
        const LtcFitOptions opt = ltc_fit_options(quality_level(s.quality));
        std::size_t texels = 1;
        for (const Axis& a : s.axes) texels *= static_cast<std::size_t>(a.count);
        auto figures = std::make_shared<FitFigures>();
        if (fits(layout)) {
            figures->objective.assign(texels, 0.0);
            figures->below_horizon.assign(texels, 0.0);
        }
        if (is_matrix(layout)) {
            figures->relative_l3.assign(texels, 0.0);
            figures->light_max.assign(texels, 0.0);
        }
        PreparedTable p;
        p.evaluator = std::make_unique<LtcEvaluator>(kind, layout, vis, opt, figures);
        p.model = ltc_model(kind, vis, layout == Layout::hdrp_matrix ? "hdrp" : layout_text);
        if (layout == Layout::hdrp_matrix) p.model["layout"] = layout_text;
        p.model["preset"] = preset;
        p.model["engine_source"] = layout == Layout::hdrp_matrix
                                       ? "Unity-Technologies/Graphics HDRP Runtime/Material/LTCAreaLight/LTCAreaLight.hlsl"
                                       : "selfshadow/ltc_code fit/fitLTC.cpp (packTab); three.js "
                                         "examples/jsm/lights/RectAreaLightTexturesLib.js";
        if (!fits(layout)) {
            p.method = {{"rule", kNormRule}};
            return p;
        }
        p.method = {{"rule", rule(kind)},
                    {"objective_nodes", {{"radial", opt.radial_nodes}, {"azimuth", opt.azimuth_nodes}}}};
        if (layout == Layout::report)
            p.method["lights"] = "the bank of ltc_light_bank: squares of 1 to 60 degrees in the peak, off "
                                 "the peak and at the horizon; exact light by adaptive Gauss-Kronrod over "
                                 "the polygon, each light to light_tolerance of n0";
        const std::string report_id = report_table(kind);
        p.finish = [figures, layout, opt, report_id](Table& t) {
            nlohmann::json fe;
            fe["objective_max"] = *std::max_element(figures->objective.begin(), figures->objective.end());
            fe["objective_median"] = median(figures->objective);
            fe["below_horizon_max"] =
                *std::max_element(figures->below_horizon.begin(), figures->below_horizon.end());
            if (is_matrix(layout)) {
                fe["relative_l3_max"] =
                    *std::max_element(figures->relative_l3.begin(), figures->relative_l3.end());
                fe["relative_l3_median"] = median(figures->relative_l3);
                fe["light_error_max"] = *std::max_element(figures->light_max.begin(), figures->light_max.end());
                fe["light_error_median"] = median(figures->light_max);
                fe["light_tolerance"] = opt.light_tolerance;
                fe["lights"] = "the bank of ltc_light_bank (as " + report_id + "); light errors are the largest "
                               "over the bank, as fractions of n0";
            }
            if (layout == Layout::report) {
                fe["light_tolerance"] = opt.light_tolerance;
                const char* names[4] = {"relative_l3", "below_horizon", "light_error_max", "light_error_mean"};
                for (int c = 0; c < 4; ++c) {
                    std::vector<double> v;
                    for (std::size_t k = 0; k < t.texel_count(); ++k) v.push_back(t.at(k, c));
                    fe[std::string(names[c]) + "_max"] = *std::max_element(v.begin(), v.end());
                    fe[std::string(names[c]) + "_median"] = median(v);
                }
            }
            t.method["fit_error"] = fe;
        };
        return p;
    };
    return d;
}

const std::vector<std::string> kReportChannels = {
    "relative L3 error of n0 D against f cos over the sphere", "LTC mass below the horizon (of 1)",
    "largest integrated-light error over the light bank, as a fraction of n0",
    "mean integrated-light error over the light bank, as a fraction of n0"};

const char* kHeitzShader = "shader mat3(vec3(R, 0, G), vec3(0, 1, 0), vec3(B, 0, A))";
const std::vector<std::string> kHeitzMatrixChannels = {"m00 of M^-1 / M^-1[1][1] (glm m[col][row])",
                                                        "m02 (column 0, row 2)", "m20 (column 2, row 0)", "m22"};

const std::vector<Entry>& entries() {
    static const std::vector<Entry> all = [] {
        std::vector<Entry> v;
        v.push_back({LtcLobeKind::ggx, Layout::heitz_matrix, "ltc_1", "ltc",
                     "Heitz LTC ltc_1: the inverse matrix of the GGX fit divided by its middle element",
                     std::string("Heitz ltc_1 (three.js LTC_MAT_1, EEVEE, Godot): ") + kHeitzShader,
                     kHeitzMatrixChannels});
        v.push_back({LtcLobeKind::ggx, Layout::heitz_norms, "ltc_2", "ltc",
                     "Heitz LTC ltc_2: norm, Fresnel moment and the horizon-clipped sphere form factor",
                     "Heitz ltc_2 (three.js LTC_MAT_2): specular = n0 F0 + n1 (1 - F0) times the LTC "
                     "integral; A on its own axes",
                     {"n0: integral of f cos(theta_i) dw_i (= ggx_albedo)",
                      "n1: integral of f (1 - v.h)^5 cos(theta_i) dw_i (= ggx_dfg B)", "unused: 0",
                      "sphere form factor clipped to the horizon at z = 2 u_x - 1 (cosine of the average "
                      "light direction), len = u_y (its length)"}});
        v.push_back({LtcLobeKind::ggx, Layout::report, "ltc_ggx_error", "ltc",
                     "Per-texel error of the GGX LTC fit (the texels of ltc_1 and ltc_2)",
                     "error report on the grid of ltc_1", kReportChannels});
        v.push_back({LtcLobeKind::charlie_sheen, Layout::heitz_matrix, "ltc_sheen_charlie", "ltc",
                     "LTC of the Charlie sheen lobe in ltc_1's layout: the inverse matrix divided by its middle "
                     "element",
                     std::string("ltc_1's layout (columns roughness, alpha = max(r^2, 0.01)): ") + kHeitzShader,
                     kHeitzMatrixChannels});
        v.push_back({LtcLobeKind::charlie_sheen, Layout::norm, "ltc_sheen_charlie_norm", "ltc",
                     "Norm n0 of the Charlie sheen lobe on the grid of ltc_sheen_charlie",
                     "ltc_sheen_charlie's grid: sheen = n0 times the LTC integral",
                     {"n0: integral of f cos(theta_i) dw_i (= sheen_charlie_albedo)"}});
        v.push_back({LtcLobeKind::charlie_sheen, Layout::report, "ltc_sheen_charlie_error", "ltc",
                     "Per-texel error of the Charlie sheen LTC fit (the texels of ltc_sheen_charlie)",
                     "error report on the grid of ltc_sheen_charlie", kReportChannels});
        v.push_back({LtcLobeKind::eon, Layout::heitz_matrix, "ltc_eon", "ltc",
                     "LTC of the EON rough diffuse lobe in ltc_1's layout: the inverse matrix divided by its "
                     "middle element",
                     std::string("ltc_1's layout (columns sigma): ") + kHeitzShader,
                     kHeitzMatrixChannels});
        v.push_back({LtcLobeKind::eon, Layout::norm, "ltc_eon_norm", "ltc",
                     "Norm n0 of the EON lobe on the grid of ltc_eon (1 up to the quadrature: EON conserves energy)",
                     "ltc_eon's grid: diffuse = rho n0 times the LTC integral",
                     {"n0: integral of f cos(theta_i) dw_i (= eon_albedo)"}});
        v.push_back({LtcLobeKind::eon, Layout::report, "ltc_eon_error", "ltc",
                     "Per-texel error of the EON LTC fit (the texels of ltc_eon)", "error report on the grid of ltc_eon",
                     kReportChannels});
        v.push_back({LtcLobeKind::ggx, Layout::hdrp_matrix, "hdrp_ltc_ggx", "hdrp_ltc",
                     "HDRP LTC GGX matrix: the inverse divided by its m22 (alpha >= 1e-3)",
                     "Unity HDRP LTCSampleMatrix: invM._m22 = 1, invM._m00_m02_m11_m20 = RGBA of the "
                     "transposed inverse",
                     {"m00 of M^-1 / M^-1[2][2] (row 0, column 0)", "m20 (row 2, column 0)",
                      "m11 (row 1, column 1)", "m02 (row 0, column 2)"}});
        return v;
    }();
    return all;
}

}  // namespace

namespace {

using tables::CheckResult;

// The norm n0 against its closed form where the lobe has one: GGX at
// roughness 1 (1 - mu ln(1 + 1/mu), height-correlated G2), the Charlie
// sheen at normal incidence, EON everywhere (1: it conserves energy).
ClosedFormCheck norm_check(LtcLobeKind kind) {
    // The norms' quadrature tolerance and 1e-12 for the closed forms.
    const double tol = kGgxTableTolerance + 1e-12;
    switch (kind) {
        case LtcLobeKind::ggx:
            return {"n0 at roughness 1 vs 1 - mu ln(1 + 1/mu) (height-correlated G2)", tol,
                    [](const TexelEvaluator& e) {
                        std::vector<std::array<double, 2>> pts;
                        for (double mu : {0.05, 0.25, 0.5, 0.75, 1.0}) pts.push_back({1.0, mu});
                        return tables::worst_over(e, pts, 0,
                                                  [](const auto& p) { return tables::ggx_albedo_alpha_one(p[1]); });
                    }};
        case LtcLobeKind::eon:
            return {"n0 vs 1 (EON conserves energy at rho = 1)", tol, [](const TexelEvaluator& e) {
                        return tables::worst_over(e, tables::grid_points({0.0, 0.3, 0.7, 1.0}, {1.0, 0.5, 0.05, 0.0}),
                                                  0, [](const auto&) { return 1.0; });
                    }};
        case LtcLobeKind::charlie_sheen:
            return {"n0 at cos_theta = 1 vs 2^(1 - n/2) / (n + 2), n = 2 + 1/alpha", tol,
                    [](const TexelEvaluator& e) {
                        return tables::worst_over(e, tables::grid_points({0.2, 0.5, 0.8, 1.0}, {1.0}), 0,
                                                  [](const auto& p) { return tables::charlie_albedo_normal(p[0] * p[0]); });
                    }};
    }
    return {};
}

// ltc_2's sphere channel at len = 0 (cos_theta = 1) is the clamped cosine
// of the horizon-clipped sphere: max(z, 0), z = 2 r - 1.
ClosedFormCheck sphere_check() {
    return {"sphere channel at len = 0 (cos_theta = 1) vs max(z, 0), z = 2 r - 1", 1e-15,
            [](const TexelEvaluator& e) {
                return tables::worst_over(e, tables::grid_points({0.0, 0.3, 0.5, 0.8, 1.0}, {1.0}), 3,
                                          [](const auto& p) { return std::max(2.0 * p[0] - 1.0, 0.0); });
            }};
}

std::vector<ClosedFormCheck> entry_checks(const Entry& e, const std::string& parameter) {
    switch (e.layout) {
        case Layout::heitz_matrix:
            return {ltc_local_minimum_check(e.id, parameter), ltc_metadata_maxima_check(e.id)};
        case Layout::hdrp_matrix:
            return {ltc_local_minimum_check(e.id, parameter), ltc_metadata_maxima_check(e.id)};
        case Layout::heitz_norms: return {norm_check(e.lobe), sphere_check()};
        case Layout::norm: return {norm_check(e.lobe)};
        case Layout::report: return {ltc_report_check(e.id, parameter)};
    }
    return {};
}

}  // namespace

void register_ltc_family(FamilyEntries& family) {
    std::vector<TableDefinition>& out = family.tables;
    for (const Entry& e : entries()) {
        TableDefinition d = make(e);
        d.checks = entry_checks(e, d.axes[0].axis.name);
        out.push_back(std::move(d));
    }
}

LtcLobe ltc_table_lobe(const TableDefinition& def, double roughness, double mu, Visibility vis) {
    for (const Entry& e : entries())
        if (e.id == def.id) return texel_lobe(e.lobe, e.layout, roughness, mu, vis);
    std::string known;
    for (const Entry& e : entries()) known += (known.empty() ? "" : ", ") + e.id;
    throw Error("table '" + def.id + "' is not an LTC table; allowed: " + known);
}

}  // namespace brdflut
