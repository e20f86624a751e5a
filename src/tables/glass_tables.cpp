// Rough dielectric (GGX glass) albedo tables: E_R, E_T and their sum, seen
// from outside (eta = n) and from inside (eta = 1/n) over the same axis of
// the material's index n.
//
// Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces"
#include <memory>

#include "brdflut/glass_integrals.h"
#include "brdflut/random.h"
#include "tables/shared_results.h"
#include "tables/checks.h"
#include "tables/registry.h"

namespace brdflut {
namespace glass_family {  // this family's own names, apart from the other families' in a unity build
namespace {

constexpr tables::Tolerances kTolerances = tables::kGlassTolerances;
static_assert(tables::kGlassTolerances.standard == kGlassTableTolerance);

const char* kQuadratureRule =
    "adaptive Gauss-Kronrod (15,31) over the half vector in x = ln(tan(theta_h)/alpha), split "
    "where a threshold of wo.h (reflection above the horizon, refraction below it, the critical "
    "angle, wo.h = 0) meets phi = 0 or pi or another threshold, and at x = +-1, from panels of at "
    "most 8 units of x ((10,21) on pieces shorter than 1, (7,15) shorter than 0.25), the "
    "first and last piece (to x = -inf, +inf) over v = e^(-|x|), under the map 3u^2 - 2u^3 on each "
    "piece; nested with phi split at the same thresholds and adaptive Gauss-Kronrod (15,31) under "
    "that map in tan(phi/4) on each piece; E_avg: E_R and E_T apart, E_R inside over the same x, "
    "then c = wo.h by adaptive Gauss-Kronrod (15,31) split at sin(theta_h) and the critical c, E_T "
    "and E_R outside over c by (15,31), then the same x split at sin(theta_h) = c (E_R's shared "
    "between the indices of one alpha), each then over the azimuth of "
    "wo about h in tan(psi/4) by adaptive Gauss-Kronrod ((7,15) for E_R, (15,31) for E_T) on its "
    "closed-form domain (E_R on "
    "half of it, the integrand even about pi/2); E_T avg inside by reciprocity from outside, "
    "E_T(1/n) = E_T(n) / n^2; error per value: QUADPACK estimate plus the integrated inner "
    "estimates";
const char* kMcSampler =
    "mixture of GGX visible normals (Heitz 2018; 0.7), normals logistic in ln(tan(theta_h)/alpha) with "
    "scale 2 (0.2) and normals with wo.h = u^4 (0.1), both channels from each normal, weighed by the "
    "mixture's density, the visible normals' density as control variate (regression estimate)";

}  // namespace
}  // namespace glass_family

namespace tables {

nlohmann::json glass_model(Visibility vis, bool inside) {
    return {{"bsdf", "GGX rough dielectric (Walter et al. 2007), single scattering"},
            {"distribution", "ggx"},
            {"visibility", to_string(vis)},
            {"fresnel", "exact unpolarized dielectric, 1 under total internal reflection"},
            {"roughness", "alpha = perceptual_roughness^2"},
            {"side", inside ? "inside: eta = 1/n (light leaves the denser medium)"
                            : "outside: eta = n (light enters the denser medium)"},
            {"convention",
             "energy: E_T includes Walter's eta_o^2 in f_t (the smooth limit of E_R + E_T is 1 on "
             "both sides); a renderer carrying radiance across the interface multiplies E_T by "
             "1/eta^2. Reflected or refracted directions on the wrong side of the macro surface "
             "contribute nothing. At eta = 1 the model still masks the straight path twice: "
             "E_T = G2(wo, -wo)(1 + Lambda(wo))"}};
}

AxisSpec ior_axis(int count) {
    return {Axis{"ior", 1.0, 3.0, count, Placement::center, Warp::ior_z}, 1.0, HUGE_VAL,
            "n: index of refraction of the denser medium over the other (>= 1); outside tables "
            "use eta = n, inside tables eta = 1/n"};
}

Estimate<2> glass_average(double alpha, double n, bool inside, Visibility vis, double abs_tol) {
    // An index below 1 is the other side of the index 1/n: the same eta,
    // through the shared outside transmission of 1/n.
    if (alpha > 0.0 && n > 0.0 && n < 1.0) return glass_average(alpha, 1.0 / n, !inside, vis, abs_tol);
    const double eta = inside ? 1.0 / n : n;
    if (!(alpha > 0.0) || !(n >= 1.0)) return ggx_glass_average(alpha, eta, vis, abs_tol);
    static SharedResults<4, Estimate<1>> transmission(1 << 14);
    bool computed = true;
    Estimate<1> t = transmission.get({key_bits(alpha), key_bits(n), key_bits(abs_tol), key_enum(vis)},
                                     [&] { return ggx_glass_average_transmission_outside(alpha, n, vis, abs_tol); },
                                     &computed);
    if (!computed) t.evaluations = 0;
    return ggx_glass_average_of_parts(ggx_glass_average_reflection(alpha, eta, vis, abs_tol), t, eta);
}

}  // namespace tables

namespace glass_family {  // this family's own names, apart from the other families' in a unity build
namespace {

enum class Kind { directional, average };

class GlassEvaluator final : public TexelEvaluator {
public:
    GlassEvaluator(Kind kind, bool inside, Visibility vis, const TableSettings& s)
        : kind_(kind), inside_(inside), vis_(vis), mc_(s.method == Method::monte_carlo),
          samples_(s.samples), seed_(s.seed), abs_tol_(kTolerances.at(s.quality)) {}

    TexelValue evaluate(const double* c, std::uint64_t texel) const override {
        const std::uint64_t seed = mix_seed(seed_, texel);
        const bool avg = kind_ == Kind::average;
        const double mu = avg ? 0.0 : c[0], alpha = avg ? c[0] : c[1], n = avg ? c[1] : c[2];
        const double eta = inside_ ? 1.0 / n : n;
        Estimate<2> e;
        if (avg)
            e = mc_ ? ggx_glass_average_mc(alpha, eta, vis_, samples_, seed)
                    : tables::glass_average(alpha, n, inside_, vis_, abs_tol_);
        else
            e = mc_ ? ggx_glass_mc(mu, alpha, eta, vis_, samples_, seed) : ggx_glass(mu, alpha, eta, vis_, abs_tol_);
        const double scale = mc_ ? tables::kMcErrorSigmas : 1.0;
        TexelValue out;
        out.value = {e.value[0], e.value[1], e.value[0] + e.value[1], 0.0};
        out.error = {scale * e.error[0], scale * e.error[1], scale * (e.error[0] + e.error[1]), 0.0};
        out.evaluations = e.evaluations;
        return out;
    }

private:
    Kind kind_;
    bool inside_;
    Visibility vis_;
    bool mc_;
    long long samples_;
    std::uint64_t seed_;
    double abs_tol_;
};

TableDefinition make(Kind kind, bool inside, std::string id, std::string description, std::vector<AxisSpec> axes) {
    TableDefinition d;
    d.id = std::move(id);
    d.description = std::move(description);
    d.axes = std::move(axes);
    const std::string avg = kind == Kind::average ? "2 * integral over mu of mu * " : "";
    d.channels = {"E_R: " + avg + "integral of f_r |cos(theta_i)| dw_i over the near hemisphere",
                  "E_T: " + avg + "integral of f_t |cos(theta_i)| dw_i over the far hemisphere (energy)",
                  "E_R + E_T"};
    d.options = {tables::visibility_option()};
    d.supports_monte_carlo = true;
    d.searched_by_identify = kind != Kind::average;  // see catalogue.h
    d.prepare = [kind, inside](const TableSettings& s) {
        const Visibility vis = visibility_from_string(tables::param(s, "visibility"));
        PreparedTable p;
        p.evaluator = std::make_unique<GlassEvaluator>(kind, inside, vis, s);
        p.model = tables::glass_model(vis, inside);
        p.method = s.method == Method::monte_carlo
                       ? tables::monte_carlo_method(kMcSampler, s)
                       : tables::quadrature_method(kQuadratureRule, kTolerances.at(s.quality));
        return p;
    };
    return d;
}

// GGX glass without an interface (n = 1): E_R = 0 and E_T = G2(mu, mu)
// (1 + Lambda(mu)) (glass_index_matched_transmission), from either side.
ClosedFormCheck index_matched_check(Kind kind) {
    const double tol = kTolerances.standard + 1e-12;
    if (kind == Kind::directional)
        return {"E_R = 0 and E_T vs G2(mu, mu) (1 + Lambda(mu)) at n = 1 (no interface)", tol,
                [](const TexelEvaluator& e) {
                    std::vector<std::array<double, 3>> pts;
                    for (double mu : {0.05, 0.4, 0.9})
                        for (double alpha : {0.05, 0.3, 1.0}) pts.push_back({mu, alpha, 1.0});
                    return tables::worst_error(e, pts, [](const TexelValue& v, const auto& p) {
                        return std::abs(v.value[0]) +
                               std::abs(v.value[1] - tables::glass_index_matched_transmission(
                                                         p[0], p[1], Visibility::height_correlated));
                    });
                }};
    return {"E_R avg = 0 and E_T avg vs 2 * integral of G2(mu, mu) (1 + Lambda(mu)) mu dmu at n = 1", tol,
            [](const TexelEvaluator& e) {
                return tables::worst_error(e, tables::grid_points({0.05, 0.3, 1.0}, {1.0}),
                                           [](const TexelValue& v, const auto& p) {
                                               return std::abs(v.value[0]) +
                                                      std::abs(v.value[1] - tables::glass_index_matched_transmission_average(
                                                                                p[0], Visibility::height_correlated));
                                           });
            }};
}

}  // namespace
}  // namespace glass_family

void register_glass_family(FamilyEntries& family) {
    using namespace glass_family;
    family.families.push_back(
        {"", "Rough glass",
        "The reflection and transmission albedos E_R and E_T of the GGX rough dielectric of Walter et al. "
        "2007 (GGX normals, exact dielectric Fresnel, 1 under total internal reflection, Smith G2 with "
        "Lambda of |cos(theta_i)|), seen from outside (eta = n) and from inside (eta = 1/n) over the same "
        "`ior` axis, and their averages over mu. E_T is energy (Walter's eta_o^2 included): a renderer "
        "that carries radiance across the interface multiplies it by 1/eta^2. A direction that lands on "
        "the wrong side of the macro surface contributes nothing. The `ior` axis uses the `ior_z` warp, "
        "linear in Cycles' z = sqrt((n - 1)/(n + 1)). The nested integrals are hand-reduced and held to "
        "the generic lobe path (a reflection and a transmission lobe declared from f alone) by a test."});
    using namespace tables;
    std::vector<TableDefinition>& out = family.tables;
    out.push_back(make(Kind::directional, false, "ggx_glass_albedo",
                       "GGX rough glass seen from outside (eta = n): E_R, E_T, E_R + E_T over (mu, alpha, n)",
                       {cos_theta_axis(16), alpha_axis(16), ior_axis(16)}));
    out.back().checks = {index_matched_check(Kind::directional)};
    out.push_back(make(Kind::directional, true, "ggx_glass_albedo_inside",
                       "GGX rough glass seen from inside (eta = 1/n): E_R, E_T, E_R + E_T over (mu, alpha, n)",
                       {cos_theta_axis(16), alpha_axis(16), ior_axis(16)}));
    out.back().checks = {index_matched_check(Kind::directional)};
    out.push_back(make(Kind::average, false, "ggx_glass_albedo_avg",
                       "GGX rough glass from outside, averages 2 * integral of E(mu) mu dmu over (alpha, n)",
                       {alpha_axis(16), ior_axis(16)}));
    out.back().checks = {index_matched_check(Kind::average)};
    out.push_back(make(Kind::average, true, "ggx_glass_albedo_avg_inside",
                       "GGX rough glass from inside, averages 2 * integral of E(mu) mu dmu over (alpha, n)",
                       {alpha_axis(16), ior_axis(16)}));
    out.back().checks = {index_matched_check(Kind::average)};

    // Allowed |E / E' - 1| of the compensated glass: the trilinear
    // interpolation error of the 16^3 table. It is largest at grazing view:
    // below the first row's centre, mu = 1/32, the lookup holds E(1/32)
    // while E(mu) rises to 1 as mu -> 0 (at n = 1.5), so the ratio tends to
    // 1 / E(1/32, alpha) - 1, at most 0.185 (alpha at or above the last
    // column's centre, 0.9385, where E(1/32) = 0.8438). The furnace grid
    // comes closer to it as it grows (0.057 at --size 32, 0.102 at the
    // default 64, 0.166 at 512); away from grazing view the error is below
    // 1e-2.
    constexpr double kCompensationTolerance = 0.2;
    const std::pair<std::string, std::string> hc{"visibility", "height_correlated"};
    family.furnace_models.insert(
        family.furnace_models.end(),
        {{"ggx_glass", "GGX rough glass (Walter 2007) at n = 1.5 from outside: E_R + E_T, single scattering",
          "ggx_glass_albedo", "ggx_glass_albedo_avg", {hc}, false, false, 0, 2, {{"ior", 1.5}}},
         {"ggx_glass_inside", "GGX rough glass at n = 1.5 from inside (eta = 1/n): E_R + E_T, single scattering",
          "ggx_glass_albedo_inside", "ggx_glass_albedo_avg_inside", {hc}, false, false, 0, 2, {{"ior", 1.5}}},
         // The interpolation error of the 16^3 table peaks at grazing view
         // and small roughness, where E(mu) turns fastest.
         {"ggx_glass_compensated",
          "GGX rough glass at n = 1.5 from outside, E scaled by 1 / E from the default 16^3 table (Cycles' "
          "compensation of untinted glass)",
          "ggx_glass_albedo", "ggx_glass_albedo_avg", {hc}, false, true, kCompensationTolerance, 2,
          {{"ior", 1.5}}, true}});
}

}  // namespace brdflut
