// GGX split-sum and Kulla-Conty albedo tables.
//
// Karis 2013, "Real Shading in Unreal Engine 4" (split-sum approximation)
// Kulla and Conty 2017, "Revisiting Physically Based Shading at Imageworks"
#include <memory>

#include "brdflut/ggx_integrals.h"
#include "brdflut/random.h"
#include "tables/checks.h"
#include "tables/registry.h"
#include "tables/shared_results.h"

namespace brdflut {
namespace ggx_family {  // this family's own names, apart from the other families' in a unity build
namespace {

// Absolute tolerance of the quadrature at each quality.
constexpr tables::Tolerances kTolerances = tables::quadrature_tolerances(kGgxTableTolerance);

const char* kQuadratureRule =
    "adaptive Gauss-Kronrod (15,31) over the half vector in x = ln(tan(theta_h)/alpha) "
    "(across the clipped band from panels of at most 3 units of x; (7,15) in "
    "xi = t^2/(alpha^2+t^2) below t = min(alpha, t_a)), "
    "nested with phi clipped analytically to the upper hemisphere (trapezoidal on the "
    "full circle, Gauss-Kronrod (15,31) in tan(phi/2), or tan(phi/4) when phi reaches "
    "past 152 degrees, on clipped ranges); E_avg: adaptive "
    "Gauss-Kronrod (7,15) in mu (from panels of at most 3 units of ln(mu)); error per "
    "value: QUADPACK estimate plus the integrated inner estimates";
const char* kMcSampler = "GGX visible normals (Heitz 2018)";

nlohmann::json ggx_model(Visibility vis) {
    return {{"brdf", "GGX microfacet, single scattering"},
            {"distribution", "ggx"},
            {"visibility", to_string(vis)},
            {"fresnel", "1"},
            {"roughness", "alpha = perceptual_roughness^2"}};
}

enum class Kind { dfg, albedo, albedo_avg };


class GgxEvaluator final : public TexelEvaluator {
public:
    GgxEvaluator(Kind kind, Visibility vis, const TableSettings& s)
        : kind_(kind), vis_(vis), method_(s.method), samples_(s.samples), seed_(s.seed),
          abs_tol_(kTolerances.at(s.quality)) {}

    TexelValue evaluate(const double* c, std::uint64_t texel) const override {
        TexelValue out;
        const bool mc = method_ == Method::monte_carlo;
        const std::uint64_t seed = mix_seed(seed_, texel);
        if (kind_ == Kind::albedo_avg) {
            const double alpha = c[0];
            const Estimate<1> e = mc ? ggx_albedo_average_mc(alpha, vis_, samples_, seed)
                                     : ggx_albedo_average(alpha, vis_, abs_tol_);
            out.value[0] = e.value[0];
            out.error[0] = mc ? tables::kMcErrorSigmas * e.error[0] : e.error[0];
            out.evaluations = e.evaluations;
            return out;
        }
        const double mu = c[0], alpha = c[1];
        bool computed = true;
        const Estimate<2> e = mc ? ggx_split_sum_mc(mu, alpha, vis_, samples_, seed)
                                 : tables::ggx_split_sum_shared(mu, alpha, vis_, abs_tol_, &computed);
        if (computed) out.evaluations = e.evaluations;
        const double scale = mc ? tables::kMcErrorSigmas : 1.0;
        if (kind_ == Kind::dfg) {
            out.value = {e.value[0], e.value[1], 0.0, 0.0};
            out.error = {scale * e.error[0], scale * e.error[1], 0.0, 0.0};
        } else {
            out.value[0] = e.value[0] + e.value[1];
            // Monte Carlo: the standard error of the sum is at most the sum.
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

TableDefinition make(Kind kind, std::string id, std::string description,
                     std::vector<AxisSpec> axes, std::vector<std::string> channels) {
    TableDefinition d;
    d.id = std::move(id);
    d.description = std::move(description);
    d.axes = std::move(axes);
    d.channels = std::move(channels);
    d.options = {tables::visibility_option({"height_correlated", "separable", "schlick_smith", "smith_joint_approx"})};
    d.supports_monte_carlo = true;
    d.prepare = [kind](const TableSettings& s) {
        const Visibility vis = visibility_from_string(tables::param(s, "visibility"));
        PreparedTable p;
        p.evaluator = std::make_unique<GgxEvaluator>(kind, vis, s);
        p.model = ggx_model(vis);
        p.method = s.method == Method::monte_carlo
                       ? tables::monte_carlo_method(kMcSampler, s)
                       : tables::quadrature_method(kQuadratureRule, kTolerances.at(s.quality));
        return p;
    };
    return d;
}

}  // namespace
}  // namespace ggx_family

double tables::ggx_table_tolerance(Quality q) { return ggx_family::kTolerances.at(q); }

Estimate<2> tables::ggx_split_sum_shared(double mu, double alpha, Visibility vis, double abs_tol, bool* computed) {
    // 262,144 texels at most, ~25 MB.
    static tables::SharedResults<4, Estimate<2>> cache(1 << 18);
    return cache.get({tables::key_bits(mu), tables::key_bits(alpha), tables::key_bits(abs_tol), tables::key_enum(vis)},
                     [&] { return ggx_split_sum(mu, alpha, vis, abs_tol); }, computed);
}

void register_ggx_family(FamilyEntries& family) {
    using namespace ggx_family;
    family.families.push_back(
        {"", "GGX microfacet: split sums and albedo",
        "The single-scattering GGX BRDF (Walter et al. 2007) with F = 1 and the height-correlated Smith "
        "G2 (Heitz 2014); `--visibility separable` takes G1(o) G1(i) and `schlick_smith` Schlick's G1 "
        "with k = alpha/2 (Karis 2013), `smith_joint_approx` Unreal's Vis_SmithJointApprox (the linear "
        "approximation of the height-correlated G2 with which Unreal builds PreintegratedGF). With A = integral of f (1 - (1 - v.h)^5) cos(theta_i) dw_i and B "
        "= integral of f (1 - v.h)^5 cos(theta_i) dw_i an engine computes specular = F0 A + B (the split "
        "sum of Karis 2013); E = A + B is the directional albedo of Kulla-Conty energy compensation, f_ms "
        "= (1 - E(mu_o))(1 - E(mu_i)) / (pi (1 - E_avg)), with E_avg = 2 * integral of E(mu) mu dmu. The "
        "`alpha` axis with the square warp and cell centres has rows uniform in perceptual roughness "
        "sqrt(alpha), as Filament's table. The integrals are hand-reduced (the azimuth in closed form "
        "about the half vector) and held to the generic lobe path by a test."});
    using namespace tables;
    std::vector<TableDefinition>& out = family.tables;
    const std::vector<double> mus{0.5 / 128, 0.01, 0.05, 0.1, 0.25, 0.5, 0.75, 0.9, 1.0};
    const auto alpha_one = grid_points(mus, {1.0});
    const auto mirror = grid_points({0.1, 0.3, 0.6, 1.0}, {1e-8});

    TableDefinition dfg = make(Kind::dfg, "ggx_dfg",
                               "GGX split-sum terms: specular = F0 * R + G (F = 1 inside the integral)",
                               {cos_theta_axis(), alpha_axis()},
                               {"A: integral of f (1 - (1 - v.h)^5) cos(theta_i) dw_i",
                                "B: integral of f (1 - v.h)^5 cos(theta_i) dw_i"});
    dfg.checks = {
        {"A + B at alpha = 1 vs 1 - mu ln(1 + 1/mu)", 1e-8,
         [alpha_one](const TexelEvaluator& e) {
             return worst_error(e, alpha_one, [](const TexelValue& v, const auto& p) {
                 return v.value[0] + v.value[1] - ggx_albedo_alpha_one(p[0]);
             });
         }},
        {"B at alpha = 1e-8 vs mirror limit (1 - mu)^5", 1e-6,
         [mirror](const TexelEvaluator& e) {
             return worst_over(e, mirror, 1, [](const auto& p) { return std::pow(1.0 - p[0], 5); });
         }},
    };
    out.push_back(std::move(dfg));

    TableDefinition albedo = make(Kind::albedo, "ggx_albedo",
                                  "GGX directional albedo E(mu, alpha) = A + B (Kulla-Conty)",
                                  {cos_theta_axis(), alpha_axis()},
                                  {"E: integral of f cos(theta_i) dw_i with F = 1"});
    albedo.checks = {
        {"E at alpha = 1 vs 1 - mu ln(1 + 1/mu)", 1e-8,
         [alpha_one](const TexelEvaluator& e) {
             return worst_over(e, alpha_one, 0, [](const auto& p) { return ggx_albedo_alpha_one(p[0]); });
         }},
        {"E at alpha = 1e-8 vs mirror limit 1", 1e-6,
         [mirror](const TexelEvaluator& e) { return worst_over(e, mirror, 0, [](const auto&) { return 1.0; }); }},
    };
    out.push_back(std::move(albedo));

    TableDefinition avg = make(Kind::albedo_avg, "ggx_albedo_avg",
                               "GGX average albedo E_avg(alpha) = 2 * integral of E(mu) mu dmu",
                               {alpha_axis()}, {"E_avg: 2 * integral of E(mu) mu dmu"});
    avg.checks = {
        {"E_avg at alpha = 1 vs (4/3)(1 - ln 2)", 1e-8,
         [](const TexelEvaluator& e) {
             return worst_over(e, points_1d({1.0}), 0, [](const auto&) { return ggx_albedo_avg_alpha_one(); });
         }},
    };
    out.push_back(std::move(avg));

    const std::pair<std::string, std::string> hc{"visibility", "height_correlated"},
        sep{"visibility", "separable"};
    family.furnace_models.insert(family.furnace_models.end(), {
        {"ggx", "GGX single scattering, height-correlated Smith G2", "ggx_albedo", "ggx_albedo_avg", {hc}, false,
         false, 0},
        {"ggx_separable", "GGX single scattering, separable Smith G1 G1", "ggx_albedo", "ggx_albedo_avg", {sep},
         false, false, 0},
        {"ggx_kulla_conty", "GGX (height-correlated) plus the Kulla-Conty multiple-scattering lobe", "ggx_albedo",
         "ggx_albedo_avg", {hc}, true, true, 1e-4},
    });
}

}  // namespace brdflut
