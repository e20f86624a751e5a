// Separable subsurface-scattering kernels: tap offsets, weights by point
// rule or by adaptive quadrature over the taps' cells, and the separable
// error against the profile's own cell masses (brdflut/separable_sss.h).
#include "brdflut/separable_sss.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "brdflut/error.h"
#include "brdflut/math.h"

namespace brdflut {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// The radius beyond which the profile's remaining reflectance is below the
// rounding of its total: nothing past it changes a double.
double reach(const RadialProfile& p) {
    const double total = p.total();
    double r = p.scale();
    for (int it = 0; it < 200 && total - p.within(r) > 1e-17 * total; ++it) r *= 2.0;
    return r;
}

// The shape at x >= 0, with its estimated error (nonzero only for the
// marginal, which is an integral).
Estimate<1> shape_at(const RadialProfile& p, KernelShape s, double x, double abs_tol) {
    Estimate<1> e;
    e.evaluations = 1;
    switch (s) {
        case KernelShape::line: e.value[0] = p.value(x); break;
        case KernelShape::radial: e.value[0] = p.radial(x) / kTwoPi; break;
        case KernelShape::marginal: return radial_profile_marginal(p, x, abs_tol);
    }
    return e;
}

// The integral of the shape over [a, b] (0 <= a < b), with the marginal's
// inner errors carried as a second channel.
Estimate<1> shape_integral(const RadialProfile& p, KernelShape s, double a, double b, double abs_tol) {
    AdaptiveOptions opt;
    opt.abs_tol = abs_tol;
    opt.max_intervals = 400;
    opt.controlled = 1;
    long long inner = 0;
    const double inner_tol = abs_tol / (b - a) * 1e-2;
    const Estimate<2> I = integrate_adaptive<2>(
        [&](double x) {
            const Estimate<1> v = shape_at(p, s, x, inner_tol);
            inner += v.evaluations;
            return std::array<double, 2>{v.value[0], v.error[0]};
        },
        a, b, opt);
    Estimate<1> out;
    out.value[0] = I.value[0];
    out.error[0] = I.error[0] + std::abs(I.value[1]) + I.error[1];
    out.evaluations = static_cast<int>(std::min<long long>(inner, std::numeric_limits<int>::max()));
    return out;
}

}  // namespace

std::string_view to_string(KernelShape s) {
    return s == KernelShape::line ? "line" : s == KernelShape::radial ? "radial" : "marginal";
}
std::string_view to_string(KernelWeights w) { return w == KernelWeights::point ? "point" : "cell"; }

KernelShape kernel_shape_from_string(std::string_view s) {
    if (s == "line") return KernelShape::line;
    if (s == "radial") return KernelShape::radial;
    if (s == "marginal") return KernelShape::marginal;
    throw Error("--kernel '" + std::string(s) + "' is not known; allowed: line, radial, marginal");
}

KernelWeights kernel_weights_from_string(std::string_view s) {
    if (s == "point") return KernelWeights::point;
    if (s == "cell") return KernelWeights::cell;
    throw Error("--weights '" + std::string(s) + "' is not known; allowed: point, cell");
}

std::vector<double> separable_tap_offsets(int one_sided, double radius, double exponent) {
    if (one_sided < 2) throw Error("a separable kernel needs at least 2 one-sided taps (got " +
                                   std::to_string(one_sided) + ")");
    if (!(radius > 0.0) || !std::isfinite(radius))
        throw Error("the kernel radius must be a finite length > 0 (got " + std::to_string(radius) + ")");
    if (!(exponent > 0.0) || !std::isfinite(exponent))
        throw Error("the tap spacing exponent must be finite and > 0 (got " + std::to_string(exponent) + ")");
    // t = i / (n - 1) for the one-sided taps i = 0 .. n - 1: the same points
    // as -1 + 2 i / (2n - 2) on the positive side.
    std::vector<double> o(static_cast<std::size_t>(one_sided));
    for (int i = 0; i < one_sided; ++i) {
        const double t = static_cast<double>(i) / (one_sided - 1);
        o[static_cast<std::size_t>(i)] = radius * std::pow(t, exponent);
    }
    o.back() = radius;
    return o;
}

std::vector<double> separable_cell_edges(const std::vector<double>& o) {
    std::vector<double> u(o.size() + 1);
    u[0] = 0.0;
    for (std::size_t i = 1; i < o.size(); ++i) u[i] = 0.5 * (o[i - 1] + o[i]);
    u[o.size()] = o.back();
    return u;
}

std::string separable_kernel_refusal(const RadialProfile& p, KernelShape shape, KernelWeights weights) {
    if (p.finite_at_origin()) return "";
    if (shape == KernelShape::line)
        return "Burley's profile is infinite at r = 0, so the line kernel R(|x|) has no finite centre weight "
               "(its integral across 0 diverges); use --kernel radial or marginal";
    if (shape == KernelShape::marginal && weights == KernelWeights::point)
        return "Burley's marginal is infinite at x = 0, so it has no point weight at the centre tap; use "
               "--weights cell";
    return "";
}

Estimate<1> radial_profile_marginal(const RadialProfile& p, double x, double abs_tol) {
    Estimate<1> out;
    const double r_max = reach(p);
    AdaptiveOptions opt;
    opt.abs_tol = 0.5 * abs_tol;
    opt.max_intervals = 400;
    if (x <= 0.0) {
        // Twice the integral of R over [0, inf); finite where R is.
        const Estimate<1> I = integrate_adaptive<1>(
            [&](double y) { return std::array<double, 1>{p.value(y)}; }, 0.0, r_max, opt);
        out.value[0] = 2.0 * I.value[0];
        out.error[0] = 2.0 * I.error[0];
        out.evaluations = I.evaluations;
        return out;
    }
    if (x >= r_max) return out;
    // y = x sinh(t), r = x cosh(t): dy = r dt, smooth in t.
    const double T = std::acosh(r_max / x);
    const Estimate<1> I = integrate_adaptive<1>(
        [&](double t) {
            const double r = x * std::cosh(t);
            return std::array<double, 1>{p.value(r) * r};
        },
        0.0, T, opt);
    out.value[0] = 2.0 * I.value[0];
    out.error[0] = 2.0 * I.error[0] + 4.0 * kEps * std::abs(out.value[0]);
    out.evaluations = I.evaluations;
    return out;
}

SeparableKernel separable_kernel(const SkinProfile& p, KernelShape shape, KernelWeights weights,
                                 const std::vector<double>& offsets, double abs_tol) {
    for (const RadialProfile& c : p) {
        const std::string why = separable_kernel_refusal(c, shape, weights);
        if (!why.empty()) throw Error(why);
    }
    const std::vector<double> u = separable_cell_edges(offsets);
    const std::size_t n = offsets.size();
    SeparableKernel k;
    k.offset = offsets;
    k.weight.assign(n, {});
    k.error.assign(n, {});
    for (std::size_t c = 0; c < 3; ++c) {
        std::vector<double> raw(n), err(n);
        // The magnitude of the raw weights, from one rule a cell, sets the
        // absolute tolerance of each raw weight.
        double magnitude = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const double mid = 0.5 * (u[i] + u[i + 1]);
            magnitude += (u[i + 1] - u[i]) * shape_at(p[c], shape, mid, 1e-6).value[0];
        }
        const double tol = abs_tol * std::max(magnitude, std::numeric_limits<double>::min()) / 8.0;
        for (std::size_t i = 0; i < n; ++i) {
            // The centre's cell is [-u_1, u_1], twice its positive half.
            const double fold = i == 0 ? 2.0 : 1.0;
            Estimate<1> e;
            if (weights == KernelWeights::point) {
                e = shape_at(p[c], shape, offsets[i], tol / (u[i + 1] - u[i]));
                e.value[0] *= u[i + 1] - u[i];
                e.error[0] *= u[i + 1] - u[i];
            } else {
                e = shape_integral(p[c], shape, u[i], u[i + 1], tol);
            }
            raw[i] = fold * e.value[0];
            err[i] = fold * e.error[0];
            k.evaluations += e.evaluations;
        }
        double sum = raw[0], sum_err = err[0];
        for (std::size_t i = 1; i < n; ++i) {
            sum += 2.0 * raw[i];
            sum_err += 2.0 * err[i];
        }
        for (std::size_t i = 0; i < n; ++i) {
            k.weight[i][c] = raw[i] / sum;
            k.error[i][c] = err[i] / sum + std::abs(raw[i]) * sum_err / (sum * sum) +
                            4.0 * static_cast<double>(n) * kEps * std::abs(k.weight[i][c]);
        }
    }
    return k;
}

Estimate<1> radial_profile_rectangle(const RadialProfile& p, double x0, double x1, double y0, double y1,
                                     double abs_tol) {
    AdaptiveOptions outer;
    outer.abs_tol = 0.5 * abs_tol;
    outer.max_intervals = 400;
    outer.controlled = 1;
    AdaptiveOptions inner = outer;
    inner.abs_tol = 0.25 * abs_tol / (x1 - x0);
    inner.controlled = static_cast<std::size_t>(-1);
    long long evaluations = 0;
    const Estimate<2> I = integrate_adaptive<2>(
        [&](double x) {
            const Estimate<1> v = integrate_adaptive<1>(
                [&](double y) { return std::array<double, 1>{p.value(std::hypot(x, y))}; }, y0, y1, inner);
            evaluations += v.evaluations;
            return std::array<double, 2>{v.value[0], v.error[0]};
        },
        x0, x1, outer);
    Estimate<1> out;
    out.value[0] = I.value[0];
    out.error[0] = I.error[0] + std::abs(I.value[1]) + I.error[1];
    out.evaluations = static_cast<int>(std::min<long long>(evaluations, std::numeric_limits<int>::max()));
    return out;
}

SeparableError separable_error(const SkinProfile& p, const SeparableKernel& k, double abs_tol) {
    const std::vector<double> u = separable_cell_edges(k.offset);
    const std::size_t n = k.offset.size();
    SeparableError out;
    // c: how many half-cells a tap's cell is (the centre's spans both
    // sides); m: how many taps share |index| i.
    auto c_of = [](std::size_t i) { return i == 0 ? 2.0 : 1.0; };
    auto m_of = [](std::size_t i) { return i == 0 ? 1.0 : 2.0; };
    for (std::size_t ch = 0; ch < 3; ++ch) {
        const double total = p[ch].total();
        const double tol = abs_tol * total / static_cast<double>(n * (n + 1) / 2);
        std::vector<double> Q(n * n), eQ(n * n);
        double quadrant = 0.0, quadrant_err = 0.0;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i; j < n; ++j) {
                const Estimate<1> e = radial_profile_rectangle(p[ch], u[i], u[i + 1], u[j], u[j + 1], tol);
                Q[i * n + j] = Q[j * n + i] = e.value[0];
                eQ[i * n + j] = eQ[j * n + i] = e.error[0];
                out.evaluations += e.evaluations;
                quadrant += (i == j ? 1.0 : 2.0) * e.value[0];
                quadrant_err += (i == j ? 1.0 : 2.0) * e.error[0];
            }
        const double S = 4.0 * quadrant, eS = 4.0 * quadrant_err;
        double tv = 0.0, tv_err = 0.0;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) {
                const double mult = m_of(i) * m_of(j);
                const double mass = c_of(i) * c_of(j) * Q[i * n + j] / S;
                tv += mult * std::abs(k.weight[i][ch] * k.weight[j][ch] - mass);
                tv_err += mult * (c_of(i) * c_of(j) * eQ[i * n + j] / S + k.weight[i][ch] * k.error[j][ch] +
                                  k.weight[j][ch] * k.error[i][ch]);
            }
        out.misplaced[ch] = 0.5 * tv;
        out.error[ch] = 0.5 * tv_err + eS / S + 8.0 * static_cast<double>(n * n) * kEps;
        out.outside[ch] = std::max(0.0, 1.0 - S / total);
    }
    return out;
}

}  // namespace brdflut
