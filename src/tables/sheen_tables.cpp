// Charlie sheen albedo table.
//
// Estevez and Kulla 2017, "Production Friendly Microfacet Sheen BRDF"
#include <memory>

#include "brdflut/random.h"
#include "brdflut/sheen_integrals.h"
#include "tables/checks.h"
#include "tables/registry.h"

namespace brdflut {
namespace sheen_family {  // this family's own names, apart from the other families' in a unity build
namespace {

// Absolute tolerance of the quadrature at each quality.
constexpr tables::Tolerances kTolerances = tables::quadrature_tolerances(kSheenAbsTolerance);

const char* kQuadratureRule =
    "closed form over phi (the integrand is rational in cos(phi) at fixed theta_h, clipped "
    "to the upper hemisphere; Gauss-Kronrod (15,31) when mu > 0.98), adaptive Gauss-Kronrod "
    "(7,15) over theta_h in ln(pi/2 - theta_h), split where the clip starts; error per "
    "value: QUADPACK estimate plus the rounding of the closed form and the neglected tails";
const char* kMcSampler = "equal mixture of the uniform hemisphere and reflected Charlie normals";

class SheenEvaluator final : public TexelEvaluator {
public:
    explicit SheenEvaluator(const TableSettings& s)
        : method_(s.method), samples_(s.samples), seed_(s.seed), abs_tol_(kTolerances.at(s.quality)) {}

    TexelValue evaluate(const double* c, std::uint64_t texel) const override {
        TexelValue out;
        const bool mc = method_ == Method::monte_carlo;
        const Estimate<1> e = mc ? sheen_charlie_albedo_mc(c[0], c[1], samples_, mix_seed(seed_, texel))
                                 : sheen_charlie_albedo(c[0], c[1], abs_tol_);
        out.value[0] = e.value[0];
        out.error[0] = (mc ? tables::kMcErrorSigmas : 1.0) * e.error[0];
        out.evaluations = e.evaluations;
        return out;
    }

private:
    Method method_;
    long long samples_;
    std::uint64_t seed_;
    double abs_tol_;
};

}  // namespace
}  // namespace sheen_family

nlohmann::json tables::charlie_sheen_model() {
    return {{"brdf", "Charlie sheen (Estevez and Kulla 2017), no Fresnel"},
            {"distribution", "charlie: (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi)"},
            {"visibility", "neubelt: 1 / (4 (mu_i + mu_o - mu_i mu_o))"},
            {"roughness", "alpha = perceptual_roughness^2"}};
}

void register_sheen_family(FamilyEntries& family) {
    using namespace sheen_family;
    family.families.push_back(
        {"", "Charlie sheen",
        "The albedo of the Charlie distribution D = (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi) "
        "(Estevez and Kulla 2017) with Neubelt's visibility V = 1/(4 (mu_i + mu_o - mu_i mu_o)) (Neubelt "
        "and Pettineo 2013), no Fresnel: Filament's cloth DFG term, alpha = perceptual_roughness^2 "
        "(Filament, KHR_materials_sheen). V is not energy conserving: E grows without bound at grazing "
        "view as alpha goes to 0. The azimuth integral has a closed form at fixed theta_h; what remains "
        "is one adaptive integral, held to the generic lobe path by a test."});
    std::vector<TableDefinition>& out = family.tables;
    TableDefinition d;
    d.id = "sheen_charlie_albedo";
    d.description = "Charlie sheen albedo E(mu, alpha) with Neubelt visibility (Filament's cloth DFG term)";
    d.axes = {tables::cos_theta_axis(), tables::alpha_axis()};
    d.channels = {"E: integral of D_charlie V_neubelt cos(theta_i) dw_i"};
    d.supports_monte_carlo = true;
    d.prepare = [](const TableSettings& s) {
        PreparedTable p;
        p.evaluator = std::make_unique<SheenEvaluator>(s);
        p.model = tables::charlie_sheen_model();
        p.method = s.method == Method::monte_carlo ? tables::monte_carlo_method(kMcSampler, s)
                                                   : tables::quadrature_method(kQuadratureRule, kTolerances.at(s.quality));
        return p;
    };
    // The table's tolerance and 1e-12 for the closed forms' rounding.
    const double tol = kTolerances.standard + 1e-12;
    d.checks = {
        {"E(1, alpha) vs 2^(1 - n/2) / (n + 2), n = 2 + 1/alpha", tol,
         [](const TexelEvaluator& e) {
             return tables::worst_over(e, tables::grid_points({1.0}, {1e-3, 0.05, 0.1, 0.5, 1.0}), 0,
                                       [](const auto& p) { return tables::charlie_albedo_normal(p[1]); });
         }},
        {"E(0, alpha) vs (n/pi)(sqrt(pi)/2) Gamma((n + 1)/2) / Gamma(n/2 + 1)", tol,
         [](const TexelEvaluator& e) {
             return tables::worst_over(e, tables::grid_points({0.0}, {0.25, 0.5, 1.0}), 0,
                                       [](const auto& p) { return tables::charlie_albedo_grazing(p[1]); });
         }},
    };
    out.push_back(std::move(d));
}

}  // namespace brdflut
