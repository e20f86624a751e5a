// Burley normalized diffusion tables: the profile and its radial CDF in
// units of d, the inverse CDF for importance sampling radii, the scaling
// factors s(A) of the three parametrizations, and the slab transmission as
// Unreal Engine defines it.
//
// Christensen and Burley 2015, "Approximate Reflectance Profiles for
// Efficient Subsurface Scattering"
#include <cmath>
#include <limits>
#include <memory>

#include "brdflut/burley.h"
#include "brdflut/math.h"
#include "tables/checks.h"
#include "tables/registry.h"

namespace brdflut {
namespace burley_family {  // this family's own names, apart from the other families' in a unity build
namespace {

// A short closed form (a few exp, expm1, pow calls): a generous count of
// double roundings, relative.
constexpr double kClosedFormRelError = 32.0 * std::numeric_limits<double>::epsilon();

nlohmann::json closed_form_method(const std::string& rule) {
    return {{"name", "closed_form"}, {"rule", rule}, {"relative_error", kClosedFormRelError}};
}

nlohmann::json burley_model() {
    return {{"model", "Burley normalized diffusion (Christensen and Burley 2015)"},
            {"profile", "R(r) = A s (e^(-s r) + e^(-s r/3)) / (8 pi r), s = 1/d, d = l / s(A)"}};
}

// integral of 2 pi x R(x) dx over [0, x] (x = r/d, A = 1) by adaptive
// Gauss-Kronrod of the profile itself (not its closed-form integral), in
// t = ln(x) below x = 1 (the density tends to 1/2 at 0) and in x above.
double burley_cdf_quadrature(double x) {
    AdaptiveOptions opt;
    opt.abs_tol = 1e-14;
    opt.max_intervals = 2000;
    opt.rule = KronrodRule::k21;
    const double lo = 1e-300;
    double total = 0.0;
    const double x1 = std::min(x, 1.0);
    if (x1 > lo)
        total += integrate_adaptive<1>(
                     [](double t) {
                         const double r = std::exp(t);
                         return std::array<double, 1>{kTwoPi * r * r * burley_profile(r)};
                     },
                     std::log(lo), std::log(x1), opt)
                     .value[0];
    for (double a = 1.0; a < x; a *= 4.0) {
        const double b = std::isinf(x) ? a * 4.0 : std::min(x, a * 4.0);
        total += integrate_adaptive<1>(
                     [](double r) { return std::array<double, 1>{kTwoPi * r * burley_profile(r)}; }, a, b, opt)
                     .value[0];
        if (a > 1e4) break;  // e^(-x/3) < 1e-1400 beyond
    }
    return total;
}

class ProfileEvaluator final : public TexelEvaluator {
public:
    TexelValue evaluate(const double* c, std::uint64_t) const override {
        TexelValue out;
        out.value[0] = burley_profile(c[0]);
        out.value[1] = burley_cdf(c[0]);
        for (int k = 0; k < 2; ++k) out.error[k] = kClosedFormRelError * std::abs(out.value[k]);
        return out;
    }
};

class InverseEvaluator final : public TexelEvaluator {
public:
    TexelValue evaluate(const double* c, std::uint64_t) const override {
        TexelValue out;
        out.value[0] = burley_inverse_cdf(c[0], &out.error[0]);
        return out;
    }
};

class ScalingEvaluator final : public TexelEvaluator {
public:
    TexelValue evaluate(const double* c, std::uint64_t) const override {
        TexelValue out;
        int k = 0;
        for (BurleyScaling s : {BurleyScaling::searchlight, BurleyScaling::diffuse_transmission, BurleyScaling::dmfp}) {
            out.value[k] = burley_scaling(c[0], s);
            out.error[k] = kClosedFormRelError * std::abs(out.value[k]);
            ++k;
        }
        return out;
    }
};

class TransmissionEvaluator final : public TexelEvaluator {
public:
    explicit TransmissionEvaluator(BurleyScaling s) : s_(s) {}
    TexelValue evaluate(const double* c, std::uint64_t) const override {
        TexelValue out;
        out.value[0] = burley_transmission(c[0], c[1], s_);
        out.error[0] = kClosedFormRelError * std::abs(out.value[0]);
        return out;
    }

private:
    BurleyScaling s_;
};

AxisSpec r_over_d_axis() {
    return {Axis{"r_over_d", 1e-3, 64.0, 128, Placement::center, Warp::log}, 1e-300, 1e6,
            "x = r / d: distance on the surface from the point of entry in units of d = l / s(A)"};
}

AxisSpec albedo_axis(int count) {
    return {Axis{"albedo", 0.0, 1.0, count, Placement::center, Warp::linear}, 0.0, 1.0,
            "A: the surface albedo (the profile's total diffuse reflectance)"};
}

}  // namespace
}  // namespace burley_family

ModelOption tables::burley_scaling_option() {
    return {"scaling",
            "Burley: how d follows from the mean free path l and the albedo A, d = l / s(A): searchlight "
            "(1.85 - A + 7|A - 0.8|^3), diffuse_transmission (1.9 - A + 3.5 (A - 0.8)^2) or dmfp "
            "(3.5 + 100 (A - 0.33)^4, l the diffuse mean free path, as Unreal)",
            "dmfp",
            {"searchlight", "diffuse_transmission", "dmfp"}};
}

void register_burley_family(FamilyEntries& family) {
    using namespace burley_family;
    family.families.push_back(
        {"", "Subsurface scattering: Burley normalized diffusion",
         "Christensen and Burley 2015's profile R(r) = A s (e^(-s r) + e^(-s r/3)) / (8 pi r), s = 1/d: its "
         "radial CDF 1 - e^(-x)/4 - 3 e^(-x/3)/4 in x = r/d, the inverse of the CDF for importance sampling "
         "radii (in y = e^(-x/3) the CDF is the cubic y^3 + 3y = 4(1 - u), solved by its trigonometric root "
         "and polished by Newton), the scaling factors s(A) of the paper's three parametrizations (searchlight "
         "and diffuse surface transmission on the volume mean free path, and the diffuse mean free path "
         "on the surface) and the transmission through a slab as Unreal Engine defines it: the part of the "
         "profile's reflectance beyond the thickness, A (1 - CDF(t/d)). All are closed forms evaluated in "
         "double; the checks integrate the profile itself."});
    std::vector<TableDefinition>& out = family.tables;
    {
        TableDefinition d;
        d.id = "burley_profile";
        d.description = "Burley normalized diffusion profile R(x) and its radial CDF, x = r/d, per unit albedo";
        d.axes = {r_over_d_axis()};
        d.channels = {"R d^2 / A = (e^(-x) + e^(-x/3)) / (8 pi x)",
                      "CDF(x) = 1 - e^(-x)/4 - 3 e^(-x/3)/4: the fraction of the reflectance within r"};
        d.prepare = [](const TableSettings&) {
            PreparedTable p;
            p.evaluator = std::make_unique<ProfileEvaluator>();
            p.model = burley_model();
            p.model["units"] = "x = r/d, A = 1";
            p.method = closed_form_method("R and the CDF (with expm1) in closed form");
            return p;
        };
        d.checks = {
            {"CDF vs the quadrature of 2 pi x R(x) over [0, x]", 1e-12,
             [](const TexelEvaluator& e) {
                 return tables::worst_over(e, tables::points_1d({1e-3, 0.05, 0.7, 3.0, 11.0, 40.0}), 1,
                                           [](const auto& p) { return burley_cdf_quadrature(p[0]); });
             }},
            {"R(x) vs the derivative of the CDF over 2 pi x (central difference)", 1e-7,
             [](const TexelEvaluator& e) {
                 return tables::worst_error(e, tables::points_1d({0.02, 0.5, 2.0, 9.0}),
                                            [](const TexelValue& v, const auto& p) {
                                                const double h = 1e-4 * p[0];
                                                const double slope =
                                                    (burley_cdf(p[0] + h) - burley_cdf(p[0] - h)) / (2.0 * h);
                                                return (v.value[0] - slope / (kTwoPi * p[0])) /
                                                       std::max(1.0, v.value[0]);
                                            });
             }},
        };
        out.push_back(std::move(d));
    }
    {
        TableDefinition d;
        d.id = "burley_inverse_cdf";
        d.description = "Burley normalized diffusion: the radius x = r/d whose radial CDF is u (importance sampling)";
        // u = 1 is r = infinity: the default range stops at 0.999 (x near 19.9),
        // and the domain short of 1.
        d.axes = {{Axis{"u", 0.0, 0.999, 256, Placement::center, Warp::linear}, 0.0, 1.0 - 1e-12,
                   "u: the probability, a uniform random number (u = 1 is r = infinity)"}};
        d.channels = {"x = r/d with CDF(x) = u"};
        d.prepare = [](const TableSettings&) {
            PreparedTable p;
            p.evaluator = std::make_unique<InverseEvaluator>();
            p.model = burley_model();
            p.model["units"] = "x = r/d";
            p.method = {{"name", "root_finding"},
                        {"rule", "y = e^(-x/3) = 2 sinh(asinh(2(1 - u))/3), the real root of y^3 + 3y = 4(1 - u), "
                                 "then two Newton steps on CDF(x) - u; error per value: the size of one more "
                                 "Newton step plus rounding"}};
            return p;
        };
        d.checks = {
            {"quadrature of 2 pi x R(x) over [0, x(u)] vs u", 1e-12,
             [](const TexelEvaluator& e) {
                 return tables::worst_error(e, tables::points_1d({1e-6, 0.01, 0.3, 0.5, 0.77, 0.99, 0.999999}),
                                            [](const TexelValue& v, const auto& p) {
                                                return burley_cdf_quadrature(v.value[0]) - p[0];
                                            });
             }},
        };
        out.push_back(std::move(d));
    }
    {
        TableDefinition d;
        d.id = "burley_scaling";
        d.description = "Burley normalized diffusion: the scaling factors s(A) of its three parametrizations";
        d.axes = {albedo_axis(128)};
        d.channels = {"s searchlight = 1.85 - A + 7 |A - 0.8|^3 (d = l / s, l the mean free path)",
                      "s diffuse surface transmission = 1.9 - A + 3.5 (A - 0.8)^2 (d = l / s)",
                      "s diffuse mean free path = 3.5 + 100 (A - 0.33)^4 (d = l_d / s)"};
        d.prepare = [](const TableSettings&) {
            PreparedTable p;
            p.evaluator = std::make_unique<ScalingEvaluator>();
            p.model = burley_model();
            p.model["source"] = "Christensen and Burley 2015 (fits to Monte Carlo)";
            p.method = closed_form_method("the three polynomials of the paper");
            return p;
        };
        // Where each fit is simplest: at A = 0.8 the searchlight and diffuse
        // fits are 1.85 - 0.8 and 1.9 - 0.8, at A = 0.33 the dmfp fit is 3.5;
        // at A = 0 and 1 the terms in (A - c) are powers of 0.8, 0.2, 0.33, 0.67.
        d.checks = {
            {"s(A) vs the paper's polynomials at A = 0, 0.33, 0.8 and 1", 1e-13,
             [](const TexelEvaluator& e) {
                 struct Case {
                     double A;
                     std::array<double, 3> s;
                 };
                 const std::vector<Case> cases = {
                     {0.0, {1.85 + 7.0 * 0.512, 1.9 + 3.5 * 0.64, 3.5 + 100.0 * 0.33 * 0.33 * 0.33 * 0.33}},
                     {0.33, {1.85 - 0.33 + 7.0 * 0.47 * 0.47 * 0.47, 1.9 - 0.33 + 3.5 * 0.47 * 0.47, 3.5}},
                     {0.8, {1.05, 1.1, 3.5 + 100.0 * 0.47 * 0.47 * 0.47 * 0.47}},
                     {1.0, {0.85 + 7.0 * 0.008, 0.9 + 3.5 * 0.04, 3.5 + 100.0 * 0.67 * 0.67 * 0.67 * 0.67}},
                 };
                 tables::CheckResult r{0.0, ""};
                 for (const Case& c : cases) {
                     const TexelValue v = e.evaluate(&c.A, 0);
                     for (std::size_t k = 0; k < 3; ++k) {
                         const double err = std::abs(v.value[k] - c.s[k]);
                         if (!(err <= r.first) || r.second.empty())
                             r = {err, "channel " + std::to_string(k) + " " + tables::point_text(std::array<double, 1>{c.A})};
                     }
                 }
                 return r;
             }},
        };
        out.push_back(std::move(d));
    }
    {
        TableDefinition d;
        d.id = "burley_transmission";
        d.description = "Burley slab transmission A (1 - CDF(t/d)) over thickness and albedo (Unreal's definition)";
        d.axes = {{Axis{"thickness", 0.0, 8.0, 64, Placement::center, Warp::linear}, 0.0, 1e6,
                   "t / l: slab thickness in units of the mean free path l of the --scaling (Unreal: the "
                   "diffuse mean free path)"},
                  albedo_axis(64)};
        d.channels = {"T = A (e^(-s t/l)/4 + 3 e^(-s t/(3 l))/4): the profile's reflectance beyond r = t"};
        d.options = {tables::burley_scaling_option()};
        d.prepare = [](const TableSettings& s) {
            const BurleyScaling scaling = burley_scaling_from_string(tables::param(s, "scaling"));
            PreparedTable p;
            p.evaluator = std::make_unique<TransmissionEvaluator>(scaling);
            p.model = burley_model();
            p.model["scaling"] = to_string(scaling);
            p.model["engine_source"] =
                "Unreal Engine BurleyNormalizedSSS.cpp, Burley_TransmissionProfile (evaluated there at t + 0.06 "
                "world units, ProfileRadiusOffset)";
            p.method = closed_form_method("A (1 - CDF(s t / l)) with the complement in exponentials");
            return p;
        };
        d.checks = {
            {"T vs A (1 - quadrature of 2 pi x R(x) over [0, s t])", 1e-12,
             [](const TexelEvaluator& e) {
                 return tables::worst_over(e, tables::grid_points({0.0, 0.1, 1.0, 4.0}, {0.05, 0.33, 0.8, 1.0}), 0,
                                           [](const auto& p) {
                                               const double s = burley_scaling(p[1], BurleyScaling::dmfp);
                                               return p[1] * (1.0 - burley_cdf_quadrature(s * p[0]));
                                           });
             }},
        };
        out.push_back(std::move(d));
    }
}

}  // namespace brdflut
