// Monte Carlo estimates of the GGX dielectric albedos, independent of the
// quadrature in ggx_glass.cpp. Each sample draws a normal m from a mixture:
// with probability 1 - kDefensive a visible normal (Heitz 2018, density
// p_v = G1(wo) (wo.m) D(m) / mu_o), else a normal whose x = ln(tan(theta_m) /
// alpha) is logistic with scale kTailScale (four times that of D, whose
// measure D cos(theta_m) dw_m is logistic in x with scale 1/2) and whose
// azimuth is uniform, or with probability kSkim a normal with wo.m = u^4
// and a uniform azimuth about wo. Both channels are weighed by the mixture's density p:
//   E_R: F(wo.m) G2(wo, wr) (wo.m) D(m) / (mu_o p(m))   when wr is above the horizon,
//   E_T: (1 - F(wo.m)) G2(wo, wt) (wo.m) D(m) / (mu_o p(m))   when wt is below it,
// with the directions built as vectors (not from the thresholds the
// quadrature splits at), and p_v / p serves as a control variate.
// Visible normals alone almost never draw the normals far from alpha's
// scale, whose share of the albedo is tiny but not negligible (the tail
// beyond tan(theta_m) = 1 at alpha = 1e-3; the normals within 1e-4 of the
// horizon, and at n = 1 + 2e-8 those with wo.m below 2e-4, where F rises
// to 1 in a layer of that width): with 1e5 samples none was drawn, and the
// standard error came out 30 times below the actual error. The other two
// components draw them, so the error sees them (the defensive mixture of
// Hesterberg 1995); the control variate keeps the error as small as the
// visible normals' alone where they suffice.
#include <cmath>

#include "brdflut/fresnel.h"
#include "brdflut/glass_integrals.h"
#include "brdflut/random.h"
#include "integrate/glass_detail.h"

namespace brdflut {
namespace {

constexpr double kDefensive = 0.2;  // share of the wide density in x
constexpr double kTailScale = 2.0;
constexpr double kSkim = 0.1;        // share of the density crowding wo.m -> 0
constexpr double kSkimPower = 4.0;   // wo.m = u^4: density (1/4) c^(-3/4) / (2 pi)

// The wide density over solid angle relative to D, q / D, as a function of
// x: q = logistic(x) / (2 pi sin^2 cos) and D = sech^2(x) / (4 pi sin^2 cos^2)
// (the measure D cos dw = sech^2(x) / 2 dx dphi / (2 pi)), so q / D =
// 2 cos(theta_m) logistic(x) / sech^2(x), written without the sin^2 that
// rounds to 0 near the pole (where q is largest).
double q_over_d(double x, double cos_m) {
    const double ax = std::abs(x);
    const double e = std::exp(-ax / kTailScale), e2 = std::exp(-2.0 * ax);
    return 2.0 * cos_m * std::exp(ax * (2.0 - 1.0 / kTailScale)) * (1.0 + e2) * (1.0 + e2) /
           (4.0 * kTailScale * (1.0 + e) * (1.0 + e));
}

// One sample: w = f / p of both channels, *cv = p_v / p - 1.
void sample(const Ggx& g, Visibility vis, double eta, const Vec3& wo, Rng& rng, double* w, double* cv) {
    w[0] = w[1] = 0.0;
    *cv = -1.0;
    const double u0 = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
    Vec3 m;
    double x;  // ln(tan(theta_m) / alpha)
    if (u0 < kSkim) {
        // wo.m = c = u1^4, the azimuth about wo uniform.
        const double c = std::pow(u1, kSkimPower), sc = safe_sqrt(1.0 - c * c);
        const double psi = 2.0 * kPi * u2, a = sc * std::cos(psi), b = sc * std::sin(psi);
        const double s_o = safe_sqrt(1.0 - wo.z * wo.z);  // wo = (s_o, 0, mu_o)
        m = {c * wo.x + a * wo.z, b, c * wo.z - a * s_o};
        x = std::log(std::hypot(m.x, m.y) / (m.z * g.alpha));
    } else if (u0 < kSkim + kDefensive) {
        if (!(u1 > 0.0)) return;  // x = -inf: a set of measure zero
        x = kTailScale * std::log(u1 / (1.0 - u1));
        const double t = g.alpha * std::exp(x), cos_m = 1.0 / std::sqrt(1.0 + t * t), sin_m = t * cos_m;
        const double phi = 2.0 * kPi * u2;
        m = {sin_m * std::cos(phi), sin_m * std::sin(phi), cos_m};
    } else {
        m = g.sample_visible_normal(wo, u1, u2);
        x = std::log(std::hypot(m.x, m.y) / (m.z * g.alpha));
    }
    const double c = dot(wo, m);
    if (!(c > 0.0) || !(m.z > 0.0)) return;
    // f / p = K (wo.m) D / (mu_o p) with p = (1 - b - s) p_v + b q + s r,
    // that is K / ((1 - b - s) G1 + b mu_o (q / D) / (wo.m) + s mu_o r / ((wo.m) D)),
    // r = c^(1/4 - 1) / (4 2 pi) the density of the normals crowding wo.m -> 0.
    const double q_over = std::isfinite(x) ? wo.z * q_over_d(x, m.z) / c : HUGE_VAL;
    const double r = std::pow(c, 1.0 / kSkimPower - 1.0) / (kSkimPower * 2.0 * kPi);
    const double r_over = wo.z * r / (c * g.D(m.z));
    const double den = (1.0 - kDefensive - kSkim) * g.G1(wo.z) + kDefensive * q_over + kSkim * r_over;
    if (!(den > 0.0) || !std::isfinite(den)) return;
    *cv = g.G1(wo.z) / den - 1.0;
    const double F = fresnel_dielectric(std::min(c, 1.0), eta);
    // Reflection wr = 2 c m - wo.
    const double mu_r = 2.0 * c * m.z - wo.z;
    if (mu_r > 0.0) w[0] = F * g.G2(wo.z, mu_r, vis) / den;
    // Refraction wt = -wo / eta + (c / eta - cos_t) m.
    const double ct2 = 1.0 - (1.0 - c * c) / (eta * eta);
    if (ct2 > 0.0 && F < 1.0) {
        const double b = c / eta - std::sqrt(ct2);
        const Vec3 wt{-wo.x / eta + b * m.x, -wo.y / eta + b * m.y, -wo.z / eta + b * m.z};
        if (wt.z < 0.0) w[1] = (1.0 - F) * g.G2(wo.z, -wt.z, vis) / den;
    }
}

// The weights y = f / p of the two channels and the control variate
// x = p_v / p - 1, whose mean is 0 because p_v integrates to 1. The estimate
// is the regression estimate mean(y) - b mean(x), b fitted per channel, and
// its standard error comes from the residuals y - b x (Owen and Zhou 2000,
// "Safe and effective importance sampling"). Where the visible normals alone
// would give a weight of no spread (f = k p_v, as at n = 1) the residuals
// vanish too, and the spread the wide density adds between the two kinds
// of samples does not enter the error.
struct RegressionAccumulator {
    long long n = 0;
    double mx = 0.0, sxx = 0.0;
    double my[2] = {}, sxy[2] = {}, syy[2] = {};
    void add(const double* y, double x) {
        ++n;
        const double inv = 1.0 / static_cast<double>(n);
        const double dx = x - mx;
        mx += dx * inv;
        sxx += dx * (x - mx);
        for (int i = 0; i < 2; ++i) {
            const double dy = y[i] - my[i];
            my[i] += dy * inv;
            sxy[i] += dx * (y[i] - my[i]);
            syy[i] += dy * (y[i] - my[i]);
        }
    }
    Estimate<2> estimate() const {
        Estimate<2> e;
        for (int i = 0; i < 2; ++i) {
            const std::size_t k = static_cast<std::size_t>(i);
            const double b = sxx > 0.0 ? sxy[i] / sxx : 0.0;
            e.value[k] = my[i] - b * mx;
            // The residual sum loses what rounding leaves of syy when the fit
            // is nearly exact (as at n = 1): never below 1e-15 of syy.
            const double rss = std::max(1e-15 * syy[i], syy[i] - b * sxy[i]);
            e.error[k] = n > 2 ? std::sqrt(rss / static_cast<double>(n - 2) / static_cast<double>(n)) : HUGE_VAL;
        }
        e.evaluations = static_cast<int>(std::min<long long>(n, 1 << 30));
        return e;
    }
};

}  // namespace

Estimate<2> ggx_glass_mc(double mu_o, double alpha, double eta, Visibility vis, long long samples,
                         std::uint64_t seed) {
    if (!(mu_o >= 0.0) || !(eta > 0.0)) return {};
    mu_o = std::clamp(mu_o, detail::kGlassGrazingMu, 1.0);
    if (!(alpha > 0.0)) return detail::glass_smooth_limit(mu_o, eta);  // a delta lobe: nothing to sample
    const Ggx g{alpha};
    const Vec3 wo = direction_from_mu(mu_o);
    Rng rng(seed, 0);
    RegressionAccumulator acc;
    for (long long s = 0; s < samples; ++s) {
        double w[2], cv;
        sample(g, vis, eta, wo, rng, w, &cv);
        acc.add(w, cv);
    }
    return acc.estimate();
}

Estimate<2> ggx_glass_average_mc(double alpha, double eta, Visibility vis, long long samples,
                                 std::uint64_t seed) {
    if (!(eta > 0.0)) return {};
    const Ggx g{alpha};
    Rng rng(seed, 1);
    RegressionAccumulator acc;
    for (long long s = 0; s < samples; ++s) {
        // mu with density 2 mu on [0, 1]: mu = sqrt(u); 1 - u keeps mu > 0.
        const double mu = std::sqrt(1.0 - rng.uniform());
        double w[2], cv = 0.0;
        if (alpha > 0.0) {
            sample(g, vis, eta, direction_from_mu(mu), rng, w, &cv);
        } else {
            const Estimate<2> e = detail::glass_smooth_limit(mu, eta);
            w[0] = e.value[0];
            w[1] = e.value[1];
        }
        acc.add(w, cv);
    }
    return acc.estimate();
}

}  // namespace brdflut
