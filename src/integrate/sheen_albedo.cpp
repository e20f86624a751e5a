// Quadrature and Monte Carlo estimates of the Charlie sheen albedo.
//
// Quadrature. With dw_i = 4 (wo.h) dw_h and u = sin(theta_h), c = cos(theta_h),
//
//   E = (1/pi) integral over v = u^n in [0, 1] of F(u) dv,   n = 2 + 1/alpha,
//   F(u) = integral over phi in [0, pi] of g,   g = 4 V mu_i (wo.h) / c,
//
// since D(h) cos(theta_h) dw_h = d(u^n) dphi / (2 pi). For fixed u every
// factor of g is affine in x = cos(phi): wo.h = p x + q with p = sin(theta_o) u,
// q = mu_o c; mu_i = 2 c (wo.h) - mu_o; 4 V = 1 / (k mu_i + mu_o), k = 1 - mu_o.
// So g = (wo.h) mu_i / (c (k mu_i + mu_o)) splits into a trigonometric
// polynomial and a multiple of 1 / (d0 + d1 cos(phi)), and the phi integral is
// closed: with the clip mu_i > 0 at phi < phi_m, T = tan(phi_m / 2),
//
//   F = [p sin(phi_m) + (q - w) phi_m + w mu_o^2 J] / (c k),   w = mu_o / (2 k c),
//   J = integral over [0, phi_m] of dphi / (d0 + d1 cos(phi))
//     = (2 T / a) f(b T^2 / a),   a = d0 + d1, b = d0 - d1,
//
// f(z) = atan(sqrt(z)) / sqrt(z), continued to atanh for z < 0. mu_i at phi = 0
// and phi = pi is cos(2 theta_h - theta_o) and cos(2 theta_h + theta_o), so the
// clip starts at theta_h1 = asin(mu_o) / 2 and the whole ring is gone past
// theta_h2 = pi/4 + theta_o/2. The terms cancel as k -> 0; for k < 0.02 the
// phi integral is taken by Gauss-Kronrod instead (g is then smooth: its pole
// lies at mu_i = -mu_o / k, far below 0).
//
// The outer integral runs in zeta = ln(beta), beta = pi/2 - theta_h, in two
// pieces split at theta_h1: F carries a 1/c factor that varies on the scale
// of beta_2 = pi/2 - theta_h2 = asin(mu_o) / 2 near grazing, which the log
// resolves, and the weight dv = n u^(n - 1) c beta dzeta decays fast once
// beta exceeds 1/sqrt(n); the range stops where the weight has fallen by
// e^-kWeightSpan below its largest value, and the neglected tail is bounded
// (g <= 2 / c) and added to the error. F has (beta - beta_i)^(3/2) kinks at
// both clip limits and the weight vanishes like theta_h^(n - 1) at the pole;
// polynomial maps flatten the rule's ends there. Each piece uses adaptive
// Gauss-Kronrod (7, 15); the error adds the QUADPACK estimates, a rounding
// bound of the closed form, and the neglected tails.
#include <cmath>

#include "brdflut/random.h"
#include "brdflut/sheen.h"
#include "brdflut/sheen_integrals.h"

namespace brdflut {
namespace {

constexpr double kEpsilon = 2.220446049250313e-16;
// Below this k = 1 - mu_o the closed form loses too many digits.
constexpr double kClosedFormMinK = 0.02;
// The outer range ends where the weight u^(n - 1) has fallen by e^-kWeightSpan.
constexpr double kWeightSpan = 40.0;

// Integral over [0, T] of 2 dt / (a + b t^2) (J above, in t = tan(phi / 2)),
// a > 0 and a + b T^2 > 0; T = HUGE_VAL is the whole half circle.
double half_angle_integral(double a, double b, double T) {
    if (T == HUGE_VAL) return kPi / std::sqrt(a * b);
    const double z = b * T * T / a;
    double f;
    if (std::abs(z) < 1e-3) {
        f = 1.0 + z * (-1.0 / 3.0 + z * (1.0 / 5.0 + z * (-1.0 / 7.0 + z * (1.0 / 9.0))));
    } else if (z > 0.0) {
        const double r = std::sqrt(z);
        f = std::atan(r) / r;
    } else {
        const double r = std::sqrt(-z);
        f = std::atanh(r) / r;
    }
    return 2.0 * T / a * f;
}

// F(u) = integral over phi in [0, pi] of g, given u = sin(theta_h) and
// c = cos(theta_h): {value, bound on its rounding or quadrature error}.
std::array<double, 2> ring_integral(double mu_o, double sin_o, double u, double c) {
    if (!(c > 0.0)) return {0.0, 0.0};
    const double p = sin_o * u, q = mu_o * c;
    const double cos_2h = (c - u) * (c + u) * mu_o, sin_2h = 2.0 * u * c * sin_o;
    const double mu_i_0 = cos_2h + sin_2h;   // mu_i at phi = 0
    const double mu_i_pi = cos_2h - sin_2h;  // mu_i at phi = pi
    if (mu_i_0 <= 0.0) return {0.0, 0.0};
    double T = HUGE_VAL, phi_m = kPi, sin_m = 0.0;
    if (mu_i_pi < 0.0) {
        T = std::sqrt(mu_i_0 / -mu_i_pi);
        phi_m = 2.0 * std::atan(T);
        sin_m = 2.0 * T / (1.0 + T * T);
    }
    const double k = 1.0 - mu_o;
    if (k < kClosedFormMinK) {
        AdaptiveOptions opt;
        opt.abs_tol = 1e-12;
        opt.rule = KronrodRule::k31;
        const Estimate<1> e = integrate_adaptive<1>(
            [&](double phi) {
                const double o_h = p * std::cos(phi) + q;
                const double mu_i = 2.0 * o_h * c - mu_o;
                return std::array<double, 1>{mu_i > 0.0 ? o_h * mu_i / (c * (k * mu_i + mu_o)) : 0.0};
            },
            0.0, phi_m, opt);
        return {e.value[0], e.error[0]};
    }
    const double m1 = 2.0 * c * p, m0 = 2.0 * c * q - mu_o;  // mu_i = m1 x + m0
    const double d1 = k * m1, d0 = k * m0 + mu_o;            // 4 V = 1 / (d1 x + d0)
    const double J = mu_o > 0.0 ? half_angle_integral(d0 + d1, d0 - d1, T) : 0.0;
    const double w = mu_o / (2.0 * k * c);
    const double t1 = p * sin_m, t2 = q * phi_m, t3 = w * phi_m, t4 = w * mu_o * mu_o * J;
    const double scale = 1.0 / (c * k);
    return {(t1 + t2 - t3 + t4) * scale, 16.0 * kEpsilon * (t1 + t2 + t3 + t4) * scale};
}

// A map s in [0, 1] -> [0, 1] with its slope, flat at the ends marked:
// a (x - x_end)^(3/2) kink becomes analytic under S ~ s^2.
struct EndMap {
    bool flat_left, flat_right;
    std::array<double, 2> operator()(double s) const {
        const double r = 1.0 - s;
        if (flat_left && flat_right) return {s * s * (3.0 - 2.0 * s), 6.0 * s * r};
        if (flat_left) return {s * s, 2.0 * s};
        if (flat_right) return {1.0 - r * r * r, 3.0 * r * r};
        return {s, 1.0};
    }
};

}  // namespace

Estimate<1> sheen_charlie_albedo(double mu_o, double alpha, double abs_tol) {
    Estimate<1> out;
    if (!(alpha > 0.0)) return out;  // the lobe vanishes
    mu_o = clamp01(mu_o);
    const double sin_o = safe_sqrt(1.0 - mu_o * mu_o);
    const double n = 2.0 + 1.0 / alpha;
    // beta = pi/2 - theta_h at the clip limits: the whole ring is reflected
    // above beta_1, none of it below beta_2.
    const double beta_2 = 0.5 * std::asin(mu_o);
    const double beta_1 = 0.5 * kPi - beta_2;
    const double ln_n = std::log(n);

    // ln(u^(n - 1)), u = cos(beta), with 1 - u = 2 sin(beta/2)^2.
    auto log_weight = [&](double beta) {
        const double h = std::sin(0.5 * beta);
        return (n - 1.0) * std::log1p(-2.0 * h * h);
    };
    // The weight is largest at beta_2 (or at 0 when mu_o = 0); past beta_hi
    // it is e^-kWeightSpan times smaller.
    const double beta_hi = std::min(0.5 * kPi, std::acos(std::cos(beta_2) * std::exp(-kWeightSpan / (n - 1.0))));
    // At mu_o = 0 the range starts at beta = 0, where g ~ 1/beta: start
    // where the skipped part, at most n beta * 2, is negligible.
    const double beta_lo = std::max(beta_2, 1e-18 / n);

    // Integrand in zeta = ln(beta): F times dv/dzeta = n u^(n - 1) c beta.
    auto at = [&](double zeta) -> std::array<double, 2> {
        const double beta = std::exp(zeta);
        const double h = std::sin(0.5 * beta), hc = std::cos(0.5 * beta);
        const double u = 1.0 - 2.0 * h * h, c = 2.0 * h * hc;
        const std::array<double, 2> f = ring_integral(mu_o, sin_o, u, c);
        const double weight = std::exp(ln_n + log_weight(beta)) * c * beta;
        return {f[0] * weight, f[1] * weight};
    };
    AdaptiveOptions opt;
    opt.abs_tol = 0.5 * abs_tol * kPi;
    opt.controlled = 1;
    double value = 0.0, error = 0.0;
    auto piece = [&](double b0, double b1, EndMap map) {
        if (!(b1 > b0)) return;
        const double z0 = std::log(b0), len = std::log(b1) - z0;
        const Estimate<2> e = integrate_adaptive<2>(
            [&](double s) {
                const std::array<double, 2> m = map(s);
                const std::array<double, 2> f = at(z0 + len * m[0]);
                return std::array<double, 2>{f[0] * len * m[1], f[1] * len * m[1]};
            },
            0.0, 1.0, opt);
        value += e.value[0];
        error += e.error[0] + e.value[1];
        out.evaluations += e.evaluations;
    };
    // Clipped ring on [beta_2, beta_1] (kinks at both ends unless cut off),
    // whole ring on [beta_1, pi/2] (weight ~ theta_h^(n-1) at the pole).
    piece(beta_lo, std::min(beta_1, beta_hi), EndMap{beta_lo == beta_2, beta_hi >= beta_1});
    piece(beta_1, beta_hi, EndMap{false, beta_hi == 0.5 * kPi});
    // Neglected tails: below beta_lo (g <= 2/c ~ 2/beta over dv <= n beta
    // dbeta), above beta_hi (dv < e^-span over u, g <= 2 / c).
    if (beta_lo > beta_2) error += 2.0 * n * beta_lo * kPi;
    if (beta_hi < 0.5 * kPi)
        error += 2.0 * kPi / std::sin(beta_hi) * std::exp(log_weight(beta_2) - kWeightSpan);
    out.value[0] = value * kInvPi;
    out.error[0] = error * kInvPi + 1e-16;
    return out;
}

// Monte Carlo, independent of the quadrature: wi from an equal mixture of
// the uniform hemisphere (density 1/(2 pi)) and the reflection of a normal
// drawn from D cos(theta_h) (density D cos(theta_h) / (4 wo.h) in wi); the
// BRDF is evaluated pointwise (charlie_sheen_brdf). Weight f mu_i / pdf(wi).
Estimate<1> sheen_charlie_albedo_mc(double mu_o, double alpha, long long samples, std::uint64_t seed) {
    Estimate<1> out;
    if (!(alpha > 0.0)) return out;
    const Charlie charlie{alpha};
    const Vec3 wo = direction_from_mu(clamp01(mu_o));
    Rng rng(seed, 2);
    MeanAccumulator<1> acc;
    for (long long s = 0; s < samples; ++s) {
        const double pick = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
        const double phi = kTwoPi * u2;
        Vec3 wi;
        if (pick < 0.5) {
            const double z = 1.0 - u1;  // uniform in (0, 1]
            const double r = safe_sqrt(1.0 - z * z);
            wi = {r * std::cos(phi), r * std::sin(phi), z};
        } else {
            const double sin_h = charlie.sample_sin_theta(u1);
            const double cos_h = safe_sqrt(1.0 - sin_h * sin_h);
            const Vec3 h{sin_h * std::cos(phi), sin_h * std::sin(phi), cos_h};
            const double o_h = dot(wo, h);
            wi = {2.0 * o_h * h.x - wo.x, 2.0 * o_h * h.y - wo.y, 2.0 * o_h * h.z - wo.z};
        }
        double w = 0.0;
        if (wi.z > 0.0) {
            const Vec3 sum{wo.x + wi.x, wo.y + wi.y, wo.z + wi.z};
            const double len = std::sqrt(dot(sum, sum));
            const double cos_h = sum.z / len;
            const double o_h = dot(wo, sum) / len;
            const double pdf_charlie = o_h > 0.0 ? charlie.D(cos_h) * cos_h / (4.0 * o_h) : 0.0;
            const double pdf = 0.5 / kTwoPi + 0.5 * pdf_charlie;
            w = charlie_sheen_brdf(charlie, wo, wi) * wi.z / pdf;
        }
        acc.add(&w);
    }
    return acc.estimate();
}

}  // namespace brdflut
