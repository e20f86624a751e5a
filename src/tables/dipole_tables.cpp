// Subsurface scattering tables of the dipole diffusion model: radial
// profile and its CDF, total diffuse reflectance, its inverse, and profiles
// of measured materials.
//
// Jensen, Marschner, Levoy and Hanrahan 2001, "A Practical Model for
// Subsurface Light Transport"
// Jensen and Buhler 2002, "A Rapid Hierarchical Rendering Technique for
// Translucent Materials"
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

#include "brdflut/dipole.h"
#include "brdflut/dipole_integrals.h"
#include "brdflut/error.h"
#include "brdflut/math.h"
#include "brdflut/random.h"
#include "tables/checks.h"
#include "tables/registry.h"

namespace brdflut {
namespace dipole_family {  // this family's own names, apart from the other families' in a unity build
namespace {

// Estimated relative error of a value computed by a short closed form
// (a few exp, sqrt and log1p calls): a generous count of double roundings.
constexpr double kClosedFormRelError = 32.0 * std::numeric_limits<double>::epsilon();

constexpr double kRadiusDomainMax = 1e6;

const char* kModelName = "dipole diffusion (Jensen et al. 2001)";
const char* kDefaultMaterial = "skin1";

// "r,g,b": three finite numbers >= 0 (coefficients in 1/mm).
std::array<double, 3> parse_coefficients(const std::string& option, const std::string& s) {
    std::array<double, 3> out{};
    std::size_t start = 0;
    for (int c = 0; c < 3; ++c) {
        const std::size_t comma = s.find(',', start);
        if ((c < 2) != (comma != std::string::npos))
            throw Error("--" + option + " '" + s + "' is not valid; allowed: r,g,b, three numbers >= 0 in 1/mm");
        const std::string part = s.substr(start, c < 2 ? comma - start : std::string::npos);
        std::size_t used = 0;
        double v = -1.0;
        try {
            v = std::stod(part, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (part.empty() || used != part.size() || !std::isfinite(v) || v < 0.0)
            throw Error("--" + option + " '" + s + "' is not valid; allowed: r,g,b, three numbers >= 0 in 1/mm");
        out[static_cast<std::size_t>(c)] = v;
        start = comma + 1;
    }
    return out;
}

ModelOption eta_option() {
    return {"eta",
            "dipole: relative index n_medium / n_outside, a number; allowed 1 to 3 with --fdr fit, "
            "(0, 10] with --fdr exact",
            "1.3",
            {}};
}

ModelOption fdr_option() {
    return {"fdr",
            "dipole: diffuse Fresnel reflectance F_dr: the Egan-Hilgeman fit Jensen uses, or the exact "
            "hemispherical average of the dielectric Fresnel reflectance from inside",
            "fit",
            {"fit", "exact"}};
}

std::vector<std::string> material_names() {
    std::vector<std::string> v;
    for (const MeasuredMaterial& m : measured_materials()) v.emplace_back(m.name);
    return v;
}

// The boundary: eta, F_dr and A, from the options.
struct Boundary {
    double eta;
    DiffuseFresnel fdr;
    double F_dr, A;
};

Boundary boundary_from(const TableSettings& s) {
    Boundary b{};
    b.fdr = diffuse_fresnel_from_string(tables::param(s, "fdr"));
    b.eta = tables::parse_number("eta", tables::param(s, "eta"));
    validate_dipole_eta(b.eta, b.fdr);
    b.F_dr = diffuse_fresnel_reflectance(b.eta, b.fdr);
    b.A = dipole_boundary_term(b.F_dr);
    return b;
}

nlohmann::json boundary_json(const Boundary& b) {
    return {{"model", kModelName},
            {"eta", b.eta},
            {"eta_meaning", "n_medium / n_outside"},
            {"fdr", to_string(b.fdr)},
            {"F_dr", b.F_dr},
            {"F_dr_formula", b.fdr == DiffuseFresnel::fit
                                 ? "-1.440/eta^2 + 0.710/eta + 0.668 + 0.0636 eta (Egan-Hilgeman)"
                                 : "2 * integral of F(mu, 1/eta) mu dmu (dielectric Fresnel from inside)"},
            {"A", b.A}};
}

nlohmann::json closed_form_method(const std::string& rule) {
    return {{"name", "closed_form"}, {"rule", rule}, {"relative_error", kClosedFormRelError}};
}

double closed_form_error(double v) { return kClosedFormRelError * std::abs(v); }

// ---------------------------------------------------------------- evaluators

class ProfileEvaluator final : public TexelEvaluator {
public:
    explicit ProfileEvaluator(double A) : A_(A) {}
    TexelValue evaluate(const double* c, std::uint64_t) const override {
        const double r = c[0], albedo = c[1];
        const Dipole d = Dipole::from_albedo(albedo, A_);
        TexelValue out;
        out.value[0] = d.profile(r);
        out.value[1] = d.cdf(r);
        out.error[0] = closed_form_error(out.value[0]);
        out.error[1] = closed_form_error(out.value[1]);
        return out;
    }

private:
    double A_;
};

class TotalEvaluator final : public TexelEvaluator {
public:
    TotalEvaluator(double A, const TableSettings& s)
        : A_(A), mc_(s.method == Method::monte_carlo), samples_(s.samples), seed_(s.seed) {}
    TexelValue evaluate(const double* c, std::uint64_t texel) const override {
        const double albedo = c[0];
        TexelValue out;
        if (mc_) {
            const Estimate<1> e =
                dipole_total_reflectance_mc(Dipole::from_albedo(albedo, A_), samples_, mix_seed(seed_, texel));
            out.value[0] = e.value[0];
            out.error[0] = tables::kMcErrorSigmas * e.error[0];
        } else {
            out.value[0] = dipole_total_reflectance(albedo, A_);
            out.error[0] = closed_form_error(out.value[0]);
        }
        return out;
    }

private:
    double A_;
    bool mc_;
    long long samples_;
    std::uint64_t seed_;
};

class InverseEvaluator final : public TexelEvaluator {
public:
    explicit InverseEvaluator(double A) : A_(A) {}
    TexelValue evaluate(const double* c, std::uint64_t) const override {
        TexelValue out;
        out.value[0] = dipole_albedo_from_reflectance(c[0], A_, &out.error[0]);
        return out;
    }

private:
    double A_;
};

class RgbProfileEvaluator final : public TexelEvaluator {
public:
    explicit RgbProfileEvaluator(std::array<Dipole, 3> d) : d_(d) {}
    TexelValue evaluate(const double* c, std::uint64_t) const override {
        TexelValue out;
        for (int k = 0; k < 3; ++k) {
            out.value[k] = d_[static_cast<std::size_t>(k)].profile(c[0]);
            out.error[k] = closed_form_error(out.value[k]);
        }
        return out;
    }

private:
    std::array<Dipole, 3> d_;
};

// ----------------------------------------------------------------- axes

AxisSpec radius_axis() {
    return {Axis{"radius", 1e-3, 64.0, 128, Placement::center, Warp::log}, 0.0, kRadiusDomainMax,
            "r: distance on the surface from the point of entry, in reduced mean free paths "
            "1/sigma_t'"};
}

AxisSpec radius_mm_axis() {
    return {Axis{"radius", 1e-3, 100.0, 256, Placement::center, Warp::log}, 0.0, kRadiusDomainMax,
            "r: distance on the surface from the point of entry, in mm"};
}

AxisSpec albedo_axis() {
    return {Axis{"albedo", 0.0, 1.0, 128, Placement::center, Warp::linear}, 0.0, 1.0,
            "a' = sigma_s' / (sigma_s' + sigma_a): reduced scattering albedo"};
}

AxisSpec reflectance_axis() {
    // The total reflectance rises from 0 at a' = 0 to exactly 1 at a' = 1
    // whatever eta and F_dr: (1/2)(1 + e^0) e^0. So [0, 1] is all of it.
    return {Axis{"reflectance", 0.0, 1.0, 128, Placement::center, Warp::linear}, 0.0, 1.0,
            "total diffuse reflectance R; 1 (the total at albedo 1, for any eta) is the largest "
            "reachable"};
}

TableDefinition base(std::string id, std::string description, std::vector<AxisSpec> axes,
                     std::vector<std::string> channels) {
    TableDefinition d;
    d.id = std::move(id);
    d.description = std::move(description);
    d.axes = std::move(axes);
    d.channels = std::move(channels);
    d.options = {eta_option(), fdr_option()};
    return d;
}

}  // namespace
}  // namespace dipole_family

void register_dipole_family(FamilyEntries& family) {
    using namespace dipole_family;
    family.families.push_back(
        {"", "Subsurface scattering: the dipole",
        "The dipole diffusion model of Jensen et al. 2001: the diffuse reflectance profile R_d(r), its "
        "radial CDF for importance sampling radii, the total diffuse reflectance (a'/2)(1 + e^(-(4/3) A "
        "sqrt(3(1 - a')))) e^(-sqrt(3(1 - a'))) and its inverse (solved by safeguarded Newton, as Jensen "
        "and Buhler 2002), in reduced mean free paths or, for the measured materials of the paper "
        "(`--material`, or `--sigma-a` and `--sigma-s`), in millimetres per channel. F_dr is the "
        "Egan-Hilgeman fit of the paper (`--fdr fit`, 1 <= eta <= 3) or the exact hemispherical average "
        "of the interface's Fresnel reflectance from inside (`--fdr exact`). The values are closed forms "
        "evaluated in double."});
    std::vector<TableDefinition>& out = family.tables;
    // The boundary term of the default settings, which verify's checks use.
    const double A = boundary_from(default_settings(base("", "", {}, {}))).A;
    {
        TableDefinition d = base(
            "dipole_profile",
            "Dipole diffuse reflectance profile R_d(r) and its radial CDF, r in reduced mean free paths",
            {radius_axis(), albedo_axis()},
            {"R_d(r): diffuse reflectance per unit area, in units of sigma_t'^2 (per squared reduced "
             "mean free path)",
             "CDF(r): (integral of 2 pi r' R_d(r') dr' over [0, r]) / total diffuse reflectance; "
             "at albedo 0 the limit albedo -> 0"});
        d.prepare = [](const TableSettings& s) {
            const Boundary b = boundary_from(s);
            PreparedTable p;
            p.evaluator = std::make_unique<ProfileEvaluator>(b.A);
            p.model = boundary_json(b);
            p.model["units"] = "sigma_t' = 1: radius in 1/sigma_t', sigma_s' = a', sigma_a = 1 - a'";
            p.method = closed_form_method(
                "R_d by the dipole formula; CDF by the closed-form integral of each source, "
                "2 pi z [e^(-s_tr z)/z - e^(-s_tr d)/d], evaluated with expm1/log1p");
            return p;
        };
        d.checks = {
            {"CDF x total vs the numerical integral of 2 pi r R_d over [0, r]", 1e-9,
             [A](const TexelEvaluator& e) {
                 return tables::worst_error(
                     e, tables::grid_points({1e-3, 0.1, 1.0, 10.0, 64.0}, {0.1, 0.5, 0.9, 1.0}),
                     [A](const TexelValue& v, const auto& p) {
                         const Dipole dip = Dipole::from_albedo(p[1], A);
                         return v.value[1] * dip.total_reflectance() -
                                dipole_reflectance_quadrature(dip, p[0], 1e-13).value[0];
                     });
             }},
        };
        out.push_back(std::move(d));
    }
    {
        TableDefinition d = base("dipole_total", "Dipole total diffuse reflectance over the reduced albedo",
                                 {albedo_axis()},
                                 {"R_total: integral of 2 pi r R_d(r) dr over [0, inf) = (a'/2)(1 + "
                                  "e^(-(4/3) A sqrt(3(1 - a')))) e^(-sqrt(3(1 - a')))"});
        d.supports_monte_carlo = true;
        d.prepare = [](const TableSettings& s) {
            const Boundary b = boundary_from(s);
            PreparedTable p;
            p.evaluator = std::make_unique<TotalEvaluator>(b.A, s);
            p.model = boundary_json(b);
            p.method = s.method == Method::monte_carlo
                           ? tables::monte_carlo_method(
                                 "r from the mixture of z/(r + z)^2, z = z_r and z_v, weight 2 pi r R_d(r)/pdf", s)
                           : closed_form_method("(a'/2)(1 + e^(-(4/3) A sqrt(3(1 - a')))) e^(-sqrt(3(1 - a')))");
            return p;
        };
        d.checks = {
            {"total vs the numerical integral of 2 pi r R_d(r)", 1e-9,
             [A](const TexelEvaluator& e) {
                 return tables::worst_over(e, tables::points_1d({0.0, 0.01, 0.3, 0.7, 0.95, 0.999, 1.0}), 0,
                                           [A](const auto& p) {
                                               return dipole_reflectance_quadrature(Dipole::from_albedo(p[0], A),
                                                                                    HUGE_VAL, 1e-12)
                                                   .value[0];
                                           });
             }},
        };
        out.push_back(std::move(d));
    }
    {
        TableDefinition d = base("dipole_albedo_inverse",
                                 "Reduced albedo a' whose dipole total diffuse reflectance is the given value",
                                 {reflectance_axis()},
                                 {"a': the reduced albedo with total diffuse reflectance R (inverse of "
                                  "dipole_total)"});
        d.prepare = [](const TableSettings& s) {
            const Boundary b = boundary_from(s);
            PreparedTable p;
            p.evaluator = std::make_unique<InverseEvaluator>(b.A);
            p.model = boundary_json(b);
            p.method = {{"name", "root_finding"},
                        {"rule", "Newton on s = sqrt(3(1 - a')) safeguarded by bisection on [0, sqrt(3)], "
                                 "to the last bits; error per value: distance to the root by one more "
                                 "Newton step plus rounding"}};
            return p;
        };
        d.checks = {
            {"total(inverse(R)) vs R", 1e-12,
             [A](const TexelEvaluator& e) {
                 return tables::worst_error(e, tables::points_1d({0.0, 0.05, 0.3, 0.6, 0.9, 0.999}),
                                            [A](const TexelValue& v, const auto& p) {
                                                return dipole_total_reflectance(v.value[0], A) - p[0];
                                            });
             }},
        };
        out.push_back(std::move(d));
    }
    {
        TableDefinition d = base(
            "dipole_profile_rgb",
            "Dipole R_d(r) per colour channel for a measured material or given coefficients, r in mm",
            {radius_mm_axis()},
            {"R_d(r) of the red channel, 1/mm^2", "R_d(r) of the green channel, 1/mm^2",
             "R_d(r) of the blue channel, 1/mm^2"});
        d.options.push_back({"material",
                             "dipole_profile_rgb: measured coefficients of Jensen et al. 2001 (eta 1.3)",
                             kDefaultMaterial, material_names()});
        d.options.push_back({"sigma-s",
                             "dipole_profile_rgb: reduced scattering sigma_s' as r,g,b in 1/mm, with "
                             "--sigma-a, instead of --material",
                             "", {}});
        d.options.push_back({"sigma-a",
                             "dipole_profile_rgb: absorption sigma_a as r,g,b in 1/mm, with --sigma-s, "
                             "instead of --material",
                             "", {}});
        d.prepare = [](const TableSettings& s) {
            const Boundary b = boundary_from(s);
            const std::string& material = tables::param(s, "material");
            const std::string& ss = tables::param(s, "sigma-s");
            const std::string& sa = tables::param(s, "sigma-a");
            std::array<double, 3> sigma_s{}, sigma_a{};
            std::string source;
            if (!ss.empty() || !sa.empty()) {
                if (ss.empty() || sa.empty())
                    throw Error("--sigma-s and --sigma-a go together; give both as r,g,b in 1/mm");
                // The option always holds a value; only a non-default one conflicts.
                if (material != kDefaultMaterial)
                    throw Error("--material '" + material +
                                "' and --sigma-s/--sigma-a both give the coefficients; allowed: one of them");
                sigma_s = parse_coefficients("sigma-s", ss);
                sigma_a = parse_coefficients("sigma-a", sa);
                for (std::size_t c = 0; c < 3; ++c)
                    if (!(sigma_s[c] + sigma_a[c] > 0.0))
                        throw Error("--sigma-s and --sigma-a are both 0 in channel " + std::to_string(c) +
                                    "; allowed: sigma_s' + sigma_a > 0 in every channel");
                source = "custom";
            } else {
                const MeasuredMaterial& m = find_measured_material(material);
                sigma_s = m.sigma_s_prime;
                sigma_a = m.sigma_a;
                source = m.name;
            }
            std::array<Dipole, 3> dipoles{Dipole(sigma_s[0], sigma_a[0], b.A), Dipole(sigma_s[1], sigma_a[1], b.A),
                                          Dipole(sigma_s[2], sigma_a[2], b.A)};
            PreparedTable p;
            p.evaluator = std::make_unique<RgbProfileEvaluator>(dipoles);
            p.model = boundary_json(b);
            p.model["material"] = source;
            if (source != "custom")
                p.model["coefficients_source"] = "Jensen et al. 2001, Figure 5";
            p.model["sigma_s_prime_per_mm"] = sigma_s;
            p.model["sigma_a_per_mm"] = sigma_a;
            p.model["units"] = "radius in mm, R_d in 1/mm^2";
            p.method = closed_form_method("R_d by the dipole formula, per channel");
            return p;
        };
        // Each channel's profile integrated over the plane, 2 pi integral of
        // r R_d(r) dr in ln(r) from 1e-9 mm (below which it adds < 1e-15)
        // to 1e4 mm (past which the profile of the default material is
        // below e^-2000), against the closed-form total reflectance.
        d.checks = {
            {"2 pi integral of r R_d(r) dr vs the closed-form total reflectance (default material)", 1e-10,
             [A](const TexelEvaluator& e) {
                 const MeasuredMaterial& m = find_measured_material(kDefaultMaterial);
                 AdaptiveOptions opt;
                 opt.abs_tol = 1e-13;
                 opt.max_intervals = 4000;
                 opt.rule = KronrodRule::k31;
                 const Estimate<3> total = integrate_adaptive_panels<3>(
                     [&](double x) {
                         const double r = std::exp(x);
                         const TexelValue v = e.evaluate(&r, 0);
                         return std::array<double, 3>{kTwoPi * r * r * v.value[0], kTwoPi * r * r * v.value[1],
                                                      kTwoPi * r * r * v.value[2]};
                     },
                     std::log(1e-9), std::log(1e4), 64, opt);
                 tables::CheckResult r{0.0, ""};
                 for (std::size_t c = 0; c < 3; ++c) {
                     const double want = Dipole(m.sigma_s_prime[c], m.sigma_a[c], A).total_reflectance();
                     const double err = std::abs(total.value[c] - want);
                     if (!(err < r.first)) r = {err, std::string("channel ") + "RGB"[c] + " of " + m.name};
                 }
                 return r;
             }},
        };
        out.push_back(std::move(d));
    }
}

}  // namespace brdflut
