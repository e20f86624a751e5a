// Pre-integrated skin: the profiles, the ring and sphere integrals by
// adaptive Gauss-Kronrod and by graded Gauss-Legendre, and Monte Carlo.
#include "brdflut/skin.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "brdflut/burley.h"
#include "brdflut/error.h"
#include "brdflut/math.h"
#include "brdflut/random.h"

namespace brdflut {

namespace {
constexpr double kEps = std::numeric_limits<double>::epsilon();
}  // namespace

std::string_view to_string(SkinGeometry g) { return g == SkinGeometry::ring ? "ring" : "sphere"; }

SkinGeometry skin_geometry_from_string(std::string_view s) {
    if (s == "ring") return SkinGeometry::ring;
    if (s == "sphere") return SkinGeometry::sphere;
    throw Error("--geometry '" + std::string(s) + "' is not known; allowed: ring, sphere");
}

RadialProfile RadialProfile::burley(double albedo, double d) {
    RadialProfile p(Kind::burley);
    p.A_ = albedo;
    p.d_ = d;
    return p;
}

RadialProfile RadialProfile::dipole(const Dipole& d) {
    RadialProfile p(Kind::dipole);
    p.dipole_ = d;
    return p;
}

RadialProfile RadialProfile::gaussians(std::vector<std::pair<double, double>> wv) {
    RadialProfile p(Kind::gaussians);
    p.g_ = std::move(wv);
    return p;
}

double RadialProfile::value(double r) const {
    switch (kind_) {
        case Kind::burley: return A_ * burley_profile(r / d_) / (d_ * d_);
        case Kind::dipole: return dipole_.profile(r);
        case Kind::gaussians: {
            double s = 0.0;
            for (const auto& [w, v] : g_) s += w * std::exp(-r * r / (2.0 * v)) / (kTwoPi * v);
            return s;
        }
    }
    return 0.0;
}

double RadialProfile::radial(double r) const {
    if (kind_ == Kind::burley) return A_ * burley_radial_density(r / d_) / d_;
    return kTwoPi * r * value(r);
}

double RadialProfile::within(double r) const {
    switch (kind_) {
        case Kind::burley: return A_ * burley_cdf(r / d_);
        case Kind::dipole: return dipole_.reflectance_within(r);
        case Kind::gaussians: {
            double s = 0.0;
            for (const auto& [w, v] : g_) s += std::isinf(r) ? w : -w * std::expm1(-r * r / (2.0 * v));
            return s;
        }
    }
    return 0.0;
}

double RadialProfile::scale() const {
    switch (kind_) {
        case Kind::burley: return d_;
        case Kind::dipole: return dipole_.z_r();
        case Kind::gaussians: {
            double s = HUGE_VAL;
            for (const auto& [w, v] : g_)
                if (w > 0.0) s = std::min(s, std::sqrt(v));
            return s;
        }
    }
    return 1.0;
}

double RadialProfile::sample_radius(double u, double r_max) const {
    if (kind_ == Kind::burley) return d_ * burley_inverse_cdf(u * burley_cdf(r_max / d_));
    const double target = u * within(r_max);
    double lo = 0.0, hi = r_max;
    for (int it = 0; it < 200 && hi - lo > 4.0 * kEps * hi; ++it) {
        const double mid = 0.5 * (lo + hi);
        if (within(mid) < target) lo = mid; else hi = mid;
    }
    return 0.5 * (lo + hi);
}

const std::vector<SkinGaussian>& deon_skin_gaussians() {
    // d'Eon and Luebke 2007, GPU Gems 3, ch. 14, as Jimenez and Gutierrez's
    // 2009 screen-space SSS fitting script quotes them: the variances (mm^2)
    // and the red, green and blue weights of the six Gaussians whose sum fits
    // a three-layer skin model; each channel's weights add to 1.
    static const std::vector<SkinGaussian> g = {
        {0.0064, {0.233, 0.455, 0.649}}, {0.0484, {0.100, 0.336, 0.344}}, {0.187, {0.118, 0.198, 0.0}},
        {0.567, {0.113, 0.007, 0.007}},  {1.99, {0.358, 0.004, 0.0}},     {7.41, {0.078, 0.0, 0.0}},
    };
    return g;
}

SkinProfile deon_skin_profile() {
    std::array<std::vector<std::pair<double, double>>, 3> wv;
    for (const SkinGaussian& g : deon_skin_gaussians())
        for (std::size_t c = 0; c < 3; ++c)
            if (g.weight[c] > 0.0) wv[c].push_back({g.weight[c], g.variance});
    return {RadialProfile::gaussians(wv[0]), RadialProfile::gaussians(wv[1]), RadialProfile::gaussians(wv[2])};
}

double clamped_cosine_azimuth_mean(double a, double b) {
    if (a >= b) return a;
    if (a <= -b) return 0.0;
    const double c = -a / b;  // in (-1, 1)
    const double phi0 = std::acos(c);
    return (a * phi0 + b * std::sqrt((1.0 - c) * (1.0 + c))) / kPi;
}

namespace {

void check_arguments(const SkinProfile& p, SkinGeometry g, double n_dot_l, double curvature) {
    if (!(n_dot_l >= -1.0 && n_dot_l <= 1.0))
        throw Error("n_dot_l " + std::to_string(n_dot_l) + " is out of range; allowed: -1 to 1");
    if (!(curvature >= 0.0) || std::isinf(curvature))
        throw Error("curvature " + std::to_string(curvature) + " is not valid; allowed: finite, >= 0");
    if (g == SkinGeometry::ring)
        for (const RadialProfile& r : p)
            if (!r.finite_at_origin())
                throw Error("the ring integral of a profile infinite at r = 0 (Burley's) diverges; "
                            "allowed: --geometry sphere");
}

// Where the integrands have kinks on [0, pi], cos(theta -+ x) = 0: 0,
// |pi/2 - theta|, pi/2 + theta and 3 pi/2 - theta (those inside), sorted,
// without repeats.
std::vector<double> breakpoints(double theta) {
    std::vector<double> b{0.0, kPi};
    for (double x : {std::abs(0.5 * kPi - theta), 0.5 * kPi + theta, 1.5 * kPi - theta})
        if (x > 0.0 && x < kPi) b.push_back(x);
    std::sort(b.begin(), b.end());
    b.erase(std::unique(b.begin(), b.end()), b.end());
    return b;
}

// The breakpoints and, below the first kink, points doubling from a quarter
// of the narrowest profile's angular width scale / rho: the profile's peak
// at x = 0 is then inside a panel of its own size, however flat the sphere
// (a first panel as wide as the kink would put no node on it).
std::vector<double> adaptive_breakpoints(const SkinProfile& p, double theta, double rho) {
    std::vector<double> b = breakpoints(theta);
    double w = HUGE_VAL;
    for (const RadialProfile& r : p) w = std::min(w, r.scale());
    for (double x = 0.25 * w / rho; x < 0.5 * b[1]; x *= 2.0) b.push_back(x);
    std::sort(b.begin(), b.end());
    return b;
}

// The ring's weight cos+(theta + x) + cos+(theta - x), x in [0, pi].
double ring_weight(double theta, double x) {
    return std::max(0.0, std::cos(theta + x)) + std::max(0.0, std::cos(theta - x));
}

template <std::size_t N, class F>
Estimate<N> integrate_segments(F& f, const std::vector<double>& b, AdaptiveOptions opt) {
    Estimate<N> out;
    opt.abs_tol /= static_cast<double>(b.size() - 1);
    for (std::size_t s = 0; s + 1 < b.size(); ++s) {
        const Estimate<N> e = integrate_adaptive<N>(f, b[s], b[s + 1], opt);
        for (std::size_t i = 0; i < N; ++i) {
            out.value[i] += e.value[i];
            out.error[i] += e.error[i];
        }
        out.evaluations += e.evaluations;
    }
    return out;
}

Estimate<3> limit(double n_dot_l) {
    Estimate<3> out;
    out.value.fill(std::max(0.0, n_dot_l));
    return out;
}

}  // namespace

Estimate<3> preintegrated_skin(const SkinProfile& p, SkinGeometry g, double n_dot_l, double curvature,
                               double abs_tol) {
    check_arguments(p, g, n_dot_l, curvature);
    if (curvature == 0.0) return limit(n_dot_l);
    const double rho = 1.0 / curvature;
    const double theta = std::acos(n_dot_l);
    const std::vector<double> b = adaptive_breakpoints(p, theta, rho);
    AdaptiveOptions opt;
    opt.max_intervals = 4000;
    opt.rule = KronrodRule::k21;
    Estimate<3> out;
    if (g == SkinGeometry::sphere) {
        std::array<double, 3> inv_w{};
        for (std::size_t c = 0; c < 3; ++c) inv_w[c] = 1.0 / p[c].within(2.0 * rho);
        const double ct = std::cos(theta), st = std::sin(theta);
        auto f = [&](double alpha) {
            const double r = 2.0 * rho * std::sin(0.5 * alpha);
            const double k = clamped_cosine_azimuth_mean(ct * std::cos(alpha), st * std::sin(alpha));
            const double jac = rho * std::cos(0.5 * alpha);
            std::array<double, 3> y{};
            for (std::size_t c = 0; c < 3; ++c) y[c] = k * p[c].radial(r) * jac * inv_w[c];
            return y;
        };
        opt.abs_tol = 0.5 * abs_tol;
        out = integrate_segments<3>(f, b, opt);
        for (std::size_t c = 0; c < 3; ++c) out.error[c] += 16.0 * kEps * (1.0 + std::abs(out.value[c]));
        return out;
    }
    // Ring. First pass: the scale of each channel's denominator.
    auto den = [&](double x) {
        const double r = 2.0 * rho * std::sin(0.5 * x);
        return std::array<double, 3>{p[0].value(r), p[1].value(r), p[2].value(r)};
    };
    AdaptiveOptions rough = opt;
    rough.abs_tol = 0.0;
    rough.max_intervals = 24;
    const Estimate<3> scale = integrate_segments<3>(den, b, rough);
    std::array<double, 3> inv_s{};
    for (std::size_t c = 0; c < 3; ++c) inv_s[c] = scale.value[c] > 0.0 ? 1.0 / scale.value[c] : 1.0;
    // Second pass: numerator and denominator, each over the first estimate.
    auto both = [&](double x) {
        const double r = 2.0 * rho * std::sin(0.5 * x);
        const double w = ring_weight(theta, x);
        std::array<double, 6> y{};
        for (std::size_t c = 0; c < 3; ++c) {
            const double v = p[c].value(r) * inv_s[c];
            y[c] = w * v;
            y[3 + c] = 2.0 * v;
        }
        return y;
    };
    opt.abs_tol = 0.25 * abs_tol;
    const Estimate<6> e = integrate_segments<6>(both, b, opt);
    out.evaluations = scale.evaluations + e.evaluations;
    for (std::size_t c = 0; c < 3; ++c) {
        const double num = e.value[c], d = e.value[3 + c];
        out.value[c] = num / d;
        out.error[c] = e.error[c] / d + std::abs(out.value[c]) * e.error[3 + c] / d +
                       16.0 * kEps * (1.0 + std::abs(out.value[c]));
    }
    return out;
}

std::array<double, 3> preintegrated_skin_gauss(const SkinProfile& p, SkinGeometry g, double n_dot_l,
                                               double curvature) {
    check_arguments(p, g, n_dot_l, curvature);
    if (curvature == 0.0) return limit(n_dot_l).value;
    const double rho = 1.0 / curvature;
    const double theta = std::acos(n_dot_l);
    const std::vector<double> b = breakpoints(theta);
    // Panels graded geometrically towards every breakpoint, from both sides.
    std::vector<double> pts = b;
    for (std::size_t s = 0; s + 1 < b.size(); ++s) {
        const double len = b[s + 1] - b[s];
        for (int j = 1; j <= 50; ++j) {
            const double h = len * std::ldexp(1.0, -j);
            pts.push_back(b[s] + h);
            pts.push_back(b[s + 1] - h);
        }
    }
    std::sort(pts.begin(), pts.end());
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    const double ct = std::cos(theta), st = std::sin(theta);
    auto f = [&](double x) {
        const double r = 2.0 * rho * std::sin(0.5 * x);
        std::array<double, 6> y{};
        if (g == SkinGeometry::sphere) {
            const double k = clamped_cosine_azimuth_mean(ct * std::cos(x), st * std::sin(x));
            const double jac = rho * std::cos(0.5 * x);
            for (std::size_t c = 0; c < 3; ++c) {
                y[3 + c] = p[c].radial(r) * jac;
                y[c] = k * y[3 + c];
            }
        } else {
            const double w = ring_weight(theta, x);
            for (std::size_t c = 0; c < 3; ++c) {
                y[3 + c] = 2.0 * p[c].value(r);
                y[c] = 0.5 * w * y[3 + c];
            }
        }
        return y;
    };
    std::array<double, 6> sum{};
    for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
        const std::array<double, 6> s = integrate_gauss<6>(f, pts[k], pts[k + 1], 32);
        for (std::size_t i = 0; i < 6; ++i) sum[i] += s[i];
    }
    return {sum[0] / sum[3], sum[1] / sum[4], sum[2] / sum[5]};
}

Estimate<3> preintegrated_skin_mc(const SkinProfile& p, SkinGeometry g, double n_dot_l, double curvature,
                                  long long samples, std::uint64_t seed) {
    check_arguments(p, g, n_dot_l, curvature);
    if (curvature == 0.0) return limit(n_dot_l);
    const double rho = 1.0 / curvature;
    const double theta = std::acos(n_dot_l);
    const double ct = std::cos(theta), st = std::sin(theta);
    Rng rng(seed, 36);
    if (g == SkinGeometry::sphere) {
        // A defensive mixture: half the samples by the profile (radius by its
        // CDF within 2 rho), half uniform over the sphere's area, so the
        // faint tails far from p are sampled too; weight = density of the
        // profile by area over the mixture's, at most 2.
        MeanAccumulator<3> acc;
        const double area = 2.0 * kTwoPi * rho * rho;
        std::array<double, 3> inv_w{};
        for (std::size_t c = 0; c < 3; ++c) inv_w[c] = 1.0 / p[c].within(2.0 * rho);
        for (long long s = 0; s < samples; ++s) {
            double y[3];
            for (std::size_t c = 0; c < 3; ++c) {
                const bool by_profile = rng.uniform() < 0.5;
                const double u = rng.uniform();
                const double r = by_profile ? p[c].sample_radius(u, 2.0 * rho)
                                            : 2.0 * rho * std::sqrt(u);  // cos(alpha) = 1 - 2u
                const double alpha = 2.0 * std::asin(std::min(1.0, r / (2.0 * rho)));
                const double phi = kTwoPi * rng.uniform();
                const double density = p[c].value(r) * inv_w[c];  // per unit area
                const double weight = std::isinf(density) ? 2.0 : density / (0.5 * density + 0.5 / area);
                y[c] = weight * std::max(0.0, ct * std::cos(alpha) + st * std::sin(alpha) * std::cos(phi));
            }
            acc.add(y);
        }
        return acc.estimate();
    }
    // Ring: x uniform on [0, pi]; a = R, b = a (cos+(theta + x) + cos+(theta - x)) / 2,
    // D = E[b] / E[a].
    std::array<double, 3> sa{}, sb{}, saa{}, sbb{}, sab{};
    for (long long s = 0; s < samples; ++s) {
        const double x = kPi * rng.uniform();
        const double r = 2.0 * rho * std::sin(0.5 * x);
        const double w = 0.5 * ring_weight(theta, x);
        for (std::size_t c = 0; c < 3; ++c) {
            const double a = p[c].value(r), bb = w * a;
            sa[c] += a;
            sb[c] += bb;
            saa[c] += a * a;
            sbb[c] += bb * bb;
            sab[c] += a * bb;
        }
    }
    Estimate<3> out;
    const double n = static_cast<double>(samples);
    for (std::size_t c = 0; c < 3; ++c) {
        const double ma = sa[c] / n, mb = sb[c] / n, D = mb / ma;
        const double var_a = saa[c] / n - ma * ma, var_b = sbb[c] / n - mb * mb, cov = sab[c] / n - ma * mb;
        const double var = std::max(0.0, var_b - 2.0 * D * cov + D * D * var_a) * n / (n - 1.0);
        out.value[c] = D;
        out.error[c] = std::sqrt(var / n) / ma;
    }
    out.evaluations = static_cast<int>(std::min<long long>(samples, 1 << 30));
    return out;
}

}  // namespace brdflut
