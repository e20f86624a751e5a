// Fresnel tables: exact reflectance and hemispherical averages of dielectric
// and conductor interfaces, and per-metal colour tables.
//
// Born and Wolf 1999, "Principles of Optics" (Fresnel equations)
// Kulla and Conty 2017, "Revisiting Physically Based Shading at Imageworks"
//   (F_avg as the input of multiple-scattering Fresnel)
#include <cmath>
#include <memory>
#include <sstream>

#include "brdflut/conductor_presets.h"
#include "brdflut/error.h"
#include "brdflut/fresnel_integrals.h"
#include "brdflut/random.h"
#include "tables/checks.h"
#include "tables/registry.h"

namespace brdflut {
namespace fresnel_family {  // this family's own names, apart from the other families' in a unity build
namespace {

// Absolute tolerance of the averages at each quality.
constexpr tables::Tolerances kTolerances{1e-6, kFresnelAbsTolerance, 1e-13};
// Largest eta and k accepted on an axis or as an option. Beyond it no real
// material exists at visible wavelengths and F is within 1e-2 of 1 except
// at normal incidence.
constexpr double kMaxIndex = 100.0;

const char* kQuadratureRule =
    "adaptive Gauss-Kronrod (7,15) in s with mu = mu_c -/+ len s^2 on each side of the "
    "critical cosine mu_c = sqrt(1 - eta^2) (mu = s^2 for eta >= 1); error per value: "
    "QUADPACK estimate";
const char* kMcSampler = "mu with density 2 mu (mu = sqrt(1 - u)), estimator F(mu)";

AxisSpec eta_axis(double min, double max, int count) {
    return {Axis{"eta", min, max, count, Placement::center, Warp::linear}, 0.0, kMaxIndex,
            "eta: relative index of refraction eta_t / eta_i (real part), eta > 0"};
}

AxisSpec k_axis(double min, double max, int count) {
    return {Axis{"k", min, max, count, Placement::center, Warp::linear}, 0.0, kMaxIndex,
            "k: extinction coefficient of the conductor's index eta + i k"};
}

// The eta axis must stay above 0; validate_settings checks only min >= 0.
void check_eta_axis(const std::string& id, const TableSettings& s) {
    for (const Axis& a : s.axes)
        if (a.name == "eta" && !(a.min > 0.0)) {
            std::ostringstream msg;
            msg << "table '" << id << "': axis 'eta' range " << a.min << ":" << a.max
                << " includes eta <= 0; allowed: 0 < eta <= " << kMaxIndex;
            throw Error(msg.str());
        }
}

ModelOption fresnel_option() {
    return {"fresnel",
            "conductor Fresnel formula: exact (complex index) or approx (the real-valued "
            "(eta^2 + k^2) cos^2 form of pbrt-v2 and Mitsuba 0.5)",
            "exact",
            {"exact", "approx"}};
}

std::vector<std::string> preset_names() {
    std::vector<std::string> names;
    for (const ConductorPreset& p : conductor_presets()) names.emplace_back(p.name);
    return names;
}

// "r,g,b": three finite numbers, each at least `min` (strictly above it when
// `strict`) and at most kMaxIndex.
std::array<double, 3> parse_rgb(const std::string& option, const std::string& text, double min,
                                bool strict) {
    std::array<double, 3> v{};
    std::size_t start = 0;
    int count = 0;
    const std::string allowed = std::string("allowed: three comma-separated numbers r,g,b, each ") +
                                (strict ? "> " : ">= ") + (min == 0.0 ? "0" : std::to_string(min)) +
                                " and <= 100";
    while (true) {
        const std::size_t comma = text.find(',', start);
        const std::string part =
            text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        double x = 0.0;
        std::size_t used = 0;
        try {
            x = std::stod(part, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (part.empty() || used != part.size() || !std::isfinite(x) || count >= 3 ||
            (strict ? !(x > min) : !(x >= min)) || x > kMaxIndex)
            throw Error("--" + option + " '" + text + "' is not valid for table 'fresnel_conductor'; " +
                        allowed);
        v[static_cast<std::size_t>(count++)] = x;
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    if (count != 3)
        throw Error("--" + option + " '" + text + "' has " + std::to_string(count) +
                    " value(s) for table 'fresnel_conductor'; " + allowed);
    return v;
}

nlohmann::json closed_form_method() {
    return {{"name", "closed_form"},
            {"rule", "exact Fresnel equations evaluated in double precision (no integration)"}};
}

nlohmann::json average_method(const TableSettings& s) {
    return s.method == Method::monte_carlo ? tables::monte_carlo_method(kMcSampler, s)
                                           : tables::quadrature_method(kQuadratureRule,
                                                                       kTolerances.at(s.quality));
}

// ---- fresnel_dielectric: F(mu, eta) ---------------------------------------

class DielectricEvaluator final : public TexelEvaluator {
public:
    TexelValue evaluate(const double* c, std::uint64_t) const override {
        TexelValue out;
        out.value[0] = fresnel_dielectric(c[0], c[1]);
        return out;
    }
};

// ---- fresnel_dielectric_avg: F_avg(eta), F_avg(1/eta) ---------------------

class DielectricAverageEvaluator final : public TexelEvaluator {
public:
    explicit DielectricAverageEvaluator(const TableSettings& s)
        : mc_(s.method == Method::monte_carlo), samples_(s.samples), seed_(s.seed),
          abs_tol_(kTolerances.at(s.quality)) {}

    TexelValue evaluate(const double* c, std::uint64_t texel) const override {
        const double eta = c[0];
        TexelValue out;
        const std::uint64_t seed = mix_seed(seed_, texel);
        const Estimate<1> outside = mc_ ? fresnel_dielectric_average_mc(eta, samples_, seed)
                                        : fresnel_dielectric_average_quadrature(eta, abs_tol_);
        const Estimate<1> inside =
            mc_ ? fresnel_dielectric_average_mc(1.0 / eta, samples_, mix_seed(seed, 1))
                : fresnel_dielectric_average_quadrature(1.0 / eta, abs_tol_);
        const double scale = mc_ ? tables::kMcErrorSigmas : 1.0;
        out.value = {outside.value[0], inside.value[0], 0.0, 0.0};
        out.error = {scale * outside.error[0], scale * inside.error[0], 0.0, 0.0};
        return out;
    }

private:
    bool mc_;
    long long samples_;
    std::uint64_t seed_;
    double abs_tol_;
};

// ---- fresnel_conductor: F(mu) per channel for one metal -------------------

class ConductorEvaluator final : public TexelEvaluator {
public:
    ConductorEvaluator(std::array<double, 3> eta, std::array<double, 3> k, FresnelForm form)
        : eta_(eta), k_(k), form_(form) {}

    TexelValue evaluate(const double* c, std::uint64_t) const override {
        TexelValue out;
        for (std::size_t ch = 0; ch < 3; ++ch)
            out.value[ch] = fresnel_conductor(c[0], eta_[ch], k_[ch], form_);
        return out;
    }

private:
    std::array<double, 3> eta_, k_;
    FresnelForm form_;
};

PreparedTable prepare_conductor(const TableSettings& s) {
    const FresnelForm form = fresnel_form_from_string(tables::param(s, "fresnel"));
    const std::string& material = tables::param(s, "metal");
    const std::string& eta_text = tables::param(s, "metal-eta");
    const std::string& k_text = tables::param(s, "metal-k");
    const ConductorPreset& preset = conductor_preset(material);
    nlohmann::json model = {{"brdf", "smooth conductor: unpolarized Fresnel reflectance"},
                            {"fresnel", to_string(form)}};
    std::array<double, 3> eta = preset.eta, k = preset.k;
    if (!eta_text.empty() || !k_text.empty()) {
        if (eta_text.empty() || k_text.empty())
            throw Error(std::string("table 'fresnel_conductor': --") + (eta_text.empty() ? "metal-k" : "metal-eta") +
                        " was given without --" + (eta_text.empty() ? "metal-eta" : "metal-k") +
                        "; allowed: both --metal-eta r,g,b and --metal-k r,g,b, or neither (use --metal)");
        eta = parse_rgb("metal-eta", eta_text, 0.0, true);
        k = parse_rgb("metal-k", k_text, 0.0, false);
        model["material"] = "custom";
    } else {
        model["material"] = material;
        model["wavelengths_nm"] = kPresetWavelengthsNm;
        model["source"] = preset.source;
    }
    model["eta"] = eta;
    model["k"] = k;
    PreparedTable p;
    p.evaluator = std::make_unique<ConductorEvaluator>(eta, k, form);
    p.model = model;
    p.method = closed_form_method();
    return p;
}

// ---- fresnel_conductor_avg: F_avg(eta, k) ---------------------------------

class ConductorAverageEvaluator final : public TexelEvaluator {
public:
    ConductorAverageEvaluator(FresnelForm form, const TableSettings& s)
        : form_(form), mc_(s.method == Method::monte_carlo), samples_(s.samples), seed_(s.seed),
          abs_tol_(kTolerances.at(s.quality)) {}

    TexelValue evaluate(const double* c, std::uint64_t texel) const override {
        const double eta = c[0], k = c[1];
        const Estimate<1> e =
            mc_ ? fresnel_conductor_average_mc(eta, k, form_, samples_, mix_seed(seed_, texel))
                : fresnel_conductor_average_quadrature(eta, k, form_, abs_tol_);
        TexelValue out;
        out.value[0] = e.value[0];
        out.error[0] = (mc_ ? tables::kMcErrorSigmas : 1.0) * e.error[0];
        return out;
    }

private:
    FresnelForm form_;
    bool mc_;
    long long samples_;
    std::uint64_t seed_;
    double abs_tol_;
};

// Indices at which the dielectric table is checked.
const std::vector<double> kCheckEtas{1.0, 1.2, 1.33, 1.5, 2.0, 2.9};

}  // namespace
}  // namespace fresnel_family

void register_fresnel_family(FamilyEntries& family) {
    using namespace fresnel_family;
    family.families.push_back(
        {"", "Fresnel reflectance",
        "The exact unpolarized reflectance F = (Rs + Rp)/2 of a smooth interface (Born and Wolf), mu = "
        "cos(theta_i), eta = eta_t/eta_i; for eta < 1, F = 1 below the critical cosine sqrt(1 - eta^2). A "
        "conductor has the complex index eta + i k (complex arithmetic throughout, so k = 0 gives the "
        "dielectric F). The averages F_avg = 2 * integral of F(mu) mu dmu feed multiple-scattering "
        "Fresnel terms (Kulla and Conty 2017); from inside a dielectric F_avg(1/n) = 1 - (1 - "
        "F_avg(n))/n^2. `--fresnel approx` takes the real-valued conductor form of pbrt-v2 and Mitsuba "
        "0.5, exact only at normal incidence. The metals of `--metal` are listed in [conductor "
        "data](conductors.md)."});
    std::vector<TableDefinition>& out = family.tables;
    using namespace tables;
    {
        TableDefinition d;
        d.id = "fresnel_dielectric";
        d.description = "Exact unpolarized dielectric Fresnel reflectance F(mu, eta) (1 under total "
                        "internal reflection)";
        d.axes = {cos_theta_axis(), eta_axis(1.0, 3.0, 128)};
        d.channels = {"F: (Rs + Rp) / 2 at cos(theta_i) = mu, relative index eta"};
        d.prepare = [](const TableSettings& s) {
            check_eta_axis("fresnel_dielectric", s);
            PreparedTable p;
            p.evaluator = std::make_unique<DielectricEvaluator>();
            p.model = {{"brdf", "smooth dielectric: unpolarized Fresnel reflectance"},
                       {"fresnel", "exact"},
                       {"eta", "eta_t / eta_i; eta < 1: light inside the denser medium"}};
            p.method = closed_form_method();
            return p;
        };
        d.checks = {
            {"F at normal incidence vs ((eta - 1)/(eta + 1))^2", 1e-15,
             [](const TexelEvaluator& e) {
                 return worst_over(e, grid_points({1.0}, kCheckEtas), 0,
                                   [](const auto& p) { return sqr((p[1] - 1) / (p[1] + 1)); });
             }},
            {"F at grazing incidence vs 1", 1e-15,
             [](const TexelEvaluator& e) {
                 return worst_over(e, grid_points({0.0}, kCheckEtas), 0,
                                   [](const auto& p) { return p[1] == 1.0 ? 0.0 : 1.0; });
             }},
        };
        out.push_back(std::move(d));
    }
    {
        TableDefinition d;
        d.id = "fresnel_dielectric_avg";
        d.description = "Dielectric Fresnel hemispherical average F_avg = 2 * integral of F(mu) mu "
                        "dmu, from outside (R) and inside (G)";
        d.axes = {eta_axis(1.0, 3.0, 128)};
        d.channels = {"F_avg(eta): outside, light enters the medium of index ratio eta",
                      "F_avg(1/eta): inside, light leaves it (includes total internal reflection)"};
        d.supports_monte_carlo = true;
        d.prepare = [](const TableSettings& s) {
            check_eta_axis("fresnel_dielectric_avg", s);
            PreparedTable p;
            p.evaluator = std::make_unique<DielectricAverageEvaluator>(s);
            p.model = {{"brdf", "smooth dielectric: unpolarized Fresnel reflectance"},
                       {"fresnel", "exact"},
                       {"quantity", "F_avg = 2 * integral of F(mu) mu dmu over [0, 1]"}};
            p.method = average_method(s);
            return p;
        };
        d.checks = {
            {"F_avg(eta) vs the exact closed form (eta > 1)", 1e-10,
             [](const TexelEvaluator& e) {
                 return worst_over(e, points_1d({1.01, 1.33, 1.5, 2.0, 2.99}), 0,
                                   [](const auto& p) { return fresnel_dielectric_average_closed_form(p[0]); });
             }},
            {"F_avg(1/eta) vs 1 - (1 - F_avg(eta))/eta^2", 1e-10,
             [](const TexelEvaluator& e) {
                 return worst_over(e, points_1d({1.01, 1.33, 1.5, 2.0, 2.99}), 1, [](const auto& p) {
                     return 1.0 - (1.0 - fresnel_dielectric_average_closed_form(p[0])) / (p[0] * p[0]);
                 });
             }},
        };
        out.push_back(std::move(d));
    }
    {
        TableDefinition d;
        d.id = "fresnel_conductor";
        d.description = "Conductor Fresnel reflectance F(mu) per channel for a metal preset or an "
                        "explicit complex index";
        d.axes = {cos_theta_axis()};
        d.channels = {"F at 650 nm (preset) or of --metal-eta/--metal-k first value",
                      "F at 550 nm (preset) or of --metal-eta/--metal-k second value",
                      "F at 450 nm (preset) or of --metal-eta/--metal-k third value"};
        d.options = {
            {"metal", "metal preset of the conductor (optical constants at 650, 550, 450 nm)", "gold",
             preset_names()},
            {"metal-eta",
             "real part of the conductor's index per channel, r,g,b (with --metal-k; overrides --metal)", "", {}},
            {"metal-k", "extinction coefficient of the conductor per channel, r,g,b (with --metal-eta)", "", {}},
            fresnel_option()};
        d.prepare = prepare_conductor;
        d.checks = {
            {"F at normal incidence vs ((eta - 1)^2 + k^2)/((eta + 1)^2 + k^2) (gold)", 1e-15,
             [](const TexelEvaluator& e) {
                 const ConductorPreset& gold = conductor_preset("gold");
                 CheckResult r{0.0, ""};
                 const double mu = 1.0;
                 const TexelValue v = e.evaluate(&mu, 0);
                 for (std::size_t c = 0; c < 3; ++c) {
                     const double eta = gold.eta[c], k = gold.k[c];
                     const double want = (sqr(eta - 1) + k * k) / (sqr(eta + 1) + k * k);
                     const double err = std::abs(v.value[c] - want);
                     if (!(err < r.first)) r = {err, std::string("channel ") + "RGB"[c]};
                 }
                 return r;
             }},
        };
        out.push_back(std::move(d));
    }
    {
        TableDefinition d;
        d.id = "fresnel_conductor_avg";
        d.description = "Conductor Fresnel hemispherical average F_avg(eta, k) = 2 * integral of "
                        "F(mu) mu dmu";
        d.axes = {eta_axis(0.02, 4.0, 128), k_axis(0.0, 10.0, 128)};
        d.channels = {"F_avg: 2 * integral of F(mu) mu dmu for the index eta + i k"};
        d.options = {fresnel_option()};
        d.supports_monte_carlo = true;
        d.prepare = [](const TableSettings& s) {
            check_eta_axis("fresnel_conductor_avg", s);
            const FresnelForm form = fresnel_form_from_string(tables::param(s, "fresnel"));
            PreparedTable p;
            p.evaluator = std::make_unique<ConductorAverageEvaluator>(form, s);
            p.model = {{"brdf", "smooth conductor: unpolarized Fresnel reflectance"},
                       {"fresnel", to_string(form)},
                       {"quantity", "F_avg = 2 * integral of F(mu) mu dmu over [0, 1]"}};
            p.method = average_method(s);
            return p;
        };
        d.checks = {
            {"F_avg(eta, k = 0) vs the dielectric closed form", 1e-9,
             [](const TexelEvaluator& e) {
                 return worst_over(e, grid_points({1.2, 1.5, 2.0, 3.5}, {0.0}), 0,
                                   [](const auto& p) { return fresnel_dielectric_average_closed_form(p[0]); });
             }},
        };
        out.push_back(std::move(d));
    }
}

}  // namespace brdflut
