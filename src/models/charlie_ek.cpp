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

double estevez_kulla_L(double x, double alpha) {
    const double t = sqr(1.0 - clamp01(alpha));  // weight of the alpha = 0 fit
    const auto fit = [t](double at_one, double at_zero) { return at_one + (at_zero - at_one) * t; };
    const double a = fit(21.5473, 25.3245), b = fit(3.82987, 3.32435), c = fit(0.19823, 0.16801),
                 d = fit(-1.97760, -1.27393), e = fit(-4.32054, -4.85967);
    return a / (1.0 + b * std::pow(std::max(x, 0.0), c)) + d * x + e;
}

double estevez_kulla_lambda(double mu, double alpha) {
    return mu < 0.5 ? std::exp(estevez_kulla_L(mu, alpha))
                    : std::exp(2.0 * estevez_kulla_L(0.5, alpha) - estevez_kulla_L(1.0 - mu, alpha));
}

double estevez_kulla_lambda_light(double mu, double alpha, bool soft) {
    const double lambda = estevez_kulla_lambda(mu, alpha);
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
    const double a = charlie_.alpha;
    const double g = 1.0 / (1.0 + estevez_kulla_lambda(wo.z, a) +
                            estevez_kulla_lambda_light(wi.z, a, shadowing_ == SheenShadowing::estevez_kulla_soft));
    return d * g / (4.0 * wo.z * wi.z);
}

LobeHints CharlieLobe::hints(const Vec3& wo) const {
    LobeHints h;
    // D = c sin(theta_h)^(1/alpha) is not smooth where h is the normal, at
    // the mirror direction of wo (|theta_h|^(1/alpha) there; a kink as alpha
    // tends to 1): the ring through it is a break point, and the point itself
    // an end of the ring's azimuth range.
    h.kinks = {std::acos(std::clamp(wo.z, -1.0, 1.0))};
    // Lambda's second derivative jumps at mu_i = 1/2 (a cone about the normal).
    if (shadowing_ != SheenShadowing::neubelt) h.kink_cones = {LobeCone{{0.0, 0.0, 1.0}, kPi / 3.0}};
    return h;
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
