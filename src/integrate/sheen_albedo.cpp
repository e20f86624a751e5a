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
//
// The moments of the lobe with any shadowing (sheen_charlie_moments, for the
// Estevez-Kulla G of charlie_ek.h, which has no closed form over the
// azimuth): the same outer rule over zeta, with g = 4 V mu_i (wo.h) w / c
// (4 V mu_i = G / mu_o for Estevez-Kulla, mu_i / (mu_i + mu_o - mu_i mu_o)
// for Neubelt; w = 1 or (1 - wo.h)^5) integrated over phi by adaptive
// Gauss-Kronrod (15, 31). A ring is split where mu_i = 1/2 (Lambda's kink),
// and where the horizon clips it the last piece is taken in t with
// phi = phi_m - (phi_m - phi_0) t^4: near mu_i = 0, Lambda goes as
// exp(a / (1 + b mu_i^c)), c about 0.2, which t^4 nearly straightens. The
// outer axis is split, besides the clip limits, where the rings start and
// stop crossing mu_i = 1/2 and at the ring through the normal (Lambda's
// (1 - mu_i)^c at wi = n); its first piece, which starts where the whole
// ring reaches the horizon, is flattened there by zeta = zeta_2 + len s^4
// for the same reason. Each inner integral gets the tolerance its outer
// weight requires and its error estimate is integrated with the values.
#include <algorithm>
#include <cmath>
#include <vector>

#include "brdflut/charlie_ek.h"
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

// The outer axis of both rules: beta = pi/2 - theta_h, the weight
// dv/dzeta = n u^(n - 1) c beta in zeta = ln(beta) (u = cos(beta) =
// sin(theta_h), c = sin(beta)), largest at beta_2 = asin(mu_o) / 2 (or at 0
// when mu_o = 0), where the whole ring reaches the horizon; past beta_hi it
// is e^-kWeightSpan times smaller.
struct HalfVectorAxis {
    double n, ln_n, beta_2, beta_hi;
    HalfVectorAxis(double mu_o, double alpha)
        : n(2.0 + 1.0 / alpha), ln_n(std::log(n)), beta_2(0.5 * std::asin(mu_o)),
          beta_hi(std::min(0.5 * kPi, std::acos(std::cos(beta_2) * std::exp(-kWeightSpan / (n - 1.0))))) {}
    // ln(u^(n - 1)), with 1 - u = 2 sin(beta/2)^2.
    double log_weight(double beta) const {
        const double h = std::sin(0.5 * beta);
        return (n - 1.0) * std::log1p(-2.0 * h * h);
    }
    struct Node {
        double u, c, weight;
    };
    Node at(double beta) const {
        const double h = std::sin(0.5 * beta), hc = std::cos(0.5 * beta);
        const double c = 2.0 * h * hc;
        return {1.0 - 2.0 * h * h, c, std::exp(ln_n + log_weight(beta)) * c * beta};
    }
    // The integral of dv above beta_hi, over c there, times g_c, a bound
    // on g c: the neglected tail of the integral of g dv (one phi).
    double tail(double g_c) const {
        return beta_hi < 0.5 * kPi ? g_c / std::sin(beta_hi) * std::exp(log_weight(beta_2) - kWeightSpan) : 0.0;
    }
};

}  // namespace

Estimate<1> sheen_charlie_albedo(double mu_o, double alpha, double abs_tol) {
    Estimate<1> out;
    if (!(alpha > 0.0)) return out;  // the lobe vanishes
    mu_o = clamp01(mu_o);
    const double sin_o = safe_sqrt(1.0 - mu_o * mu_o);
    const HalfVectorAxis axis(mu_o, alpha);
    const double n = axis.n, beta_2 = axis.beta_2, beta_hi = axis.beta_hi;
    // beta = pi/2 - theta_h at the clip limits: the whole ring is reflected
    // above beta_1, none of it below beta_2.
    const double beta_1 = 0.5 * kPi - beta_2;
    // At mu_o = 0 the range starts at beta = 0, where g ~ 1/beta: start
    // where the skipped part, at most n beta * 2, is negligible.
    const double beta_lo = std::max(beta_2, 1e-18 / n);

    // Integrand in zeta = ln(beta): F times dv/dzeta.
    auto at = [&](double zeta) -> std::array<double, 2> {
        const HalfVectorAxis::Node x = axis.at(std::exp(zeta));
        const std::array<double, 2> f = ring_integral(mu_o, sin_o, x.u, x.c);
        return {f[0] * x.weight, f[1] * x.weight};
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
    error += kPi * axis.tail(2.0);
    out.value[0] = value * kInvPi;
    out.error[0] = error * kInvPi + 1e-16;
    return out;
}

Estimate<2> sheen_charlie_moments(double mu_o, double alpha, SheenShadowing shadowing, double abs_tol) {
    Estimate<2> out;
    out.evaluations = 0;
    if (!(alpha > 0.0)) return out;  // the lobe vanishes
    alpha = std::min(alpha, 1.0);
    mu_o = std::clamp(std::isnan(mu_o) ? 0.0 : mu_o, 1e-12, 1.0);
    const bool ek = shadowing != SheenShadowing::neubelt;
    const bool soft = shadowing == SheenShadowing::estevez_kulla_soft;
    const EstevezKullaFit fit(alpha);
    const double lambda_o = ek ? fit.lambda(mu_o) : 0.0;
    const double sin_o = safe_sqrt((1.0 - mu_o) * (1.0 + mu_o));
    const double theta_o = std::acos(mu_o);
    const HalfVectorAxis axis(mu_o, alpha);
    // 4 V mu_i as a function of mu_i > 0.
    auto visibility = [&](double mu_i) {
        return ek ? 1.0 / (mu_o * (1.0 + lambda_o + fit.lambda_light(mu_i, soft)))
                  : mu_i / (mu_i + mu_o - mu_i * mu_o);
    };
    constexpr int kClipPower = 4;
    int evaluations = 0;

    // The azimuth integral of g at u = sin(theta_h), c = cos(theta_h), to
    // tolerance tol: {F_E, F_F, error estimate}.
    auto ring = [&](double u, double c, double tol) -> std::array<double, 3> {
        std::array<double, 3> r{};
        if (!(c > 0.0)) return r;
        const double p = sin_o * u, q = mu_o * c;
        const double mu_i_0 = 2.0 * c * (p + q) - mu_o, mu_i_pi = 2.0 * c * (q - p) - mu_o;
        if (!(mu_i_0 > 0.0)) return r;
        // phi where mu_i takes the value m (mu_i = 2 c (p cos(phi) + q) - mu_o).
        auto phi_at = [&](double m) {
            return std::acos(std::clamp(((m + mu_o) / (2.0 * c) - q) / p, -1.0, 1.0));
        };
        const bool clipped = mu_i_pi < 0.0;
        const double phi_m = clipped ? phi_at(0.0) : kPi;
        const double phi_k = ek && mu_i_0 > 0.5 && mu_i_pi < 0.5 ? phi_at(0.5) : 0.0;
        auto g = [&](double phi) -> std::array<double, 2> {
            ++evaluations;
            const double o_h = p * std::cos(phi) + q;
            const double mu_i = 2.0 * c * o_h - mu_o;
            if (!(mu_i > 0.0)) return {0.0, 0.0};
            const double v = visibility(mu_i) * o_h / c;
            const double w = 1.0 - o_h, w2 = w * w;
            return {v, v * w2 * w2 * w};
        };
        AdaptiveOptions opt;
        opt.abs_tol = tol;
        opt.rule = KronrodRule::k31;
        auto add = [&](const Estimate<2>& e) {
            r[0] += e.value[0];
            r[1] += e.value[1];
            r[2] += e.error[0] + e.error[1];
        };
        if (phi_k > 0.0 && phi_k < phi_m) add(integrate_adaptive<2>(g, 0.0, phi_k, opt));
        const double a = std::max(phi_k, 0.0), len = phi_m - a;
        if (!(len > 0.0)) return r;
        if (!clipped) {
            add(integrate_adaptive<2>(g, a, phi_m, opt));
        } else {
            add(integrate_adaptive<2>(
                [&](double t) {
                    const double t3 = t * t * t;
                    const std::array<double, 2> y = g(phi_m - len * t3 * t);
                    const double j = len * kClipPower * t3;
                    return std::array<double, 2>{y[0] * j, y[1] * j};
                },
                0.0, 1.0, opt));
        }
        return r;
    };

    // beta = pi/2 - theta_h: the whole ring is below the horizon under
    // beta_2, clipped up to beta_1.
    const double beta_2 = axis.beta_2, beta_hi = axis.beta_hi;
    const double beta_1 = 0.25 * kPi + 0.5 * theta_o;
    std::vector<double> breaks = {beta_2, beta_1, beta_hi};
    if (ek)  // the rings through mu_i = 1/2 at phi = 0 or pi, and through the normal
        for (double theta_h : {0.5 * (kPi / 3.0 + theta_o), 0.5 * (theta_o - kPi / 3.0), 0.5 * (kPi / 3.0 - theta_o),
                               0.5 * theta_o})
            if (theta_h > 0.0) breaks.push_back(0.5 * kPi - theta_h);
    std::sort(breaks.begin(), breaks.end());
    breaks.erase(std::remove_if(breaks.begin(), breaks.end(), [&](double b) { return !(b >= beta_2 && b <= beta_hi); }),
                 breaks.end());
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
    const double scale = kInvPi;  // E = (1/pi) integral over v of the azimuth integral over [0, pi]
    const std::size_t pieces = breaks.size() - 1;
    // Piece k of the breaks is s in [k, k + 1]: one adaptive integral over
    // all of them with one error budget.
    AdaptiveOptions opt;
    opt.abs_tol = 0.5 * abs_tol / scale;
    opt.controlled = 2;
    opt.max_intervals = 200 * static_cast<int>(std::max<std::size_t>(pieces, 1));
    const double ring_tol = 0.05 * opt.abs_tol / static_cast<double>(std::max<std::size_t>(pieces, 1));
    std::vector<double> ends;
    for (std::size_t k = 0; k <= pieces && pieces > 0; ++k) ends.push_back(static_cast<double>(k));
    const Estimate<3> e = integrate_adaptive_breaks<3>(
        [&](double sk) -> std::array<double, 3> {
            const std::size_t k = std::min(static_cast<std::size_t>(sk), pieces - 1);
            const double s = sk - static_cast<double>(k);
            const double b0 = breaks[k], b1 = breaks[k + 1];
            if (!(b1 > b0)) return {0.0, 0.0, 0.0};
            const bool flat_start = k == 0, flat_end = b1 == 0.5 * kPi;
            const double z0 = std::log(b0), len = std::log(b1) - z0;
            // s -> [0, 1]: 1 - (1 - s)^3 at the pole (EndMap), then
            // s^4 at the start (the whole ring at the horizon).
            const std::array<double, 2> m = EndMap{false, flat_end}(s);
            double x = m[0], dx = m[1];
            if (flat_start) {
                const double x3 = x * x * x;
                dx *= kClipPower * x3;
                x *= x3;
            }
            const HalfVectorAxis::Node node = axis.at(std::exp(z0 + len * x));
            const double weight = node.weight * len * dx;
            if (!(weight > 0.0)) return {0.0, 0.0, 0.0};
            const std::array<double, 3> f = ring(node.u, node.c, ring_tol / weight);
            return {f[0] * weight, f[1] * weight, f[2] * weight};
        },
        ends.data(), ends.size(), opt);
    const double inner_error = e.value[2] + e.error[2];
    // The neglected tail above beta_hi: dv below e^-span times the largest
    // weight, g <= 4 V mu_i / c <= 1 / (mu_o c), c >= sin(beta_hi).
    const double tail = kPi * axis.tail(1.0 / mu_o);
    for (std::size_t i = 0; i < 2; ++i) {
        out.value[i] = e.value[i] * scale;
        out.error[i] = (e.error[i] + inner_error + tail) * scale + 1e-16;
    }
    out.evaluations = evaluations;
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
