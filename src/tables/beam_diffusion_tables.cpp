// Photon beam diffusion tables in pbrt-v4's BSSRDFTable layout: the radial
// profile 2 pi r Sr over pbrt's 100 albedos and 64 radii, the effective
// albedo rho_eff (the profile's integral over the surface) and its inverse
// (the albedo that gives a target rho_eff), exact by adaptive quadrature or
// by pbrt-v4's own construction (100-point midpoint rules, Catmull-Rom
// integration and inversion) for comparison.
//
// Habel, Christensen and Jarosz 2013, "Photon Beam Diffusion: A Hybrid Monte
// Carlo Method for Subsurface Scattering"
// Pharr, Jakob and Humphreys, "Physically Based Rendering", 4th edition,
// section 11.4 (mmp/pbrt-v4 src/pbrt/bssrdf.cpp)
#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>

#include "brdflut/beam_diffusion.h"
#include "brdflut/error.h"
#include "brdflut/fresnel.h"
#include "brdflut/math.h"
#include "tables/checks.h"
#include "tables/registry.h"

namespace brdflut {
namespace beam_diffusion_family {  // this family's own names, apart from the other families' in a unity build
namespace {

// The pbrt-v4 commit read for the definitions.
constexpr const char* kPbrtCommit = "5f7a606806a4ac7b939131ded9d7a30ebd02416e";

// Relative tolerance of every integral at each quality.
constexpr tables::Tolerances kTolerances{1e-6, 1e-10, 1e-12};

enum class Construction { exact, pbrt_midpoint, pbrt_fast_exp };

Construction construction_of(const TableSettings& s) {
    const std::string& c = tables::param(s, "construction");
    return c == "pbrt_midpoint" ? Construction::pbrt_midpoint
           : c == "pbrt_fast_exp" ? Construction::pbrt_fast_exp
                                  : Construction::exact;
}

PbrtExp pbrt_exp_of(Construction c) { return c == Construction::pbrt_fast_exp ? PbrtExp::fast : PbrtExp::exact; }

struct Medium {
    double eta, g;
};

Medium medium_of(const TableSettings& s) {
    const Medium m{tables::parse_number("beam_eta", tables::param(s, "beam_eta")),
                   tables::parse_number("beam_g", tables::param(s, "beam_g"))};
    if (!(m.eta >= 1.0 && m.eta <= 3.0))
        throw Error("--beam_eta '" + tables::param(s, "beam_eta") + "' is out of range; allowed: 1 to 3");
    if (!(m.g >= -0.99 && m.g <= 0.99))
        throw Error("--beam_g '" + tables::param(s, "beam_g") + "' is out of range; allowed: -0.99 to 0.99");
    return m;
}

std::vector<ModelOption> options() {
    return {{"beam_eta", "beam diffusion: relative index n_medium / n_outside, 1 to 3 (pbrt-v4's default 1.33)", "1.33", {}},
            {"beam_g", "beam diffusion: Henyey-Greenstein asymmetry, -0.99 to 0.99", "0", {}},
            {"construction",
             "beam diffusion: exact (adaptive quadrature, rho_eff over r to infinity) or pbrt-v4's own "
             "construction: its 100-point midpoint rules, Catmull-Rom rho_eff over its 64 radii and "
             "Catmull-Rom inversion over its 100 albedos, with std::exp (pbrt_midpoint) or pbrt's CPU "
             "FastExp (pbrt_fast_exp)",
             "exact",
             {"exact", "pbrt_midpoint", "pbrt_fast_exp"}}};
}

nlohmann::json model_of(const Medium& m, const TableSettings& s) {
    return {{"model", "photon beam diffusion (Habel et al. 2013) as pbrt-v4 defines it (BeamDiffusionSS + BeamDiffusionMS)"},
            {"units", "lengths in mean free paths: sigma_t = 1, sigma_s = rho, sigma_a = 1 - rho"},
            {"eta", m.eta},
            {"g", m.g},
            {"construction", tables::param(s, "construction")},
            {"engine_source", std::string("mmp/pbrt-v4 src/pbrt/bssrdf.cpp @") + kPbrtCommit + " (ComputeBeamDiffusionBSSRDF)"}};
}

nlohmann::json method_of(Construction c, const TableSettings& s, const std::string& exact_rule) {
    if (c == Construction::exact) {
        nlohmann::json j = {{"name", "quadrature"}, {"rule", exact_rule}, {"relative_tolerance", kTolerances.at(s.quality)}};
        return j;
    }
    return {{"name", "pbrt_construction"},
            {"rule", std::string("pbrt-v4's 100-point midpoint rules in u = 1 - e^(-sigma z), Catmull-Rom rho_eff over "
                                 "its 64 radii, Catmull-Rom inversion over its 100 albedos; exponentials: ") +
                         (c == Construction::pbrt_fast_exp ? "pbrt's CPU FastExp" : "std::exp")},
            {"error", "not estimated (0): the values are pbrt's, not the integrals"}};
}

const char* kProfileRule =
    "Sr_ms: adaptive Gauss-Kronrod (10,21) in z on panels 0, r/2, 2r, 8r, .. up to 50 / sigma'_t; Sr_ss: in "
    "w = sqrt(t - t_c) on panels 0, sqrt(r)/4, sqrt(r), .. up to sqrt(50); r = 0: the limit of 2 pi r Sr_ss "
    "over the exit angle; error: QUADPACK estimate plus a closed-form bound on the part beyond the cut";
const char* kRhoEffRule =
    "the integral of 2 pi r Sr over r: adaptive Gauss-Kronrod (10,21) in ln r on [1e-14, 1] and in 1/r on "
    "[1, inf), each node the profile at a tenth of the tolerance; error: outer estimate plus the integrated "
    "inner estimates plus the part below 1e-14";
const char* kInverseRule =
    "secant steps on rho_eff(x) - target in x = 1 - sqrt(1 - rho), from the Catmull-Rom inverse of rho_eff at "
    "33 nodes; error: the last step plus rho_eff's error over the slope";

AxisSpec radius_axis() {
    return {Axis{"radius", 2.5e-3, 2.5e-3 * std::pow(1.2, 62), 64, Placement::zero_then_endpoints, Warp::log},
            0.0, 1e6,
            "r: distance on the surface from the point of entry in mean free paths (pbrt-v4's optical radius "
            "r sigma_t; its grid 0, 2.5e-3, then times 1.2)"};
}

AxisSpec albedo_axis() {
    return {Axis{"albedo", 0.0, 1.0, 100, Placement::endpoints, Warp::saturating_exp}, 0.0, 1.0,
            "rho = sigma_s / sigma_t: the single-scattering albedo (pbrt-v4's grid (1 - e^(-8 i/99)) / (1 - e^(-8)))"};
}

// The profile at (r, rho): 2 pi r Sr total, single and multiple scattering.
class ProfileEvaluator final : public TexelEvaluator {
public:
    ProfileEvaluator(Medium m, Construction c, double tol) : m_(m), c_(c), tol_(tol) {}
    TexelValue evaluate(const double* p, std::uint64_t) const override {
        const BeamDiffusion b(p[1], m_.g, m_.eta);
        TexelValue out;
        if (c_ == Construction::exact) {
            const Estimate<1> s = b.weighted_ss(p[0], tol_), ms = b.weighted_ms(p[0], tol_);
            out.value = {s.value[0] + ms.value[0], s.value[0], ms.value[0], 0.0};
            out.error = {s.error[0] + ms.error[0], s.error[0], ms.error[0], 0.0};
            out.evaluations = s.evaluations + ms.evaluations;
        } else {
            const double s = b.weighted_ss_midpoint(p[0], 100, pbrt_exp_of(c_));
            const double ms = b.weighted_ms_midpoint(p[0], 100, pbrt_exp_of(c_));
            out.value = {s + ms, s, ms, 0.0};
            out.evaluations = 200;
        }
        return out;
    }

private:
    Medium m_;
    Construction c_;
    double tol_;
};

// pbrt's rho_eff at albedo rho: the Catmull-Rom integral of its midpoint
// profile over its 64 radii, for the total, SS and MS parts.
std::array<double, 3> pbrt_rho_eff(double rho, const Medium& m, PbrtExp e) {
    static const std::vector<double> radii = pbrt_radius_samples(64);
    const BeamDiffusion b(rho, m.g, m.eta);
    std::vector<double> ss, ms, all;
    for (double r : radii) {
        ss.push_back(b.weighted_ss_midpoint(r, 100, e));
        ms.push_back(b.weighted_ms_midpoint(r, 100, e));
        all.push_back(ss.back() + ms.back());
    }
    return {catmull_rom_integral(radii, all), catmull_rom_integral(radii, ss), catmull_rom_integral(radii, ms)};
}

class RhoEffEvaluator final : public TexelEvaluator {
public:
    RhoEffEvaluator(Medium m, Construction c, double tol) : m_(m), c_(c), tol_(tol) {}
    TexelValue evaluate(const double* p, std::uint64_t) const override {
        TexelValue out;
        if (c_ == Construction::exact) {
            const Estimate<2> e = BeamDiffusion(p[0], m_.g, m_.eta).rho_eff(tol_);
            out.value = {e.value[0] + e.value[1], e.value[0], e.value[1], 0.0};
            out.error = {e.error[0] + e.error[1], e.error[0], e.error[1], 0.0};
            out.evaluations = e.evaluations;
        } else {
            const auto v = pbrt_rho_eff(p[0], m_, pbrt_exp_of(c_));
            out.value = {v[0], v[1], v[2], 0.0};
            out.evaluations = 64 * 200;
        }
        return out;
    }

private:
    Medium m_;
    Construction c_;
    double tol_;
};

class InverseEvaluator final : public TexelEvaluator {
public:
    InverseEvaluator(Medium m, Construction c, double tol) {
        if (c == Construction::exact) {
            inverse_ = std::make_unique<RhoEffInverse>(m.g, m.eta, tol);
        } else {
            rho_ = pbrt_rho_samples(100);
            for (double rho : rho_) rho_eff_.push_back(pbrt_rho_eff(rho, m, pbrt_exp_of(c))[0]);
        }
    }
    TexelValue evaluate(const double* p, std::uint64_t) const override {
        TexelValue out;
        if (inverse_) out.value[0] = inverse_->albedo(p[0], &out.error[0]);
        else out.value[0] = catmull_rom_invert(rho_, rho_eff_, p[0]);
        return out;
    }

private:
    std::unique_ptr<RhoEffInverse> inverse_;
    std::vector<double> rho_, rho_eff_;
};

// ------------------------------------------------------------ independent routes

// The integral of f over [a, b] to a relative tolerance: a coarse adaptive
// Gauss-Kronrod (7,15) pass gives its size, a second one its value.
template <class F>
double integrate_relative(F&& f, double a, double b, double rel) {
    AdaptiveOptions opt;
    opt.abs_tol = 0.0;
    opt.max_intervals = 24;
    const double size = std::abs(integrate_adaptive<1>(f, a, b, opt).value[0]);
    opt.abs_tol = std::max(rel * size, 1e-300);
    opt.max_intervals = 4000;
    return integrate_adaptive<1>(f, a, b, opt).value[0];
}

// 2 pi r Sr_ss over the exit angle theta (cos theta = t/d): t = r cot(theta),
// so 2 pi r Sr_ss = 2 pi rho integral over [0, theta_c] of
// e^(-r cot(theta/2)) p(cos theta) T(cos theta) cos(theta) dtheta; plain
// adaptive Gauss-Kronrod (7,15) in theta.
double weighted_ss_over_angle(double r, double rho, const Medium& m) {
    const double theta_c = std::asin(1.0 / m.eta);
    const auto f = [&](double th) {
        const double c = std::cos(th);
        const double w = r > 0.0 ? std::exp(-r / std::tan(0.5 * th)) : 1.0;
        return std::array<double, 1>{w * henyey_greenstein_pbrt(c, m.g) * (1.0 - fresnel_dielectric(c, 1.0 / m.eta)) * c};
    };
    return kTwoPi * rho * integrate_relative(f, 0.0, theta_c, 1e-12);
}

// 2 pi r Sr_ms in pbrt's variable u = 1 - e^(-sigma'_t z) over [0, 1]
// (plain adaptive Gauss-Kronrod (7,15), no panels).
double weighted_ms_over_u(double r, double rho, const Medium& m) {
    const BeamDiffusion b(rho, m.g, m.eta);
    const double sigmap_t = 1.0 - rho * m.g;
    const auto f = [&](double u) {
        const double z = -std::log1p(-u) / sigmap_t;
        return std::array<double, 1>{b.ms_integrand(z, r) / (sigmap_t * (1.0 - u))};
    };
    return kTwoPi * r * integrate_relative(f, 0.0, 1.0, 1e-12);
}

// rho_eff_ss in closed inner form: the r integral of e^(-r cot(theta/2)) is
// tan(theta/2), so rho_eff_ss = 2 pi rho integral of p T cos(theta) tan(theta/2).
double rho_eff_ss_over_angle(double rho, const Medium& m) {
    const double theta_c = std::asin(1.0 / m.eta);
    const auto f = [&](double th) {
        const double c = std::cos(th);
        return std::array<double, 1>{std::tan(0.5 * th) * henyey_greenstein_pbrt(c, m.g) *
                                     (1.0 - fresnel_dielectric(c, 1.0 / m.eta)) * c};
    };
    return kTwoPi * rho * integrate_relative(f, 0.0, theta_c, 1e-12);
}

// rho_eff_ms with the order of integration swapped: over z outside (ln z on
// [1e-12, 1], u = 1 - e^(-sigma'_t (z - 1)) beyond), over r inside (ln r on
// [1e-12, 1], 1/r beyond), adaptive Gauss-Kronrod (7,15).
double rho_eff_ms_swapped(double rho, const Medium& m) {
    const BeamDiffusion b(rho, m.g, m.eta);
    const double sigmap_t = 1.0 - rho * m.g;
    const double lo = std::log(1e-12);
    const auto over_r = [&](double z) {
        const auto near = [&](double y) {
            const double r = std::exp(y);
            return std::array<double, 1>{kTwoPi * r * r * b.ms_integrand(z, r)};
        };
        const auto far = [&](double w) {
            const double r = 1.0 / w;
            return std::array<double, 1>{kTwoPi * r * r * r * b.ms_integrand(z, r)};
        };
        return integrate_relative(near, lo, 0.0, 1e-11) + integrate_relative(far, 0.0, 1.0, 1e-11);
    };
    const auto low = [&](double y) {
        const double z = std::exp(y);
        return std::array<double, 1>{z * over_r(z)};
    };
    const auto high = [&](double u) {
        const double z = 1.0 - std::log1p(-u) / sigmap_t;
        return std::array<double, 1>{over_r(z) / (sigmap_t * (1.0 - u))};
    };
    return integrate_relative(low, lo, 0.0, 1e-10) + integrate_relative(high, 0.0, 1.0, 1e-10);
}

// The prepare step of a table of this family with evaluator E.
template <class E>
std::function<PreparedTable(const TableSettings&)> prepare_with(const char* rule) {
    return [rule](const TableSettings& s) {
        const Medium m = medium_of(s);
        const Construction c = construction_of(s);
        PreparedTable p;
        p.evaluator = std::make_unique<E>(m, c, kTolerances.at(s.quality));
        p.model = model_of(m, s);
        p.method = method_of(c, s, rule);
        return p;
    };
}

// Channel `channel` against an independent route at held-out points (pbrt's
// default medium, eta 1.33 and g = 0), as a relative error within 1e-9.
constexpr Medium kCheckMedium{1.33, 0.0};
template <std::size_t N, class Route>
ClosedFormCheck relative_check(std::string name, std::vector<std::array<double, N>> points, std::size_t channel,
                               Route route) {
    return {std::move(name), 1e-9, [points, channel, route](const TexelEvaluator& e) {
                return tables::worst_error(e, points, [&](const TexelValue& v, const std::array<double, N>& p) {
                    const double x = route(p);
                    return (v.value[channel] - x) / x;
                });
            }};
}

TableDefinition profile_table() {
    TableDefinition d;
    d.id = "beam_diffusion_profile";
    d.description = "Photon beam diffusion profile 2 pi r Sr over pbrt-v4's radii and albedos (BSSRDFTable::profile)";
    d.axes = {radius_axis(), albedo_axis()};
    d.channels = {"2 pi r Sr(r): the profile as pbrt-v4 stores it (Sr = Sr_ss + Sr_ms); at r = 0 its limit",
                  "2 pi r Sr_ss: single scattering", "2 pi r Sr_ms: multiple scattering (photon beam diffusion)"};
    d.options = options();
    d.prepare = prepare_with<ProfileEvaluator>(kProfileRule);
    d.checks = {
        relative_check("2 pi r Sr_ss vs its integral over the exit angle, held-out points (relative)",
                       tables::grid_points({0.0, 1e-3, 0.0137, 0.41, 3.3, 27.0}, {0.37, 1.0}), 1,
                       [](const auto& p) { return weighted_ss_over_angle(p[0], p[1], kCheckMedium); }),
        relative_check("2 pi r Sr_ms vs adaptive quadrature in pbrt's u = 1 - e^(-sigma'_t z), held-out points "
                       "(relative)",
                       tables::grid_points({1e-3, 0.0137, 0.41, 3.3, 27.0}, {0.37, 1.0}), 2,
                       [](const auto& p) { return weighted_ms_over_u(p[0], p[1], kCheckMedium); }),
        {"rho = 0: no scattering, every channel 0", 0.0,
         [](const TexelEvaluator& e) {
             return tables::worst_error(e, tables::grid_points({0.0, 2.5e-3, 0.3, 5.0}, {0.0}),
                                        [](const TexelValue& v, const auto&) {
                                            return std::abs(v.value[0]) + std::abs(v.value[1]) + std::abs(v.value[2]);
                                        });
         }},
    };
    return d;
}

TableDefinition rho_eff_table() {
    TableDefinition d;
    d.id = "beam_diffusion_rho_eff";
    d.description = "Photon beam diffusion effective albedo rho_eff over pbrt-v4's albedos (BSSRDFTable::rhoEff)";
    d.axes = {albedo_axis()};
    d.channels = {"rho_eff: integral of 2 pi r Sr(r) dr over [0, inf)", "its single-scattering part",
                  "its multiple-scattering part"};
    d.options = options();
    d.prepare = prepare_with<RhoEffEvaluator>(kRhoEffRule);
    d.checks = {
        relative_check("single-scattering part vs the closed r integral over the exit angle (relative)",
                       tables::points_1d({0.11, 0.63, 0.985, 1.0}), 1,
                       [](const auto& p) { return rho_eff_ss_over_angle(p[0], kCheckMedium); }),
        relative_check("multiple-scattering part vs the z and r integrals swapped (relative)",
                       tables::points_1d({0.37, 1.0}), 2,
                       [](const auto& p) { return rho_eff_ms_swapped(p[0], kCheckMedium); }),
        {"rho_eff rises with rho (largest fall between neighbours of 24 albedos)", 0.0,
         [](const TexelEvaluator& e) {
             tables::CheckResult r{0.0, ""};
             double prev = -1.0;
             for (int i = 0; i <= 23; ++i) {
                 const double rho = std::expm1(-8.0 * i / 23.0) / std::expm1(-8.0);
                 const double v = e.evaluate(&rho, 0).value[0];
                 if (!std::isfinite(v)) return tables::CheckResult{HUGE_VAL, "not finite"};
                 if (prev - v >= r.first) r = {std::max(0.0, prev - v), tables::point_text(std::array<double, 1>{rho})};
                 prev = v;
             }
             return r;
         }},
    };
    return d;
}

// The total channel against the sum of the two independent routes.
ClosedFormCheck profile_total_check() {
    return relative_check(
        "2 pi r Sr vs the exit-angle route (single) plus pbrt's u route (multiple), held-out points (relative)",
        tables::grid_points({0.0137, 0.41, 3.3}, {0.37, 1.0}), 0, [](const auto& p) {
            return weighted_ss_over_angle(p[0], p[1], kCheckMedium) + weighted_ms_over_u(p[0], p[1], kCheckMedium);
        });
}

ClosedFormCheck rho_eff_total_check() {
    return relative_check(
        "rho_eff vs the closed single-scattering route plus the swapped multiple-scattering one (relative)",
        tables::points_1d({0.93}), 0,
        [](const auto& p) { return rho_eff_ss_over_angle(p[0], kCheckMedium) + rho_eff_ms_swapped(p[0], kCheckMedium); });
}

// A core table as the pbrt preset holds it: its first channel alone, with
// the preset named in its metadata.
TableDefinition pbrt_table(TableDefinition d, std::string id, std::string description, const std::string& function,
                           ClosedFormCheck check) {
    d.id = std::move(id);
    d.description = std::move(description);
    d.channels.resize(1);
    d.preset = "pbrt";
    d.engine_source = std::string("mmp/pbrt-v4 src/pbrt/bssrdf.cpp @") + kPbrtCommit + " (" + function + ")";
    d.prepare = [prepare = d.prepare](const TableSettings& s) {
        PreparedTable t = prepare(s);
        t.model["preset"] = "pbrt";
        return t;
    };
    d.checks = {std::move(check)};
    return d;
}

}  // namespace
}  // namespace beam_diffusion_family

void register_beam_diffusion_family(FamilyEntries& family) {
    using namespace beam_diffusion_family;
    family.families.push_back(
        {"", "Subsurface scattering: photon beam diffusion (pbrt-v4's BSSRDFTable)",
         "Habel et al. 2013's photon beam diffusion as pbrt-v4 defines it (`BeamDiffusionSS`, `BeamDiffusionMS`, "
         "`ComputeBeamDiffusionBSSRDF` in src/pbrt/bssrdf.cpp), in pbrt-v4's layout: the profile 2 pi r Sr(r) of "
         "a medium with sigma_t = 1 lit by a beam at normal incidence, over its 100 albedos "
         "rho_i = (1 - e^(-8 i/99)) / (1 - e^(-8)) and its 64 radii 0, 2.5e-3, then times 1.2; the effective "
         "albedo rho_eff (the integral of 2 pi r Sr over the surface) and the albedo that gives a target "
         "rho_eff. Sr is the sum of single scattering (Henyey-Greenstein phase, Fresnel transmission leaving "
         "the medium, depths below the critical angle's t_c = r sqrt(eta^2 - 1) cut off) and multiple "
         "scattering (a dipole per real source depth z, weighted by sigma'_t e^(-sigma'_t z), with the "
         "Grosjean D, the Fresnel moment fits, cPhi, cE and the kappa factor). The exact construction "
         "integrates both by adaptive quadrature and rho_eff over r to infinity; `--construction "
         "pbrt_midpoint` (or `pbrt_fast_exp`, with pbrt's CPU FastExp) reproduces pbrt-v4's own tables: "
         "100-point midpoint rules in the exponential sampling variable, Catmull-Rom rho_eff over the 64 "
         "radii (to r = 203) and Catmull-Rom inversion. The checks take other variables: the exit angle for "
         "single scattering (and its r integral in closed form for rho_eff), pbrt's u for multiple "
         "scattering, and the order of the z and r integrals swapped for rho_eff."});
    std::vector<TableDefinition>& out = family.tables;
    out.push_back(profile_table());
    out.push_back(rho_eff_table());
    {
        TableDefinition d;
        d.id = "beam_diffusion_albedo";
        d.description = "Photon beam diffusion: the albedo rho whose effective albedo is rho_eff (pbrt-v4's SubsurfaceFromDiffuse)";
        d.axes = {{Axis{"reflectance", 0.0, 1.0, 64, Placement::endpoints, Warp::linear}, 0.0, 2.0,
                   "rho_eff: the target effective albedo (beyond rho_eff(1), 1.03 at eta = 1.33, rho is clamped to 1)"}};
        d.channels = {"rho with rho_eff(rho) = the target"};
        d.options = options();
        d.prepare = prepare_with<InverseEvaluator>(kInverseRule);
        d.checks = {
            {"round trip: rho_eff of the stored rho (the closed single-scattering route plus the swapped "
             "multiple-scattering one) vs the target",
             1e-9,
             [](const TexelEvaluator& e) {
                 return tables::worst_error(e, tables::points_1d({0.137, 0.5, 0.871}),
                                            [](const TexelValue& v, const auto& p) {
                                                return rho_eff_ss_over_angle(v.value[0], kCheckMedium) +
                                                       rho_eff_ms_swapped(v.value[0], kCheckMedium) - p[0];
                                            });
             }},
        };
        out.push_back(std::move(d));
    }
    // The pbrt preset: BSSRDFTable's profile and rhoEff arrays, one channel
    // each, on its grids (the core tables' layout).
    out.push_back(pbrt_table(profile_table(), "pbrt_bssrdf_profile",
                             "pbrt-v4 BSSRDFTable::profile: 2 pi r Sr over its 64 radii (x) and 100 albedos (rows)",
                             "ComputeBeamDiffusionBSSRDF, BeamDiffusionSS + BeamDiffusionMS", profile_total_check()));
    out.push_back(pbrt_table(rho_eff_table(), "pbrt_bssrdf_rho_eff",
                             "pbrt-v4 BSSRDFTable::rhoEff: the effective albedo over its 100 albedos",
                             "ComputeBeamDiffusionBSSRDF: rhoEff by IntegrateCatmullRom", rho_eff_total_check()));
}

}  // namespace brdflut
