// Unreal Engine's legacy cloth lobe (brdflut/cloth_invggx.h): the inverted
// GGX distribution with the cloth visibility, its albedo and Fresnel moment
// through the generic lobe path (generic_lobe.h), from the BRDF alone.
#include <cmath>
#include <memory>

#include "brdflut/cloth_invggx.h"
#include "brdflut/random.h"
#include "tables/checks.h"
#include "tables/registry.h"

namespace brdflut {
namespace cloth_family {  // this family's own names, apart from the other families' in a unity build
namespace {

// With an honest estimate below it and float rounding, every stored value
// is within 1e-7 of the integral.
constexpr double kTableTolerance = 1e-8;
constexpr tables::Tolerances kTolerances = tables::quadrature_tolerances(kTableTolerance);

// The weights of the two moments: 1 and (1 - v.h)^5.
constexpr std::array<MomentWeight, 2> kWeights = {MomentWeight{moment_weight::one},
                                                   MomentWeight{moment_weight::schlick}};

const char* kRule =
    "generic lobe path (generic_lobe.h): wi in polar coordinates (theta, psi) about the normal, adaptive "
    "Gauss-Kronrod (10,21) in both; error per value: QUADPACK estimate plus the integrated inner estimates";

class ClothEvaluator final : public TexelEvaluator {
public:
    explicit ClothEvaluator(const TableSettings& s)
        : mc_(s.method == Method::monte_carlo), samples_(s.samples), seed_(s.seed),
          abs_tol_(kTolerances.at(s.quality)) {}
    TexelValue evaluate(const double* c, std::uint64_t texel) const override {
        TexelValue out;
        const InvGgxClothLobe lobe(c[1]);
        Estimate<2> e;
        if (mc_) {
            e = generic_moments_mc<2>(lobe, c[0], kWeights, samples_, mix_seed(seed_, texel));
        } else {
            GenericOptions opt;
            opt.abs_tol = abs_tol_;
            e = generic_moments<2>(lobe, c[0], kWeights, opt);
        }
        const double scale = mc_ ? tables::kMcErrorSigmas : 1.0;
        out.value = {e.value[0], e.value[1], 0.0, 0.0};
        out.error = {scale * e.error[0], scale * e.error[1], 0.0, 0.0};
        out.evaluations = e.evaluations;
        return out;
    }

private:
    bool mc_;
    long long samples_;
    std::uint64_t seed_;
    double abs_tol_;
};

// Both moments by a product Gauss-Legendre rule over (mu_i, phi), composite
// on [0, 1/2, 1] x [0, pi/2, pi] with 40 points a panel: an independent
// rule for the smooth lobes of alpha >= 0.3.
std::array<double, 2> moments_by_product_rule(double mu_o, double alpha) {
    const InvGgxClothLobe lobe(alpha);
    const double sin_o = std::sqrt((1.0 - mu_o) * (1.0 + mu_o));
    const Vec3 wo{sin_o, 0.0, mu_o};
    const GaussLegendre& g = gauss_legendre(40);
    std::array<double, 2> sum{};
    for (double mu_a : {0.0, 0.5})
        for (double phi_a : {0.0, 0.5 * kPi})
            for (std::size_t i = 0; i < g.x.size(); ++i)
                for (std::size_t j = 0; j < g.x.size(); ++j) {
                    const double mu = mu_a + 0.25 * (1.0 + g.x[i]);
                    const double phi = phi_a + 0.25 * kPi * (1.0 + g.x[j]);
                    const double s = std::sqrt((1.0 - mu) * (1.0 + mu));
                    const Vec3 wi{s * std::cos(phi), s * std::sin(phi), mu};
                    const Vec3 h{wo.x + wi.x, wo.y + wi.y, wo.z + wi.z};
                    const double oh = dot(wo, h) / std::sqrt(dot(h, h));
                    // Twice: phi in [-pi, 0] mirrors [0, pi].
                    const double w = 2.0 * 0.25 * g.w[i] * 0.25 * kPi * g.w[j] * lobe.f(wo, wi) * mu;
                    sum[0] += w;
                    sum[1] += w * std::pow(1.0 - oh, 5);
                }
    return sum;
}

}  // namespace
}  // namespace cloth_family

void register_cloth_family(FamilyEntries& family) {
    using namespace cloth_family;
    family.families.push_back(
        {"", "Unreal's legacy cloth",
         "The cloth lobe of Unreal Engine's Cloth shading model without Substrate: the inverted GGX "
         "distribution D = (1 + 4 a2^2 / d^2) / (pi (1 + 4 a2)), d = (n.h)^2 (1 - a2) + a2, a2 = alpha^2 "
         "(D_InvGGX), with the cloth visibility V = 1/(4 (mu_i + mu_o - mu_i mu_o)) (Vis_Cloth), f = D V, no "
         "Fresnel. The table holds its albedo E and its Fresnel moment F (f weighted by (1 - v.h)^5), the two "
         "channels of Unreal's legacy cloth energy texture, through the generic lobe path from the BRDF "
         "alone. At alpha = 1, D = 1/pi and E(mu) = (1/(1 - mu) + mu ln(mu)/(1 - mu)^2)/2."});
    TableDefinition d;
    d.id = "cloth_invggx_moments";
    d.description = "Unreal's legacy cloth (D_InvGGX, Vis_Cloth): albedo E and Fresnel moment F over (mu, alpha)";
    d.axes = {tables::cos_theta_axis(32), tables::alpha_axis(32)};
    d.channels = {"E: integral of f cos(theta_i) dw_i", "F: integral of f (1 - v.h)^5 cos(theta_i) dw_i"};
    d.supports_monte_carlo = true;
    // About a millisecond a texel: left out of identify's coarse search.
    d.searched_by_identify = false;
    d.prepare = [](const TableSettings& s) {
        PreparedTable p;
        p.evaluator = std::make_unique<ClothEvaluator>(s);
        p.model = {{"brdf", "Unreal legacy cloth: D_InvGGX(alpha^2, n.h) Vis_Cloth(mu_o, mu_i), no Fresnel"},
                   {"distribution", "(1 + 4 a2^2 / d^2) / (pi (1 + 4 a2)), d = (n.h)^2 (1 - a2) + a2, a2 = alpha^2"},
                   {"visibility", "1 / (4 (mu_i + mu_o - mu_i mu_o))"}};
        p.method = s.method == Method::monte_carlo
                       ? tables::monte_carlo_method("cosine-weighted hemisphere", s)
                       : tables::quadrature_method(kRule, kTolerances.at(s.quality));
        return p;
    };
    d.checks.push_back({"E at alpha = 1 vs (1/(1 - mu) + mu ln(mu)/(1 - mu)^2)/2 (D = 1/pi)", kTableTolerance + 1e-12,
                        [](const TexelEvaluator& e) {
                            return tables::worst_over(e, tables::grid_points({0.0, 0.05, 0.3, 0.7, 0.95, 1.0}, {1.0}),
                                                      0, [](const auto& p) { return inv_ggx_cloth_albedo_alpha_one(p[0]); });
                        }});
    for (int ch : {0, 1})
        d.checks.push_back({ch == 0 ? "E vs a product Gauss-Legendre rule over (mu_i, phi)"
                                    : "F vs a product Gauss-Legendre rule over (mu_i, phi)",
                            kTableTolerance + 1e-10, [ch](const TexelEvaluator& e) {
                                return tables::worst_over(
                                    e, tables::grid_points({0.2, 0.6, 0.95}, {0.3, 0.7}), ch, [ch](const auto& p) {
                                        return moments_by_product_rule(p[0], p[1])[static_cast<std::size_t>(ch)];
                                    });
                            }});
    family.tables.push_back(std::move(d));
}

}  // namespace brdflut
