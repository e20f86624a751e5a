#include "brdflut/charlie_ek.h"

#include <algorithm>

#include "brdflut/error.h"

namespace brdflut {

const char* to_string(SheenShadowing s) {
    switch (s) {
        case SheenShadowing::estevez_kulla: return "estevez_kulla";
        case SheenShadowing::estevez_kulla_soft: return "estevez_kulla_soft";
        case SheenShadowing::neubelt: return "neubelt";
    }
    return "estevez_kulla";
}

SheenShadowing sheen_shadowing_from_string(const std::string& name) {
    for (SheenShadowing s :
         {SheenShadowing::estevez_kulla, SheenShadowing::estevez_kulla_soft, SheenShadowing::neubelt})
        if (name == to_string(s)) return s;
    throw Error("unknown sheen shadowing '" + name + "'; allowed: estevez_kulla, estevez_kulla_soft, neubelt");
}

EstevezKullaFit::EstevezKullaFit(double alpha) {
    const double t = sqr(1.0 - clamp01(alpha));
    const auto fit = [t](double at_one, double at_zero) { return at_one + (at_zero - at_one) * t; };
    a_ = fit(21.5473, 25.3245);
    b_ = fit(3.82987, 3.32435);
    c_ = fit(0.19823, 0.16801);
    d_ = fit(-1.97760, -1.27393);
    e_ = fit(-4.32054, -4.85967);
    l_half_ = L(0.5);
}

double EstevezKullaFit::L(double x) const { return a_ / (1.0 + b_ * std::pow(std::max(x, 0.0), c_)) + d_ * x + e_; }

double EstevezKullaFit::lambda(double mu) const {
    return mu < 0.5 ? std::exp(L(mu)) : std::exp(2.0 * l_half_ - L(1.0 - mu));
}

double EstevezKullaFit::lambda_light(double mu, bool soft) const {
    const double lambda = this->lambda(mu);
    if (!soft) return lambda;
    const double s2 = sqr(1.0 - mu), s8 = sqr(sqr(s2));
    return std::pow(lambda, 1.0 + 2.0 * s8);
}

double CharlieLobe::f(const Vec3& wo, const Vec3& wi) const {
    if (!(wo.z > 0.0) || !(wi.z > 0.0)) return 0.0;
    const Vec3 s{wo.x + wi.x, wo.y + wi.y, wo.z + wi.z};
    const double len = std::sqrt(dot(s, s));
    if (!(len > 0.0)) return 0.0;
    const double d = charlie_.D(s.z / len);
    if (shadowing_ == SheenShadowing::neubelt) return d * neubelt_visibility(wo.z, wi.z);
    const double lambda_o = per_cosine(charlie_.alpha, wo.z, [&] { return fit_.lambda(wo.z); });
    // About the normal (hints) a ring of the generic path has one wi.z.
    const double lambda_i = shadowing_ == SheenShadowing::estevez_kulla_soft
                                ? per_cosine(charlie_.alpha, wi.z, [&] { return fit_.lambda_light(wi.z, true); })
                                : per_cosine(charlie_.alpha, wi.z, [&] { return fit_.lambda(wi.z); });
    const double g = 1.0 / (1.0 + lambda_o + lambda_i);
    return d * g / (4.0 * wo.z * wi.z);
}

LobeHints CharlieLobe::hints(const Vec3& wo) const {
    LobeHints h;
    // D = c sin(theta_h)^(1/alpha) is not smooth where h is the normal, at
    // the mirror direction of wo: |x|^(1/alpha) about that point (a cusp as
    // alpha tends to 1). Lambda of the light is exp(2 L(1/2) - L(1 - mu_i))
    // above mu_i = 1/2, with L's (1 - mu_i)^c: a cusp at the normal.
    h.point_kinks = {Vec3{-wo.x, -wo.y, wo.z}};
    if (shadowing_ != SheenShadowing::neubelt) h.point_kinks.push_back(Vec3{0.0, 0.0, 1.0});
    // Lambda's second derivative jumps at mu_i = 1/2 (a cone about the normal).
    if (shadowing_ != SheenShadowing::neubelt) h.kink_cones = {LobeCone{{0.0, 0.0, 1.0}, kPi / 3.0}};
    return h;
}

bool CharlieLobe::own_moments(double mu_o, double abs_tol, Estimate<2>& out) const {
    out = sheen_charlie_moments(mu_o, charlie_.alpha, shadowing_, abs_tol);
    return true;
}

LobeSample CharlieLobe::sample(const Vec3& wo, double u1, double u2) const {
    return cosine_and_mirror_mixture(
        wo, u1, u2,
        [&](double u, double phi) {
            const double st = charlie_.sample_sin_theta(u), ct = safe_sqrt(1.0 - st * st);
            return Vec3{st * std::cos(phi), st * std::sin(phi), ct};
        },
        [&](const Vec3& h) { return charlie_.D(h.z) * h.z; });
}

}  // namespace brdflut
