#include "brdflut/beam_diffusion.h"

#include <algorithm>
#include <cmath>
#include <cstdint>


#include "brdflut/fresnel.h"
#include "brdflut/math.h"

namespace brdflut {
namespace {

// Where the integrals are cut: the weights e^(-sigma'_t z) and
// e^(-sigma_t (t - t_c)) are below e^(-50) beyond; the part left out is
// bounded in closed form and added to the error.
constexpr double kDepthCut = 50.0;

// Integral of f over [breaks[0], breaks.back()], panel by panel, to a
// relative tolerance: one Gauss-Kronrod (10, 21) panel per interval gives
// the size V of the integral, then the panel of largest error is bisected
// until the summed error is below rel_tol |V| (over the first `controlled`
// channels, relative to the largest of them).
template <std::size_t N, class F>
Estimate<N> integrate_breaks(F&& f, const std::vector<double>& breaks, double rel_tol, std::size_t controlled = N) {
    Estimate<N> out;
    AdaptiveOptions opt;
    opt.rule = KronrodRule::k21;
    opt.max_intervals = 400;
    opt.controlled = controlled;
    std::vector<detail::Interval<N>> panels = detail::interval_heap<N>(breaks.size() - 1, opt);
    double size = 0.0;
    {
        std::array<double, N> v{};
        for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
            panels.push_back(detail::kronrod_panel<N>(f, breaks[k], breaks[k + 1], controlled, KronrodRule::k21));
            for (std::size_t c = 0; c < N; ++c) v[c] += panels.back().value[c];
        }
        for (std::size_t c = 0; c < controlled && c < N; ++c) size = std::max(size, std::abs(v[c]));
        out.evaluations = static_cast<int>(21 * panels.size());
    }
    opt.abs_tol = std::max(rel_tol * size, 1e-300);
    return detail::adaptive_from<N>(f, std::move(panels), opt, out);
}

// 0, then s, 4 s, 16 s, .. up to hi (the last break is hi).
std::vector<double> geometric_breaks(double s, double hi) {
    std::vector<double> b{0.0};
    for (double x = s; x < hi; x *= 4.0) b.push_back(x);
    b.push_back(hi);
    return b;
}

double pbrt_exp(double x, PbrtExp e) { return e == PbrtExp::fast ? pbrt_fast_exp(x) : std::exp(x); }

}  // namespace

double fresnel_moment1_fit(double eta) {
    const double e2 = eta * eta, e3 = e2 * eta, e4 = e3 * eta, e5 = e4 * eta;
    if (eta < 1.0) return 0.45966 - 1.73965 * eta + 3.37668 * e2 - 3.904945 * e3 + 2.49277 * e4 - 0.68441 * e5;
    return -4.61686 + 11.1136 * eta - 10.4646 * e2 + 5.11455 * e3 - 1.27198 * e4 + 0.12746 * e5;
}

double fresnel_moment2_fit(double eta) {
    const double e2 = eta * eta, e3 = e2 * eta, e4 = e3 * eta, e5 = e4 * eta;
    if (eta < 1.0) return 0.27614 - 0.87350 * eta + 1.12077 * e2 - 0.65095 * e3 + 0.07883 * e4 + 0.04860 * e5;
    const double r = 1.0 / eta, r2 = r * r, r3 = r2 * r;
    return -547.033 + 45.3087 * r3 - 218.725 * r2 + 458.843 * r + 404.557 * eta - 189.519 * e2 + 54.9327 * e3 -
           9.00603 * e4 + 0.63942 * e5;
}

double henyey_greenstein_pbrt(double c, double g) {
    g = std::clamp(g, -0.99, 0.99);
    const double denom = 1.0 + g * g + 2.0 * g * c;
    return (1.0 - g * g) / (4.0 * kPi * denom * std::sqrt(std::max(denom, 0.0)));
}

double pbrt_fast_exp(double x) {
    // e^x = 2^(x log2 e) = 2^i 2^f, 2^f by pbrt's cubic on [0, 1).
    const double xp = x * 1.442695041;
    const double i = std::floor(xp), f = xp - i;
    const double two_f = 1.0 + f * (0.695556856 + f * (0.226173572 + f * 0.0781455737));
    if (i + std::ilogb(two_f) < -126) return 0.0;
    return std::ldexp(two_f, static_cast<int>(std::max(i, -2000.0)));
}

BeamDiffusion::BeamDiffusion(double rho, double g, double eta) : rho_(rho), g_(g), eta_(eta) {
    const double sigma_a = 1.0 - rho, sigmap_s = rho * (1.0 - g);
    sigmap_t_ = sigma_a + sigmap_s;
    rhop_ = sigmap_s / sigmap_t_;
    D_ = (2.0 * sigma_a + sigmap_s) / (3.0 * sigmap_t_ * sigmap_t_);
    sigma_tr_ = std::sqrt(std::max(0.0, sigma_a / D_));
    const double m1 = fresnel_moment1_fit(eta), m2 = fresnel_moment2_fit(eta);
    ze_ = -2.0 * D_ * (1.0 + 3.0 * m2) / (1.0 - 2.0 * m1);
    cphi_ = 0.25 * (1.0 - 2.0 * m1);
    ce_ = 0.5 * (1.0 - 3.0 * m2);
    crit_slope_ = std::sqrt(std::max(0.0, eta * eta - 1.0));
}

double BeamDiffusion::ms_integrand(double z, double r) const {
    const double zv = 2.0 * ze_ - z;
    const double dr = std::sqrt(r * r + z * z), dv = std::sqrt(r * r + zv * zv);
    const double er = std::exp(-sigma_tr_ * dr), ev = std::exp(-sigma_tr_ * dv);
    const double phi = (er / dr - ev / dv) / (4.0 * kPi * D_);
    const double edn =
        (z * (1.0 + sigma_tr_ * dr) * er / (dr * dr * dr) - zv * (1.0 + sigma_tr_ * dv) * ev / (dv * dv * dv)) /
        (4.0 * kPi);
    const double kappa = -std::expm1(-2.0 * sigmap_t_ * (dr + z));
    return sigmap_t_ * std::exp(-sigmap_t_ * z) * kappa * rhop_ * rhop_ * (cphi_ * phi + ce_ * edn);
}

double BeamDiffusion::ss_integrand(double t, double r) const {
    const double d = std::sqrt(r * r + t * t);
    const double c = t / d;
    const double transmit = 1.0 - fresnel_dielectric(std::min(c, 1.0), 1.0 / eta_);
    return rho_ * std::exp(-(t + d)) / (d * d) * henyey_greenstein_pbrt(c, g_) * transmit * c;
}

Estimate<1> BeamDiffusion::weighted_ms(double r, double rel_tol) const {
    Estimate<1> out;
    if (r <= 0.0 || rhop_ == 0.0) return out;  // 2 pi r Sr_ms -> 0 (Sr_ms grows as ln(1/r))
    const double zmax = kDepthCut / sigmap_t_;
    const auto f = [&](double z) { return std::array<double, 1>{ms_integrand(z, r)}; };
    out = integrate_breaks<1>(f, geometric_breaks(0.5 * std::min(r, 0.25), zmax), rel_tol);
    // Beyond zmax: kappa <= 1, z/dr^3 and |zv|/dv^3 <= 1/d^2, and
    // e^(-s d)/d, (1 + s d) e^(-s d)/d^2 fall with d >= dmin.
    const double dmin = std::sqrt(r * r + zmax * zmax), e = std::exp(-sigma_tr_ * dmin);
    const double bound = std::exp(-kDepthCut) * rhop_ * rhop_ *
                         (std::abs(cphi_) * 2.0 * e / (4.0 * kPi * D_ * dmin) +
                          std::abs(ce_) * 2.0 * (1.0 + sigma_tr_ * dmin) * e / (4.0 * kPi * dmin * dmin));
    out.value[0] *= kTwoPi * r;
    out.error[0] = kTwoPi * r * (out.error[0] + bound);
    return out;
}

Estimate<1> BeamDiffusion::weighted_ss(double r, double rel_tol) const {
    if (r <= 0.0) {
        Estimate<1> out;
        out.value[0] = weighted_ss_at_zero(rel_tol, &out.error[0]);
        return out;
    }
    const double tc = t_crit(r);
    // t = t_c + w^2: the transmission rises as sqrt(t - t_c) from the
    // critical angle, so the integrand in w is smooth there.
    const double wmax = std::sqrt(kDepthCut);
    const auto f = [&](double w) { return std::array<double, 1>{2.0 * w * ss_integrand(tc + w * w, r)}; };
    Estimate<1> out = integrate_breaks<1>(f, geometric_breaks(0.25 * std::sqrt(std::min(r, 1.0)), wmax), rel_tol);
    // Beyond: T, c <= 1, p <= (1 + |g|)/(4 pi (1 - |g|)^2), d >= dmin.
    const double ga = std::min(std::abs(g_), 0.99);
    const double tmin = tc + kDepthCut, dmin = std::sqrt(r * r + tmin * tmin);
    const double bound = rho_ * std::exp(-(tmin + dmin)) / (dmin * dmin) * (1.0 + ga) / (4.0 * kPi * (1.0 - ga) * (1.0 - ga));
    out.value[0] *= kTwoPi * r;
    out.error[0] = kTwoPi * r * (out.error[0] + bound);
    return out;
}

double BeamDiffusion::weighted_ss_at_zero(double rel_tol, double* error) const {
    // 2 pi rho integral over [0, theta_c] of p T cos(theta) dtheta, theta =
    // theta_c - v^2 (T rises as sqrt(theta_c - theta)).
    const double theta_c = eta_ > 1.0 ? std::asin(1.0 / eta_) : 0.5 * kPi;
    const double vmax = std::sqrt(theta_c);
    const auto f = [&](double v) {
        const double c = std::cos(theta_c - v * v);
        const double transmit = 1.0 - fresnel_dielectric(c, 1.0 / eta_);
        return std::array<double, 1>{2.0 * v * henyey_greenstein_pbrt(c, g_) * transmit * c};
    };
    const Estimate<1> e = integrate_breaks<1>(f, {0.0, 0.5 * vmax, vmax}, rel_tol);
    if (error) *error = kTwoPi * rho_ * e.error[0];
    return kTwoPi * rho_ * e.value[0];
}

double BeamDiffusion::weighted_ms_midpoint(double r, int n, PbrtExp ex) const {
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double z = -std::log(1.0 - (i + 0.5) / n) / sigmap_t_;
        const double zv = 2.0 * ze_ - z;
        const double dr = std::sqrt(r * r + z * z), dv = std::sqrt(r * r + zv * zv);
        const double er = pbrt_exp(-sigma_tr_ * dr, ex), ev = pbrt_exp(-sigma_tr_ * dv, ex);
        const double phi = (er / dr - ev / dv) / (4.0 * kPi * D_);
        const double edn =
            (z * (1.0 + sigma_tr_ * dr) * er / (dr * dr * dr) - zv * (1.0 + sigma_tr_ * dv) * ev / (dv * dv * dv)) /
            (4.0 * kPi);
        const double kappa = 1.0 - pbrt_exp(-2.0 * sigmap_t_ * (dr + z), ex);
        sum += kappa * rhop_ * rhop_ * (cphi_ * phi + ce_ * edn);
    }
    return kTwoPi * r * sum / n;
}

double BeamDiffusion::weighted_ss_midpoint(double r, int n, PbrtExp ex) const {
    const double tc = t_crit(r);
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double t = tc - std::log(1.0 - (i + 0.5) / n);
        const double d = std::sqrt(r * r + t * t), c = t / d;
        sum += rho_ * pbrt_exp(-(d + tc), ex) / (d * d) * henyey_greenstein_pbrt(c, g_) *
               (1.0 - fresnel_dielectric(std::min(c, 1.0), 1.0 / eta_)) * c;
    }
    return kTwoPi * r * sum / n;
}

Estimate<2> BeamDiffusion::rho_eff(double rel_tol) const {
    // Over r in [r_lo, 1] in y = ln r (2 pi r Sr is finite at 0: the part
    // below r_lo is at most about r_lo times its value there, added to the
    // error) and over [1, inf) in w = 1/r (2 pi r Sr falls as e^(-sigma_tr r)
    // or, at rho = 1, as 1/r^2: smooth in w up to w = 0). Inner integrals to
    // rel_tol / 10; their error estimates are integrated alongside.
    const double inner = 0.1 * rel_tol;
    const auto at = [&](double r) {
        const Estimate<1> s = weighted_ss(r, inner), m = weighted_ms(r, inner);
        return std::array<double, 4>{s.value[0], m.value[0], s.error[0], m.error[0]};
    };
    const double r_lo = 1e-14;
    const auto near = [&](double y) {
        const double r = std::exp(y);
        auto v = at(r);
        for (double& x : v) x *= r;
        return v;
    };
    const auto far = [&](double w) {
        if (w <= 0.0) {
            // The limit w -> 0 of (2 pi r Sr)(1/w) / w^2: 0 unless sigma_tr = 0,
            // where 2 pi r Sr ~ C / r^2: C from a large radius.
            if (sigma_tr_ > 0.0) return std::array<double, 4>{};
            const double r = 1e6;
            auto v = at(r);
            for (double& x : v) x *= r * r;
            return v;
        }
        const double r = 1.0 / w;
        auto v = at(r);
        for (double& x : v) x *= r * r;
        return v;
    };
    std::vector<double> ybreaks;
    for (double y = std::log(r_lo); y < 0.0; y += 4.0) ybreaks.push_back(y);
    ybreaks.push_back(0.0);
    const Estimate<4> a = integrate_breaks<4>(near, ybreaks, rel_tol, 2);
    const Estimate<4> b = integrate_breaks<4>(far, {0.0, 0.03125, 0.125, 0.5, 1.0}, rel_tol, 2);
    const auto low = at(r_lo);
    Estimate<2> out;
    for (std::size_t c = 0; c < 2; ++c) {
        out.value[c] = a.value[c] + b.value[c];
        out.error[c] = a.error[c] + b.error[c] + a.value[c + 2] + b.value[c + 2] + 2.0 * r_lo * std::abs(low[c]);
    }
    out.evaluations = a.evaluations + b.evaluations;
    return out;
}

std::vector<double> pbrt_rho_samples(int n) {
    std::vector<double> v(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        v[static_cast<std::size_t>(i)] = std::expm1(-8.0 * i / (n - 1.0)) / std::expm1(-8.0);
    return v;
}

std::vector<double> pbrt_radius_samples(int n) {
    std::vector<double> v(static_cast<std::size_t>(n), 0.0);
    if (n > 1) v[1] = 2.5e-3;
    for (std::size_t j = 2; j < v.size(); ++j) v[j] = v[j - 1] * 1.2;
    return v;
}

namespace {
// The Catmull-Rom segment i of f over nodes: its end values and the slopes
// times the width (finite differences, one-sided at the ends).
struct Segment {
    double x0, width, f0, f1, d0, d1;
};
Segment catmull_rom_segment(const std::vector<double>& x, const std::vector<double>& f, std::size_t i) {
    Segment s{x[i], x[i + 1] - x[i], f[i], f[i + 1], 0.0, 0.0};
    s.d0 = i > 0 ? s.width * (f[i + 1] - f[i - 1]) / (x[i + 1] - x[i - 1]) : f[i + 1] - f[i];
    s.d1 = i + 2 < x.size() ? s.width * (f[i + 2] - f[i]) / (x[i + 2] - x[i]) : f[i + 1] - f[i];
    return s;
}
}  // namespace

double catmull_rom_integral(const std::vector<double>& nodes, const std::vector<double>& f) {
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
        const Segment s = catmull_rom_segment(nodes, f, i);
        sum += s.width * (0.5 * (s.f0 + s.f1) + (s.d0 - s.d1) / 12.0);
    }
    return sum;
}

double catmull_rom_invert(const std::vector<double>& nodes, const std::vector<double>& f, double y) {
    if (!(y > f.front())) return nodes.front();
    if (!(y < f.back())) return nodes.back();
    std::size_t i = static_cast<std::size_t>(std::upper_bound(f.begin(), f.end(), y) - f.begin()) - 1;
    i = std::min(i, f.size() - 2);
    const Segment s = catmull_rom_segment(nodes, f, i);
    // The Hermite cubic on t in [0, 1] rises from f0 to f1: bisection
    // (to the last bit of t) finds where it reaches y.
    const auto value = [&](double t) {
        const double t2 = t * t, t3 = t2 * t;
        return (2 * t3 - 3 * t2 + 1) * s.f0 + (-2 * t3 + 3 * t2) * s.f1 + (t3 - 2 * t2 + t) * s.d0 + (t3 - t2) * s.d1;
    };
    double lo = 0.0, hi = 1.0;
    for (int k = 0; k < 60; ++k) {
        const double m = 0.5 * (lo + hi);
        (value(m) < y ? lo : hi) = m;
    }
    return s.x0 + 0.5 * (lo + hi) * s.width;
}

RhoEffInverse::RhoEffInverse(double g, double eta, double rel_tol) : g_(g), eta_(eta), tol_(rel_tol) {
    for (int k = 0; k <= 32; ++k) {
        x_.push_back(k / 32.0);
        f_.push_back(rho_eff_of_x(x_.back(), 1e-7));
    }
}

double RhoEffInverse::rho_eff_of_x(double x, double rel_tol, double* error) const {
    const double s = 1.0 - x;
    const Estimate<2> e = BeamDiffusion(1.0 - s * s, g_, eta_).rho_eff(rel_tol);
    if (error) *error = e.error[0] + e.error[1];
    return e.value[0] + e.value[1];
}

double RhoEffInverse::albedo(double target, double* error) const {
    if (error) *error = 0.0;
    if (!(target > 0.0)) return 0.0;
    if (!(target < f_.back())) return 1.0;  // unreachable (the guess nodes' rho_eff(1)), clamped
    // The bracket: the guess nodes around the target, one more on each side
    // (their values are only good to 1e-7).
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(f_.begin(), f_.end(), target) - f_.begin());
    double lo = x_[k >= 2 ? k - 2 : 0], hi = x_[std::min(k + 1, x_.size() - 1)];
    double xa = std::clamp(catmull_rom_invert(x_, f_, target), lo, hi);
    double ea = 0.0, ha = rho_eff_of_x(xa, tol_, &ea) - target;
    double xb = xa + (xa + 1e-6 <= hi ? 1e-6 : -1e-6), eb = 0.0, hb = rho_eff_of_x(xb, tol_, &eb) - target;
    double step = std::abs(xb - xa);
    for (int it = 0; it < 40 && step > 1e-12 && std::abs(hb) > eb; ++it) {
        // Keep the bracket from the signs seen (rho_eff rises with x).
        if (ha < 0.0) lo = std::max(lo, xa); else hi = std::min(hi, xa);
        if (hb < 0.0) lo = std::max(lo, xb); else hi = std::min(hi, xb);
        double xn = hb != ha ? xb - hb * (xb - xa) / (hb - ha) : 0.5 * (lo + hi);
        if (!(xn > lo && xn < hi)) xn = 0.5 * (lo + hi);
        step = std::abs(xn - xb);
        xa = xb;
        ha = hb;
        ea = eb;
        xb = xn;
        hb = rho_eff_of_x(xb, tol_, &eb) - target;
    }
    if (error) {
        const double slope = std::abs((hb - ha) / (xb - xa));
        // Stopped on the residual: the root is within it (plus rho_eff's
        // error) over the slope; on the step: add the step.
        const double xerr = (std::abs(hb) <= eb ? 0.0 : step) + (slope > 0.0 ? (std::abs(hb) + eb) / slope : 1.0);
        *error = 2.0 * (1.0 - xb) * xerr + xerr * xerr;
    }
    const double s = 1.0 - xb;
    return 1.0 - s * s;
}

}  // namespace brdflut
