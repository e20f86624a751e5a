#include "tables/lobe_table.h"

#include <memory>

#include "brdflut/random.h"
#include "tables/checks.h"
#include "tables/registry.h"

namespace brdflut::tables {
namespace {

// Absolute tolerance of the quadrature at each quality.
constexpr Tolerances kTolerances = quadrature_tolerances(kLobeAbsTolerance);

const char* kQuadratureRule =
    "adaptive Gauss-Kronrod (7,15), split at every kink of the integrand: the phi integral in "
    "closed form where it has one (diffuse, subsurface, Oren-Nayar family), in polar "
    "coordinates about wo for the sheen, over the GTR1 half-vector measure with phi clipped to "
    "the upper hemisphere for the clearcoat (Gauss-Kronrod (15,31) in the GTR1 measure below "
    "the clipped band and in ln(tan(theta_h)) across it; doubling trapezoid on full circles, "
    "Gauss-Kronrod (15,31) in tan(phi/4) on clipped arcs); polynomial parts by exact Gauss-Legendre; "
    "averages over theta_o, the clearcoat's directly over the half vector (GTR1 measure), "
    "wo.h and the azimuth of wo about it (Gauss-Kronrod (15,31), trapezoid on full circles); "
    "error per value: QUADPACK estimate";

std::string mc_sampler(Lobe lobe) {
    return lobe == Lobe::disney_clearcoat ? "GTR1 half vectors (Burley 2012)"
                                          : "cosine-weighted hemisphere";
}

class LobeEvaluator final : public TexelEvaluator {
public:
    LobeEvaluator(Lobe lobe, LobeTableKind kind, const TableSettings& s)
        : lobe_(lobe), kind_(kind), method_(s.method), samples_(s.samples), seed_(s.seed),
          abs_tol_(kTolerances.at(s.quality)) {}

    TexelValue evaluate(const double* c, std::uint64_t texel) const override {
        const bool mc = method_ == Method::monte_carlo;
        const std::uint64_t seed = mix_seed(seed_, texel);
        Estimate<1> e;
        switch (kind_) {
            case LobeTableKind::albedo:
                e = mc ? lobe_albedo_mc(lobe_, c[0], c[1], samples_, seed)
                       : lobe_albedo(lobe_, c[0], c[1], abs_tol_);
                break;
            case LobeTableKind::albedo_1d:
                e = mc ? lobe_albedo_mc(lobe_, c[0], 0.0, samples_, seed)
                       : lobe_albedo(lobe_, c[0], 0.0, abs_tol_);
                break;
            case LobeTableKind::albedo_average:
                e = mc ? lobe_albedo_average_mc(lobe_, c[0], samples_, seed)
                       : lobe_albedo_average(lobe_, c[0], abs_tol_);
                break;
        }
        TexelValue out;
        out.value[0] = e.value[0];
        out.error[0] = mc ? kMcErrorSigmas * e.error[0] : e.error[0];
        out.evaluations = e.evaluations;
        return out;
    }

private:
    Lobe lobe_;
    LobeTableKind kind_;
    Method method_;
    long long samples_;
    std::uint64_t seed_;
    double abs_tol_;
};

// E(1, p) by a second route: at normal incidence every lobe is symmetric
// about the normal, so E(1, p) = 2 pi integral over theta_i of
// f(n, wi(theta_i)) cos sin, with f evaluated pointwise (lobe_brdf), taken
// in x = ln(theta_i) (the clearcoat peaks at theta_i = 0 with width 2 alpha
// >= 0.002) from theta_i = 1e-9, below which the integrand adds < 1e-12.
double normal_incidence_albedo(Lobe lobe, double p) {
    AdaptiveOptions opt;
    opt.abs_tol = 1e-13;
    opt.max_intervals = 4000;
    opt.rule = KronrodRule::k31;
    const Vec3 wo{0.0, 0.0, 1.0};
    return integrate_adaptive_panels<1>(
               [&](double x) {
                   const double t = std::exp(x);
                   const Vec3 wi{std::sin(t), 0.0, std::cos(t)};
                   return std::array<double, 1>{kTwoPi * lobe_brdf(lobe, wo, wi, p) * wi.z * wi.x * t};
               },
               std::log(1e-9), std::log(0.5 * kPi), 48, opt)
        .value[0];
}

ClosedFormCheck normal_incidence_check(Lobe lobe, LobeTableKind kind) {
    const std::vector<double> params = kind == LobeTableKind::albedo_1d ? std::vector<double>{0.0}
                                                                        : std::vector<double>{0.0, 0.5, 1.0};
    // The table's own tolerance, and the reference's (1e-13) with room for rounding.
    return {"E(1, p) vs 2 pi integral of f(n, wi) cos(theta_i) sin(theta_i) dtheta_i (pointwise BRDF)",
            kTolerances.standard + 1e-12, [lobe, kind, params](const TexelEvaluator& e) {
                if (kind == LobeTableKind::albedo_1d)
                    return worst_over(e, points_1d({1.0}), 0,
                                      [lobe](const auto&) { return normal_incidence_albedo(lobe, 0.0); });
                return worst_over(e, grid_points({1.0}, params), 0,
                                  [lobe](const auto& pt) { return normal_incidence_albedo(lobe, pt[1]); });
            }};
}

}  // namespace

TableDefinition lobe_table(Lobe lobe, LobeTableKind kind, std::string id, std::string description,
                           std::vector<AxisSpec> axes, std::string channel, nlohmann::json model) {
    TableDefinition d;
    d.id = std::move(id);
    d.description = std::move(description);
    d.axes = std::move(axes);
    d.channels = {std::move(channel)};
    d.supports_monte_carlo = true;
    if (kind != LobeTableKind::albedo_average) d.checks.push_back(normal_incidence_check(lobe, kind));
    d.prepare = [lobe, kind, model](const TableSettings& s) {
        PreparedTable p;
        p.evaluator = std::make_unique<LobeEvaluator>(lobe, kind, s);
        p.model = model;
        p.method = s.method == Method::monte_carlo
                       ? monte_carlo_method(mc_sampler(lobe), s)
                       : quadrature_method(kQuadratureRule, kTolerances.at(s.quality));
        return p;
    };
    return d;
}

}  // namespace brdflut::tables
