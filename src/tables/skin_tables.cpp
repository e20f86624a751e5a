// Pre-integrated skin tables (Penner 2011) in Unreal's layout: the diffuse
// light of a curved surface blurred by a diffusion profile, over the wrapped
// N.L and the curvature, per colour channel, for Burley's profile, Jensen's
// dipole and d'Eon and Luebke's sum of Gaussians.
//
// Penner and Borshukov 2011, "Pre-Integrated Skin Shading" (GPU Pro 2)
// d'Eon and Luebke 2007, "Advanced Techniques for Realistic Real-Time Skin
// Rendering" (GPU Gems 3, ch. 14)
#include <algorithm>
#include <cmath>
#include <memory>

#include "brdflut/burley.h"
#include "brdflut/dipole.h"
#include "brdflut/error.h"
#include "brdflut/math.h"
#include "brdflut/random.h"
#include "brdflut/skin.h"
#include "tables/checks.h"
#include "tables/registry.h"

namespace brdflut {
namespace skin_family {  // this family's own names, apart from the other families' in a unity build
namespace {

constexpr tables::Tolerances kTolerances = tables::quadrature_tolerances(1e-10);

class SkinEvaluator final : public TexelEvaluator {
public:
    SkinEvaluator(SkinProfile p, SkinGeometry g, const TableSettings& s)
        : p_(std::move(p)),
          g_(g),
          mc_(s.method == Method::monte_carlo),
          samples_(s.samples),
          seed_(s.seed),
          abs_tol_(kTolerances.at(s.quality)) {}
    TexelValue evaluate(const double* c, std::uint64_t texel) const override {
        TexelValue out;
        const Estimate<3> e = mc_ ? preintegrated_skin_mc(p_, g_, c[0], c[1], samples_, mix_seed(seed_, texel))
                                  : preintegrated_skin(p_, g_, c[0], c[1], abs_tol_);
        for (std::size_t k = 0; k < 3; ++k) {
            out.value[k] = e.value[k];
            out.error[k] = (mc_ ? tables::kMcErrorSigmas : 1.0) * e.error[k];
        }
        out.evaluations = e.evaluations;
        return out;
    }

private:
    SkinProfile p_;
    SkinGeometry g_;
    bool mc_;
    long long samples_;
    std::uint64_t seed_;
    double abs_tol_;
};

// MaterialX's mx_integrate_burley_diffusion: Penner's ring for Burley's
// profile (e^(-r/d) + e^(-r/(3d))) / max(r, 1e-8) by a 32-point midpoint
// rule in x, at radius 1/max(curvature, 0.01); the table's d per channel.
class MaterialxSkinEvaluator final : public TexelEvaluator {
public:
    explicit MaterialxSkinEvaluator(const SkinProfile& p) {
        for (std::size_t c = 0; c < 3; ++c) d_[c] = p[c].scale();
    }
    TexelValue evaluate(const double* c, std::uint64_t) const override {
        TexelValue out;
        const double theta = std::acos(std::clamp(c[0], -1.0, 1.0));
        const double radius = 1.0 / std::max(c[1], 0.01);
        constexpr int kSamples = 32;
        std::array<double, 3> sum_d{}, sum_r{};
        for (int i = 0; i < kSamples; ++i) {
            const double x = -kPi + (i + 0.5) * (2.0 * kPi / kSamples);
            const double dist = radius * std::abs(2.0 * std::sin(0.5 * x));
            for (std::size_t k = 0; k < 3; ++k) {
                const double R = (std::exp(-dist / d_[k]) + std::exp(-dist / (3.0 * d_[k]))) / std::max(dist, 1e-8);
                sum_d[k] += R * std::max(std::cos(theta + x), 0.0);
                sum_r[k] += R;
            }
        }
        for (std::size_t k = 0; k < 3; ++k) {
            out.value[k] = sum_d[k] / sum_r[k];
            out.error[k] = 0.0;  // the construction is the value: no integral is claimed
        }
        return out;
    }

private:
    std::array<double, 3> d_{};
};

AxisSpec n_dot_l_axis() {
    // u = N.L * 0.5 + 0.5, Unreal's PreintegratedSkinBxDF coordinate.
    return {Axis{"n_dot_l", -1.0, 1.0, 64, Placement::center, Warp::linear}, -1.0, 1.0,
            "N.L = cos(theta): the light's angle to the surface normal, stored at u = N.L * 0.5 + 0.5"};
}

AxisSpec curvature_axis() {
    return {Axis{"curvature", 0.0, 1.0, 64, Placement::center, Warp::linear}, 0.0, 1e4,
            "1 / radius of the sphere, in 1/mm (the profiles are in mm); 0 is a flat surface"};
}

ModelOption geometry_option() {
    return {"geometry",
            "pre-integrated skin: ring (Penner's formula, the profile along a great circle) or sphere (the "
            "profile over the sphere's area)",
            "ring",
            {"ring", "sphere"}};
}

const std::vector<std::string> kChannels = {"D red: the normalized blurred diffuse light", "D green",
                                            "D blue"};

nlohmann::json geometry_json(SkinGeometry g) {
    return g == SkinGeometry::ring
               ? nlohmann::json("ring: int cos+(theta + x) R(2 rho sin(|x|/2)) dx / int R(2 rho sin(|x|/2)) dx")
               : nlohmann::json("sphere: int cos+ R(|p - q|) dA / int R(|p - q|) dA");
}

const char* kRule =
    "adaptive Gauss-Kronrod (10,21) over the ring angle x (ring) or the polar angle alpha from the point "
    "(sphere, the azimuth in closed form), split where cos(theta -+ x) = 0; ring: numerator and "
    "denominator over a first estimate of the denominator; sphere: over the closed-form reflectance within "
    "r = 2 rho; error per value: the QUADPACK estimates carried through the ratio plus rounding";
const char* kMcSampler =
    "sphere: q from an equal mixture of the profile (radius by its CDF within 2 rho, azimuth uniform) and "
    "the uniform density by area, each sample cos+ at q times the profile's density over the mixture's; "
    "ring: x uniform, ratio of means with its delta-method standard error";

// The checks every skin table has, for its profile and geometry at the
// default settings: a different quadrature at held-out points, the flat
// limit, and the energy identity.
std::vector<ClosedFormCheck> skin_checks(std::function<SkinProfile()> profile, SkinGeometry g) {
    std::vector<ClosedFormCheck> checks;
    checks.push_back(
        {"D vs graded Gauss-Legendre at held-out points", 1e-9, [profile, g](const TexelEvaluator& e) {
             const SkinProfile p = profile();
             tables::CheckResult r{0.0, ""};
             for (const auto& pt : tables::grid_points({-0.31, 0.07, 0.62, 0.97}, {0.013, 0.37, 0.81})) {
                 const TexelValue v = e.evaluate(pt.data(), 0);
                 const std::array<double, 3> want = preintegrated_skin_gauss(p, g, pt[0], pt[1]);
                 for (std::size_t c = 0; c < 3; ++c) {
                     const double err = std::abs(v.value[c] - want[c]);
                     if (!(err <= r.first) || r.second.empty()) r = {err, tables::point_text(pt)};
                 }
             }
             return r;
         }});
    checks.push_back({"D at curvature 1e-6 /mm vs the clamped cosine (flat limit)", 1e-9,
                      [](const TexelEvaluator& e) {
                          tables::CheckResult r{0.0, ""};
                          for (const auto& pt : tables::grid_points({-0.6, 0.2, 0.8, 1.0}, {1e-6})) {
                              const TexelValue v = e.evaluate(pt.data(), 0);
                              for (std::size_t c = 0; c < 3; ++c) {
                                  const double err = std::abs(v.value[c] - std::max(0.0, pt[0]));
                                  if (!(err <= r.first) || r.second.empty()) r = {err, tables::point_text(pt)};
                              }
                          }
                          return r;
                      }});
    const bool ring = g == SkinGeometry::ring;
    checks.push_back(
        {ring ? "energy: integral of D dtheta over [0, pi] vs 1" : "energy: integral of D dN.L over [-1, 1] vs 1/2",
         1e-8, [ring](const TexelEvaluator& e) {
             tables::CheckResult r{0.0, ""};
             for (double k : {0.05, 0.5, 1.0}) {
                 AdaptiveOptions opt;
                 opt.abs_tol = 1e-10;
                 opt.max_intervals = 200;
                 auto f = [&](double t) {
                     const double c[2] = {ring ? std::cos(t) : t, k};
                     const TexelValue v = e.evaluate(c, 0);
                     return std::array<double, 3>{v.value[0], v.value[1], v.value[2]};
                 };
                 const Estimate<3> I = ring ? integrate_adaptive<3>(f, 0.0, kPi, opt)
                                            : integrate_adaptive<3>(f, -1.0, 1.0, opt);
                 for (std::size_t c = 0; c < 3; ++c) {
                     const double err = std::abs(I.value[c] - (ring ? 1.0 : 0.5));
                     if (!(err <= r.first) || r.second.empty())
                         r = {err, "curvature " + std::to_string(k) + ", channel " + "RGB"[c]};
                 }
             }
             return r;
         }});
    return checks;
}

// Jensen et al. 2001's skin1, eta 1.3 with the Egan-Hilgeman F_dr, in mm.
SkinProfile dipole_skin_profile() {
    const MeasuredMaterial& m = find_measured_material("skin1");
    const double A = dipole_boundary_term(diffuse_fresnel_reflectance(1.3, DiffuseFresnel::fit));
    return {RadialProfile::dipole(Dipole(m.sigma_s_prime[0], m.sigma_a[0], A)),
            RadialProfile::dipole(Dipole(m.sigma_s_prime[1], m.sigma_a[1], A)),
            RadialProfile::dipole(Dipole(m.sigma_s_prime[2], m.sigma_a[2], A))};
}

TableDefinition skin_table(std::string id, std::string description) {
    TableDefinition d;
    d.id = std::move(id);
    d.description = std::move(description);
    d.axes = {n_dot_l_axis(), curvature_axis()};
    d.channels = kChannels;
    d.supports_monte_carlo = true;
    // An adaptive integral of a few thousand evaluations a texel: left out
    // of identify's coarse search (see catalogue.h), as the glass averages.
    d.searched_by_identify = false;
    return d;
}

}  // namespace
}  // namespace skin_family

std::array<double, 3> tables::parse_rgb(const std::string& option, const std::string& s, double lo, bool open_lo,
                                        double hi, const std::string& allowed) {
    std::array<double, 3> out{};
    std::size_t start = 0;
    auto bad = [&]() { return Error("--" + option + " '" + s + "' is not valid; allowed: r,g,b, " + allowed); };
    for (std::size_t c = 0; c < 3; ++c) {
        const std::size_t comma = s.find(',', start);
        if ((c < 2) != (comma != std::string::npos)) throw bad();
        const std::string part = s.substr(start, c < 2 ? comma - start : std::string::npos);
        std::size_t used = 0;
        double v = NAN;
        try {
            v = std::stod(part, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (part.empty() || used != part.size() || !std::isfinite(v) || v < lo || (open_lo && v == lo) || v > hi)
            throw bad();
        out[c] = v;
        start = comma + 1;
    }
    return out;
}

std::vector<ModelOption> tables::burley_rgb_options() {
    return {{"surface-albedo", "Burley: the albedo A per channel, r,g,b in (0, 1]", "0.8,0.5,0.3", {}},
            {"dmfp", "Burley: the mean free path l per channel, r,g,b in mm (d = l / s(A))", "1.0,0.5,0.25", {}},
            tables::burley_scaling_option()};
}

tables::BurleyRgb tables::burley_rgb(const TableSettings& s) {
    BurleyRgb b{};
    b.albedo = parse_rgb("surface-albedo", param(s, "surface-albedo"), 0.0, true, 1.0, "three numbers in (0, 1]");
    b.dmfp = parse_rgb("dmfp", param(s, "dmfp"), 0.0, true, 1e3, "three lengths in mm, > 0");
    b.scaling = burley_scaling_from_string(param(s, "scaling"));
    return b;
}

SkinProfile tables::burley_rgb_profile(const BurleyRgb& b) {
    auto one = [&](std::size_t c) {
        return RadialProfile::burley(b.albedo[c], b.dmfp[c] / burley_scaling(b.albedo[c], b.scaling));
    };
    return {one(0), one(1), one(2)};
}

nlohmann::json tables::burley_rgb_model(const BurleyRgb& b) {
    return {{"profile", "Burley normalized diffusion (Christensen and Burley 2015)"},
            {"albedo", b.albedo},
            {"mean_free_path_mm", b.dmfp},
            {"scaling", to_string(b.scaling)}};
}

void register_skin_family(FamilyEntries& family) {
    using namespace skin_family;
    family.families.push_back(
        {"", "Pre-integrated skin",
         "Penner and Borshukov 2011's pre-integrated skin: a sphere of radius 1/curvature lit at angle theta, "
         "its diffuse light cos+ blurred by a diffusion profile R(r) and normalized, D(theta, curvature) per "
         "colour channel, over Unreal's PreIntegratedSkinBRDF coordinates (N.L stored at N.L * 0.5 + 0.5, "
         "curvature in 1/mm). The ring geometry is Penner's formula, int cos+(theta + x) R(2 rho sin(|x|/2)) dx "
         "/ int R(2 rho sin(|x|/2)) dx over x in [-pi, pi]; the sphere geometry blurs over the sphere's area "
         "instead (the azimuth in closed form). Burley's profile is infinite like 1/r at r = 0, which makes "
         "both ring integrals diverge (the ratio tends to cos+ at every curvature, so a midpoint rule such "
         "as MaterialX's 32 samples gives a value that depends on its sample count): its table uses the "
         "sphere, where 1/r is integrable. Profiles: Burley (per-channel albedo and diffuse mean free path), "
         "Jensen's dipole for skin1 (Jensen et al. 2001, eta 1.3) and d'Eon and Luebke 2007's six "
         "Gaussians. The curvature 0 is the clamped cosine; D is normalized, so multiplied by the "
         "profile's albedo it conserves the profile's energy: over the sphere the integral of D dN.L is 1/2, "
         "over the ring the integral of D dtheta on [0, pi] is 1, as for cos+."});
    std::vector<TableDefinition>& out = family.tables;
    {
        TableDefinition d = skin_table(
            "skin_preintegrated_burley",
            "Pre-integrated skin D(N.L, curvature) for Burley's profile, over the sphere, per channel");
        d.options = tables::burley_rgb_options();
        d.options.push_back({"skin-construction",
                             "skin_preintegrated_burley: exact (the sphere, by adaptive quadrature) or materialx "
                             "(MaterialX's mx_integrate_burley_diffusion: Penner's ring by a 32-point midpoint rule "
                             "at radius 1/max(curvature, 0.01), with this table's d)",
                             "exact",
                             {"exact", "materialx"}});
        d.prepare = [](const TableSettings& s) {
            const tables::BurleyRgb b = tables::burley_rgb(s);
            const bool materialx = tables::param(s, "skin-construction") == "materialx";
            if (materialx && s.method == Method::monte_carlo)
                throw Error("--skin-construction materialx is MaterialX's own rule; allowed with it: --method quadrature");
            PreparedTable p;
            if (materialx) p.evaluator = std::make_unique<MaterialxSkinEvaluator>(tables::burley_rgb_profile(b));
            else p.evaluator = std::make_unique<SkinEvaluator>(tables::burley_rgb_profile(b), SkinGeometry::sphere, s);
            p.model = tables::burley_rgb_model(b);
            p.model["geometry"] = materialx ? geometry_json(SkinGeometry::ring) : geometry_json(SkinGeometry::sphere);
            p.model["curvature_unit"] = "1/mm";
            p.model["construction"] = materialx ? "materialx" : "exact";
            if (materialx)
                p.method = {{"name", "materialx_construction"},
                            {"rule", "MaterialX mx_integrate_burley_diffusion (AcademySoftwareFoundation/MaterialX "
                                     "libraries/pbrlib/genglsl/lib/mx_microfacet_diffuse.glsl "
                                     "@cb6e8c9981d616b594aef6aa1dea2f14a7cc99c9): 32-point midpoint rule over the ring, radius "
                                     "1/max(curvature, 0.01), profile (e^(-r/d) + e^(-r/(3d))) / max(r, 1e-8)"},
                            {"error", "not estimated (0): the values are MaterialX's rule, not the integral"}};
            else
                p.method = s.method == Method::monte_carlo ? tables::monte_carlo_method(kMcSampler, s)
                                                           : tables::quadrature_method(kRule, kTolerances.at(s.quality));
            return p;
        };
        const tables::BurleyRgb defaults = tables::burley_rgb(default_settings(d));
        d.checks = skin_checks([defaults] { return tables::burley_rgb_profile(defaults); }, SkinGeometry::sphere);
        out.push_back(std::move(d));
    }
    auto fixed_profile = [&](std::string id, std::string description, std::function<SkinProfile()> profile,
                             nlohmann::json model) {
        TableDefinition d = skin_table(std::move(id), std::move(description));
        d.options = {geometry_option()};
        d.prepare = [profile, model](const TableSettings& s) {
            const SkinGeometry g = skin_geometry_from_string(tables::param(s, "geometry"));
            PreparedTable p;
            p.evaluator = std::make_unique<SkinEvaluator>(profile(), g, s);
            p.model = model;
            p.model["geometry"] = geometry_json(g);
            p.model["curvature_unit"] = "1/mm";
            p.method = s.method == Method::monte_carlo ? tables::monte_carlo_method(kMcSampler, s)
                                                       : tables::quadrature_method(kRule, kTolerances.at(s.quality));
            return p;
        };
        d.checks = skin_checks(profile, SkinGeometry::ring);
        out.push_back(std::move(d));
    };
    fixed_profile("skin_preintegrated_dipole",
                  "Pre-integrated skin D(N.L, curvature) for Jensen's dipole (skin1), per channel", dipole_skin_profile,
                  {{"profile", "dipole diffusion (Jensen et al. 2001), skin1, eta 1.3, F_dr Egan-Hilgeman fit"},
                   {"sigma_s_prime_per_mm", find_measured_material("skin1").sigma_s_prime},
                   {"sigma_a_per_mm", find_measured_material("skin1").sigma_a}});
    nlohmann::json gaussians = nlohmann::json::array();
    for (const SkinGaussian& g : deon_skin_gaussians())
        gaussians.push_back({{"variance_mm2", g.variance}, {"weight_rgb", g.weight}});
    fixed_profile("skin_preintegrated_gaussians",
                  "Pre-integrated skin D(N.L, curvature) for d'Eon and Luebke's six-Gaussian skin profile",
                  deon_skin_profile,
                  {{"profile", "sum of Gaussians e^(-r^2/(2v)) / (2 pi v) (d'Eon and Luebke 2007, skin)"},
                   {"gaussians", gaussians}});
}

}  // namespace brdflut
