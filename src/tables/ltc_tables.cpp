// LTC area-light tables in the layouts engines load (ltc_tables.h: how any
// family declares one), and the LTC family: the GGX, Charlie sheen and EON
// lobes' tables.
//
// Heitz, Dupuy, Hill and Neubelt 2016, "Real-Time Polygonal-Light Shading
//   with Linearly Transformed Cosines" (ltc_1, ltc_2: selfshadow/ltc_code
//   fit/fitLTC.cpp packTab, loaded by three.js, Blender EEVEE, Godot)
// Unity HDRP LTCAreaLight.hlsl (LTCSampleMatrix: the transposed inverse
//   divided by its m22, as _m00_m02_m11_m20 of the transpose)
#include <algorithm>
#include <array>
#include <cstdio>
#include <map>
#include <memory>
#include <mutex>
#include <string>
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
namespace ltc_family {  // this family's own names, apart from the other families' in a unity build
namespace {

using Layout = LtcLayout;
using Options = std::map<std::string, std::string>;

// The lobes of the catalogue's LTC tables by table id, recorded by
// ltc_table() while the catalogue is built (ltc_table_lobe reads them).
struct LobeRegistry {
    std::mutex mutex;
    std::map<std::string, LtcTexelLobe> lobes;
};
LobeRegistry& lobe_registry() {
    static LobeRegistry r;
    return r;
}

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
tables::SharedResults<8, TexelFit>& texel_fit_cache() {
    static tables::SharedResults<8, TexelFit> cache(1 << 16);
    return cache;
}
// The norms of a generic lobe at a texel, computed once per run at the
// lobe's own tolerance: the fit, its error report and the norm tables of
// the lobe all need n0, and the generic path's integral costs as much as a
// good part of the fit (65,536 texels at most, ~2 MB).
LtcNorms shared_norms(const LtcLobe& lobe) {
    static tables::SharedResults<4, LtcNorms> cache(1 << 16);
    using tables::key_bits;
    return cache.get({lobe.key, key_bits(lobe.mu_o), key_bits(lobe.param), key_bits(lobe.norm_tolerance)},
                     [&] { return ltc_norms(lobe); });
}
// The lobe with those norms known (a lobe that knows its own is kept).
LtcLobe with_shared_norms(LtcLobe lobe) {
    if (lobe.kind != LtcLobeKind::generic || lobe.known_n0 >= 0.0) return lobe;
    const LtcNorms n = shared_norms(lobe);
    lobe.known_n0 = n.n0;
    lobe.known_n0_error = n.n0_error;
    lobe.known_n1 = n.n1;
    lobe.known_n1_error = n.n1_error;
    return lobe;
}

TexelFit texel_fit(const LtcLobe& given, const LtcFitOptions& opt) {
    using tables::key_bits;
    const LtcLobe lobe = with_shared_norms(given);
    return texel_fit_cache().get(
        {tables::key_enum(lobe.kind), tables::key_enum(lobe.vis), key_bits(lobe.mu_o), key_bits(lobe.param), lobe.key,
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

// The norm tables of a generic lobe hold n0 = A + B to the quality's
// tolerance: the lobe's own norm tolerance (the default quality's) times
// this. They take the fits' n0 (shared_norms) where its error estimate
// meets that, else compute A and B to half of it each.
double norm_tolerance_scale(Quality q) { return q == Quality::draft ? 100.0 : q == Quality::reference ? 0.01 : 1.0; }

class LtcEvaluator final : public TexelEvaluator {
public:
    LtcEvaluator(LtcTexelLobe lobe, Options options, Layout layout, const LtcFitOptions& opt,
                 std::shared_ptr<FitFigures> figures, double norm_scale)
        : lobe_(std::move(lobe)), options_(std::move(options)), layout_(layout), opt_(opt),
          figures_(std::move(figures)), norm_scale_(norm_scale) {}

    // coords: (roughness, cos_theta) in the definition's order.
    TexelValue evaluate(const double* c, std::uint64_t texel) const override {
        const double r = c[0], mu = c[1];
        LtcLobe lobe = lobe_(r, mu, options_);
        TexelValue out;
        if (!fits(layout_)) {
            if (lobe.kind == LtcLobeKind::generic && lobe.known_n0 < 0.0) {
                // The norms the fits use when their error estimates meet
                // this table's tolerance, else A and B to half of it each.
                // (Below the default quality's tolerance they never do.)
                const double wanted = lobe.norm_tolerance * norm_scale_;
                bool meets = false;
                if (norm_scale_ >= 1.0) {
                    const LtcNorms shared = shared_norms(lobe);
                    meets = shared.n0_error <= wanted && shared.n1_error <= wanted;
                }
                if (meets) lobe = with_shared_norms(lobe);
                else lobe.norm_tolerance = 0.5 * wanted;
            }
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
    LtcTexelLobe lobe_;
    Options options_;
    Layout layout_;
    LtcFitOptions opt_;
    std::shared_ptr<FitFigures> figures_;
    double norm_scale_;
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

// The fit's rule for a lobe (`sample`, one texel's: whether it peaks near
// the mirror direction sets the objective's terms and the frame).
std::string rule(const LtcLobe& sample, const std::string& norms_rule) {
    const double mass = ltc_mass_weight(sample);
    return std::string(
               "per texel: Nelder-Mead in double on all four parameters of a y-symmetric LTC from an initial "
               "guess computed from the texel's own lobe (its peak and half-maximum widths), restarted until it "
               "stops improving; objective int |p - D|^3 / (p + D) dw / int p^2 dw (Heitz's error measure)") +
           (mass == 0.0 ? std::string()
                        : " + " + number_text(mass) +
                              " int (p - D)^2 / (p + D) dw (the triangular discrimination, which bounds every "
                              "polygon's light error)") +
           ", by Gauss-Legendre product quadrature in stereographic coordinates about the lobe's " +
           (sample.peaks_near_mirror() ? "peak" : "normal") +
           ", split at the horizon; + " + number_text(kLtcFitLightWeight) + " max(0, 1 - mu / " +
           number_text(kLtcFitLightMu) + ")^2 times the sum of squared differences of the "
           "LTC's light (closed form) and the lobe's (exact polygon quadrature to light_tolerance) over the "
           "eight lights of ltc_fit_light_bank; " + norms_rule;
}

const char* kNormRule = "no fit: exact integrals (n0, n1) and the closed-form sphere form factor";

// Rows uniform in sqrt(1 - cos theta): cos_theta from 1 down to 0, squared
// warp (mu = 1 - u^2), end points; the lobe is evaluated at mu >= cos(1.57).
AxisSpec view_axis() {
    return {Axis{"cos_theta", 1.0, 0.0, 64, Placement::endpoints, Warp::square}, 0.0, 1.0,
            "cos(theta_o); rows at u = sqrt(1 - cos(theta_o)); the lobe is fitted at cos(theta_o) >= cos(1.57)"};
}

const char* kFrame = "normal +z, view (sin theta, 0, cos theta); M^-1 acts on column vectors in this frame";

int quality_level(Quality q) { return q == Quality::draft ? 0 : q == Quality::reference ? 2 : 1; }

// The stored inverse matrix by rows (TableDefinition::shader_matrix), as the
// evaluator packs it: Heitz (a, c, b, d) of [[a, 0, b], [0, 1, 0], [c, 0, d]];
// HDRP (a, c, 1, b) / d.
const std::array<std::string, 9> kHeitzMatrix = {"R", "0", "B", "0", "1", "0", "G", "0", "A"};
const std::array<std::string, 9> kHdrpMatrix = {"R", "0", "A", "0", "B", "0", "G", "0", "1"};

// The options a lobe is built with: the given ones, the defaults for the rest.
Options with_defaults(const std::vector<ModelOption>& declared, const Options& given) {
    Options all;
    for (const ModelOption& o : declared) all[o.name] = o.default_value;
    for (const auto& kv : given) all[kv.first] = kv.second;
    return all;
}

std::vector<ClosedFormCheck> layout_checks(const std::string& id, Layout layout, const std::string& parameter) {
    switch (layout) {
        case Layout::heitz_matrix:
        case Layout::hdrp_matrix: return {ltc_local_minimum_check(id, parameter), ltc_metadata_maxima_check(id)};
        case Layout::report: return {ltc_report_check(id, parameter)};
        case Layout::heitz_norms:
        case Layout::norm: return {};
    }
    return {};
}

}  // namespace
}  // namespace ltc_family

std::uint64_t ltc_lobe_key(const std::string& name) {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a
    for (unsigned char ch : name) h = (h ^ ch) * 1099511628211ull;
    return h;
}

TableDefinition ltc_table(LtcTableSpec e) {
    using namespace ltc_family;
    TableDefinition d;
    d.id = e.id;
    d.description = e.description;
    d.axes = {e.roughness, view_axis()};
    d.channels = e.channels;
    d.options = e.options;
    d.preset = e.preset;
    // A fit per texel is not searched (catalogue.h); the norm tables hold
    // integrals as cheap as the albedo tables, and identify searches them.
    d.searched_by_identify = !fits(e.layout);
    const Layout layout = e.layout;
    if (is_matrix(layout)) {
        d.shader_result = "ltc_inverse";
        d.shader_matrix = layout == Layout::heitz_matrix ? kHeitzMatrix : kHdrpMatrix;
    }
    d.checks = layout_checks(e.id, layout, d.axes[0].axis.name);
    for (ClosedFormCheck& c : e.checks) d.checks.push_back(std::move(c));
    {
        LobeRegistry& reg = lobe_registry();
        std::lock_guard<std::mutex> lock(reg.mutex);
        reg.lobes[e.id] = e.lobe;
    }
    d.prepare = [e = std::move(e)](const TableSettings& s) {
        if (s.method == Method::monte_carlo)
            throw Error("LTC tables are fitted by quadrature only; --method monte_carlo is not allowed");
        const Layout layout = e.layout;
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
        // A texel's lobe (this one at roughness 0.5, mu 0.5) tells the rule
        // whether the lobe peaks and so which terms its objective has;
        // building it also rejects bad option values before any texel.
        const Options options = with_defaults(e.options, s.params);
        const LtcLobe sample = e.lobe(0.5, 0.5, options);
        PreparedTable p;
        const double norm_scale = norm_tolerance_scale(s.quality);
        p.evaluator = std::make_unique<LtcEvaluator>(e.lobe, options, layout, opt, figures, norm_scale);
        p.model = e.model(options);
        p.model["layout"] = e.layout_text;
        p.model["frame"] = kFrame;
        p.model["preset"] = e.preset;
        p.model["engine_source"] = e.engine_source;
        if (!fits(layout)) {
            p.method = {{"rule", kNormRule}};
            if (sample.kind == LtcLobeKind::generic) {
                p.method["rule"] = std::string(kNormRule) +
                                   "; n0 = A + B by the generic lobe path: the fits' n0 (A and B each to the "
                                   "lobe's norm tolerance) where its error estimate is within abs_tolerance, else "
                                   "A and B each to half of abs_tolerance";
                p.method["abs_tolerance"] = sample.norm_tolerance * norm_scale;
            }
            return p;
        }
        p.method = {{"rule", rule(sample, e.norms_rule)},
                    {"objective_nodes", {{"radial", opt.radial_nodes}, {"azimuth", opt.azimuth_nodes}}}};
        if (layout == Layout::report)
            p.method["lights"] = "the bank of ltc_light_bank: squares of 1 to 60 degrees in the peak, off "
                                 "the peak and at the horizon; exact light by adaptive Gauss-Kronrod over "
                                 "the polygon, each light to light_tolerance of n0";
        const std::string report_id = e.report_table;
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

LtcLobe ltc_table_lobe(const TableDefinition& def, double roughness, double mu, const ltc_family::Options& options) {
    using namespace ltc_family;
    LtcTexelLobe lobe;
    {
        LobeRegistry& reg = lobe_registry();
        std::lock_guard<std::mutex> lock(reg.mutex);
        const auto it = reg.lobes.find(def.id);
        if (it == reg.lobes.end()) {
            std::string known;
            for (const auto& kv : reg.lobes) known += (known.empty() ? "" : ", ") + kv.first;
            throw Error("table '" + def.id + "' is not an LTC table; allowed: " + known);
        }
        lobe = it->second;
    }
    return lobe(roughness, mu, with_defaults(def.options, options));
}

// The LTC family: GGX (Heitz's ltc_1 and ltc_2, HDRP's matrix), the Charlie
// sheen and EON, each with its error table.
namespace ltc_family {  // this family's own names, apart from the other families' in a unity build
namespace {

// The lobe of a texel: the roughness coordinate r mapped to the lobe's
// parameter (GGX and Charlie alpha = r^2, HDRP's GGX at alpha >= 1e-3; EON
// sigma = r), clamped by LtcLobe.
LtcTexelLobe kind_lobe(LtcLobeKind kind, Layout layout) {
    return [kind, layout](double r, double mu, const Options& options) {
        if (kind == LtcLobeKind::eon) return LtcLobe(kind, mu, r);
        const Visibility vis = kind == LtcLobeKind::ggx ? visibility_from_string(options.at("visibility"))
                                                        : Visibility::height_correlated;
        const double alpha = std::max(alpha_from_perceptual(r), layout == Layout::hdrp_matrix ? 1e-3 : 0.0);
        return LtcLobe(kind, mu, alpha, vis);
    };
}

std::string norms_rule(LtcLobeKind kind) {
    return kind == LtcLobeKind::ggx             ? "n0, n1 by the ggx_dfg quadrature"
           : kind == LtcLobeKind::charlie_sheen ? "n0 by the sheen_charlie_albedo quadrature"
                                                : "n0 by the eon_albedo quadrature";
}

AxisSpec roughness_axis(LtcLobeKind kind) {
    if (kind == LtcLobeKind::eon)
        return {Axis{"sigma", 0.0, 1.0, 64, Placement::endpoints, Warp::linear}, 0.0, 1.0,
                "EON (Fujii/OpenPBR) roughness sigma in [0, 1]"};
    return {Axis{"roughness", 0.0, 1.0, 64, Placement::endpoints, Warp::linear}, 0.0, 1.0,
            kind == LtcLobeKind::ggx ? "perceptual roughness r; GGX alpha = max(r^2, 1e-5)"
                                     : "perceptual roughness r; Charlie alpha = max(r^2, 0.01)",
            "", "alpha"};
}

nlohmann::json ltc_model(LtcLobeKind kind, Visibility vis, const std::string& layout) {
    if (kind == LtcLobeKind::charlie_sheen) {
        nlohmann::json m = tables::charlie_sheen_model();
        m["brdf"] = "Charlie sheen (Estevez and Kulla 2017), no Fresnel, fitted by a linearly transformed cosine";
        m["roughness"] = "alpha = max(perceptual_roughness^2, 0.01)";
        return m;
    }
    if (kind == LtcLobeKind::eon)
        return {{"brdf", "EON rough diffuse at rho = 1 (Portsmouth et al. 2025; FON plus the multiple-scattering "
                         "lobe with FON's exact albedo, as eon_albedo), fitted by a linearly transformed cosine"},
                {"roughness", "sigma in [0, 1]; sigma = 0 is Lambert"}};
    return {{"brdf", "GGX microfacet, single scattering, fitted by a linearly transformed cosine"},
            {"distribution", "ggx"},
            {"visibility", to_string(vis)},
            {"fresnel", "1 (n1 carries the Schlick moment)"},
            {"roughness", layout == "hdrp" ? "alpha = max(perceptual_roughness^2, 1e-3)"
                                           : "alpha = max(perceptual_roughness^2, 1e-5)"}};
}

// The error report of the lobe's tables.
std::string report_table(LtcLobeKind kind) {
    return kind == LtcLobeKind::ggx ? "ltc_ggx_error" : kind == LtcLobeKind::eon ? "ltc_eon_error" : "ltc_sheen_charlie_error";
}

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
        case LtcLobeKind::generic: break;
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

const std::vector<std::string> kReportChannels = {
    "relative L3 error of n0 D against f cos over the sphere", "LTC mass below the horizon (of 1)",
    "largest integrated-light error over the light bank, as a fraction of n0",
    "mean integrated-light error over the light bank, as a fraction of n0"};

const char* kHdrpPacking =
    "Unity HDRP LTCSampleMatrix: invM._m22 = 1, invM._m00_m02_m11_m20 = RGBA of the transposed inverse";
const std::vector<std::string> kHdrpMatrixChannels = {"m00 of M^-1 / M^-1[2][2] (row 0, column 0)",
                                                       "m20 (row 2, column 0)", "m11 (row 1, column 1)",
                                                       "m02 (row 0, column 2)"};

const char* kHeitzShader = "shader mat3(vec3(R, 0, G), vec3(0, 1, 0), vec3(B, 0, A))";
const std::vector<std::string> kHeitzMatrixChannels = {"m00 of M^-1 / M^-1[1][1] (glm m[col][row])",
                                                        "m02 (column 0, row 2)", "m20 (column 2, row 0)", "m22"};

// A table of the family: its lobe kind, layout and texts.
LtcTableSpec spec(LtcLobeKind kind, Layout layout, std::string id, std::string preset, std::string description,
                  std::string layout_text, std::vector<std::string> channels) {
    LtcTableSpec e;
    e.id = std::move(id);
    e.preset = std::move(preset);
    e.description = std::move(description);
    e.layout = layout;
    e.layout_text = std::move(layout_text);
    e.channels = std::move(channels);
    e.roughness = roughness_axis(kind);
    // The fitter's GGX lobe takes the two Smith forms (not Schlick's).
    if (kind == LtcLobeKind::ggx) e.options = {tables::visibility_option({"height_correlated", "separable"})};
    const std::string model_layout = layout == Layout::hdrp_matrix ? "hdrp" : e.layout_text;
    e.model = [kind, model_layout](const Options& options) {
        return ltc_model(kind, kind == LtcLobeKind::ggx ? visibility_from_string(options.at("visibility"))
                                                        : Visibility::height_correlated,
                         model_layout);
    };
    e.engine_source = layout == Layout::hdrp_matrix
                          ? "Unity-Technologies/Graphics HDRP Runtime/Material/LTCAreaLight/LTCAreaLight.hlsl"
                          : "selfshadow/ltc_code fit/fitLTC.cpp (packTab); three.js "
                            "examples/jsm/lights/RectAreaLightTexturesLib.js";
    e.norms_rule = norms_rule(kind);
    e.report_table = report_table(kind);
    e.lobe = kind_lobe(kind, layout);
    if (layout == Layout::heitz_norms) e.checks = {norm_check(kind), sphere_check()};
    if (layout == Layout::norm) e.checks = {norm_check(kind)};
    return e;
}

}  // namespace
}  // namespace ltc_family

void register_ltc_family(FamilyEntries& family) {
    using namespace ltc_family;
    family.families.push_back(
        {"", "Area lights: linearly transformed cosines",
        "Linearly transformed cosines (Heitz, Dupuy, Hill and Neubelt 2016) shade polygonal lights in "
        "closed form: per view angle and roughness a 3x3 matrix M carries the clamped cosine to a "
        "distribution close to the lobe f cos, and a polygon's light is the cosine's edge integral over "
        "M^-1 P. brdflut fits M per texel (Nelder-Mead on all four parameters of a y-symmetric LTC, "
        "Heitz's error measure, a light term near grazing view) for the GGX lobe in Heitz's layout "
        "(`ltc_1`, `ltc_2`, as three.js, EEVEE and Godot load them) and HDRP's (`hdrp_ltc_ggx`), and in "
        "Heitz's layout for the Charlie sheen and EON lobes, each with a table of the per-texel error "
        "(relative L3 error, mass below the horizon, integrated-light error over a bank of lights). Any "
        "family declares the LTC of a lobe of its own through the same path (`src/tables/ltc_tables.h`)."});
    using K = LtcLobeKind;
    std::vector<TableDefinition>& out = family.tables;
    out.push_back(ltc_table(spec(K::ggx, Layout::heitz_matrix, "ltc_1", "ltc",
                                 "Heitz LTC ltc_1: the inverse matrix of the GGX fit divided by its middle element",
                                 std::string("Heitz ltc_1 (three.js LTC_MAT_1, EEVEE, Godot): ") + kHeitzShader,
                                 kHeitzMatrixChannels)));
    out.push_back(ltc_table(spec(K::ggx, Layout::heitz_norms, "ltc_2", "ltc",
                                 "Heitz LTC ltc_2: norm, Fresnel moment and the horizon-clipped sphere form factor",
                                 "Heitz ltc_2 (three.js LTC_MAT_2): specular = n0 F0 + n1 (1 - F0) times the LTC "
                                 "integral; A on its own axes",
                                 {"n0: integral of f cos(theta_i) dw_i (= ggx_albedo)",
                                  "n1: integral of f (1 - v.h)^5 cos(theta_i) dw_i (= ggx_dfg B)", "unused: 0",
                                  "sphere form factor clipped to the horizon at z = 2 u_x - 1 (cosine of the average "
                                  "light direction), len = u_y (its length)"})));
    out.push_back(ltc_table(spec(K::ggx, Layout::report, "ltc_ggx_error", "ltc",
                                 "Per-texel error of the GGX LTC fit (the texels of ltc_1 and ltc_2)",
                                 "error report on the grid of ltc_1", kReportChannels)));
    out.push_back(ltc_table(spec(K::charlie_sheen, Layout::heitz_matrix, "ltc_sheen_charlie", "ltc",
                                 "LTC of the Charlie sheen lobe in ltc_1's layout: the inverse matrix divided by its "
                                 "middle element",
                                 std::string("ltc_1's layout (columns roughness, alpha = max(r^2, 0.01)): ") +
                                     kHeitzShader,
                                 kHeitzMatrixChannels)));
    out.push_back(ltc_table(spec(K::charlie_sheen, Layout::norm, "ltc_sheen_charlie_norm", "ltc",
                                 "Norm n0 of the Charlie sheen lobe on the grid of ltc_sheen_charlie",
                                 "ltc_sheen_charlie's grid: sheen = n0 times the LTC integral",
                                 {"n0: integral of f cos(theta_i) dw_i (= sheen_charlie_albedo)"})));
    out.push_back(ltc_table(spec(K::charlie_sheen, Layout::report, "ltc_sheen_charlie_error", "ltc",
                                 "Per-texel error of the Charlie sheen LTC fit (the texels of ltc_sheen_charlie)",
                                 "error report on the grid of ltc_sheen_charlie", kReportChannels)));
    out.push_back(ltc_table(spec(K::eon, Layout::heitz_matrix, "ltc_eon", "ltc",
                                 "LTC of the EON rough diffuse lobe in ltc_1's layout: the inverse matrix divided by "
                                 "its middle element",
                                 std::string("ltc_1's layout (columns sigma): ") + kHeitzShader,
                                 kHeitzMatrixChannels)));
    out.push_back(ltc_table(spec(K::eon, Layout::norm, "ltc_eon_norm", "ltc",
                                 "Norm n0 of the EON lobe on the grid of ltc_eon (1 up to the quadrature: EON "
                                 "conserves energy)",
                                 "ltc_eon's grid: diffuse = rho n0 times the LTC integral",
                                 {"n0: integral of f cos(theta_i) dw_i (= eon_albedo)"})));
    out.push_back(ltc_table(spec(K::eon, Layout::report, "ltc_eon_error", "ltc",
                                 "Per-texel error of the EON LTC fit (the texels of ltc_eon)",
                                 "error report on the grid of ltc_eon", kReportChannels)));
    out.push_back(ltc_table(spec(K::ggx, Layout::hdrp_matrix, "hdrp_ltc_ggx", "hdrp_ltc",
                                 "HDRP LTC GGX matrix: the inverse divided by its m22 (alpha >= 1e-3)",
                                 kHdrpPacking, kHdrpMatrixChannels)));
}

namespace ltc_family {
namespace {
// A table of a layer: its layout, id and texts on the layer's grid.
TableDefinition layer_table(const LtcLayer& layer, Layout layout, const std::string& preset, const std::string& id,
                            const std::string& description, const std::string& layout_text,
                            const std::vector<std::string>& channels, const std::string& error_id) {
    LtcTableSpec e;
    e.id = id;
    e.preset = preset;
    e.description = description;
    e.layout = layout;
    e.layout_text = layout_text;
    e.channels = channels;
    e.roughness = {Axis{"roughness", 0.0, 1.0, 64, Placement::endpoints, Warp::linear}, 0.0, 1.0,
                   layer.roughness_meaning, "", "alpha"};
    e.model = layer.model;
    e.engine_source = layer.engine_source;
    e.norms_rule = layer.norms_rule;
    e.report_table = error_id;
    e.lobe = layer.lobe;
    if (layout == Layout::norm) e.checks = layer.norm_checks;
    return ltc_table(std::move(e));
}
}  // namespace
}  // namespace ltc_family

std::vector<TableDefinition> hdrp_ltc_layer(const LtcLayer& layer) {
    using namespace ltc_family;
    const std::string matrix_id = "hdrp_ltc_" + layer.name, error_id = matrix_id + "_error";
    return {layer_table(layer, Layout::hdrp_matrix, "hdrp_ltc", matrix_id, layer.matrix_description, kHdrpPacking,
                        kHdrpMatrixChannels, error_id),
            layer_table(layer, Layout::report, "hdrp_ltc", error_id, layer.error_description,
                        "error report on the grid of " + matrix_id, kReportChannels, error_id)};
}

std::vector<TableDefinition> heitz_ltc_layer(const LtcLayer& layer) {
    using namespace ltc_family;
    const std::string matrix_id = "ltc_" + layer.name, norm_id = matrix_id + "_norm", error_id = matrix_id + "_error";
    return {layer_table(layer, Layout::heitz_matrix, "ltc", matrix_id, layer.matrix_description,
                        "ltc_1's layout: " + std::string(kHeitzShader), kHeitzMatrixChannels, error_id),
            layer_table(layer, Layout::norm, "ltc", norm_id, layer.norm_description,
                        matrix_id + "'s grid: the lobe = n0 times the LTC integral", {"n0: integral of f cos(theta_i) dw_i"},
                        error_id),
            layer_table(layer, Layout::report, "ltc", error_id, layer.error_description,
                        "error report on the grid of " + matrix_id, kReportChannels, error_id)};
}

}  // namespace brdflut
