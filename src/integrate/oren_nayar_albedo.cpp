// Quadrature of the directional albedo of the Oren-Nayar family.
//
// The phi dependence has a closed form in every model: over phi in [0, 2 pi],
// integral of max(0, cos(phi)) = 2 (qualitative model), and Fujii's
// s = sin_i sin_o cos(phi) gives integral of s/t = 2 sin_i sin_o (1/max(mu_i, mu_o) - 1)
// (s/max over the half circle where s > 0, s over the other). What is left is
// an integral over theta_i (smooth, unlike sqrt(1 - mu_i^2) in mu_i), split at
// theta_i = theta_o where max/min switch:
//   qualitative: E = A + (2B/pi) [integral over [0, theta_o] of sin_o sin_i^2
//                                 + integral over [theta_o, pi/2] of tan_o sin_i^2 mu_i] dtheta_i
//   Fujii:       E = A + (2 sigma A/pi) [integral over [0, theta_o] of sin_o sin_i^2 (1 - mu_i)
//                      + integral over [theta_o, pi/2] of sin_o sin_i^2 mu_i (1/mu_o - 1)] dtheta_i
//   EON adds     2 (1 - E_FON(mu_o)) / (1 - E_FON_avg) integral of (1 - E_FON(mu_i)) mu_i sin_i dtheta_i
//   (E_FON exact, oren_nayar.h).
#include <cmath>

#include "brdflut/oren_nayar.h"
#include "integrate/lobe_albedo_detail.h"

namespace brdflut::detail {

namespace {

// integral over [0, theta_o] of below(theta_i) + integral over [theta_o, pi/2]
// of above(theta_i), each channel within abs_tol / 2.
template <class Below, class Above>
Estimate<1> split_at_theta_o(double theta_o, Below&& below, Above&& above, double abs_tol) {
    AdaptiveOptions opt;
    opt.abs_tol = 0.5 * abs_tol;
    Estimate<1> out;
    for (const Estimate<1>& e :
         {integrate_adaptive<1>([&](double t) { return std::array<double, 1>{below(t)}; }, 0.0,
                                theta_o, opt),
          integrate_adaptive<1>([&](double t) { return std::array<double, 1>{above(t)}; },
                                theta_o, 0.5 * kPi, opt)}) {
        out.value[0] += e.value[0];
        out.error[0] += e.error[0];
        out.evaluations += e.evaluations;
    }
    return out;
}

struct ViewAngles {
    double mu_o, sin_o, theta_o;
    explicit ViewAngles(double mu)
        : mu_o(clamp01(mu)), sin_o(safe_sqrt(1.0 - mu_o * mu_o)), theta_o(std::acos(mu_o)) {}
};

}  // namespace

Estimate<1> oren_nayar_albedo(double mu, double sigma, double abs_tol) {
    const OrenNayar on{sigma};
    const ViewAngles v(mu);
    const double scale = 2.0 * on.B() * kInvPi;
    Estimate<1> e = split_at_theta_o(
        v.theta_o,
        [&](double t) { return v.sin_o * sqr(std::sin(t)); },
        [&](double t) { return v.sin_o / v.mu_o * sqr(std::sin(t)) * std::cos(t); },
        scale > 0.0 ? abs_tol / scale : abs_tol);
    e.value[0] = on.A() + scale * e.value[0];
    e.error[0] *= scale;
    return e;
}

Estimate<1> fujii_oren_nayar_albedo(double mu, double sigma, double abs_tol) {
    const FujiiOrenNayar fon{sigma};
    const ViewAngles v(mu);
    const double scale = 2.0 * sigma * fon.A() * kInvPi;
    Estimate<1> e = split_at_theta_o(
        v.theta_o,
        [&](double t) { return v.sin_o * sqr(std::sin(t)) * (1.0 - std::cos(t)); },
        [&](double t) {
            return v.sin_o * sqr(std::sin(t)) * std::cos(t) * (1.0 / v.mu_o - 1.0);
        },
        scale > 0.0 ? abs_tol / scale : abs_tol);
    e.value[0] = fon.A() + scale * e.value[0];
    e.error[0] *= scale;
    return e;
}

Estimate<1> eon_albedo(double mu, double sigma, double abs_tol) {
    const Eon eon{FujiiOrenNayar{sigma}};
    const ViewAngles v(mu);
    Estimate<1> e = fujii_oren_nayar_albedo(mu, sigma, 0.5 * abs_tol);
    // integral of f_ms mu_i dw_i = 2 pi integral of f_ms(mu_o, mu_i) mu_i sin_i dtheta_i.
    AdaptiveOptions opt;
    opt.abs_tol = 0.5 * abs_tol;
    const Estimate<1> ms = integrate_adaptive<1>(
        [&](double t) {
            const double mu_i = std::cos(t);
            return std::array<double, 1>{2.0 * kPi * eon.multiple_scattering_brdf(v.mu_o, mu_i) *
                                         mu_i * std::sin(t)};
        },
        0.0, 0.5 * kPi, opt);
    e.value[0] += ms.value[0];
    e.error[0] += ms.error[0];
    e.evaluations += ms.evaluations;
    return e;
}

}  // namespace brdflut::detail
