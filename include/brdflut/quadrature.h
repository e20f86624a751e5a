// Deterministic one-dimensional quadrature: Gauss-Legendre rules of any order
// and a globally adaptive Gauss-Kronrod (7, 15) integrator for vector-valued
// integrands.
//
// Piessens et al. 1983, "QUADPACK: A Subroutine Package for Automatic
// Integration" (the Kronrod nodes and weights below are those of QK15).
//
// The adaptive rule is deterministic: the same integrand and tolerances give
// the same nodes in the same order, so results do not depend on threads.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace brdflut {

// n-point Gauss-Legendre rule on [-1, 1].
struct GaussLegendre {
    std::vector<double> x;  // nodes, ascending
    std::vector<double> w;  // weights, sum to 2
};
// Rules are computed once per order (Newton on the Legendre recurrence) and
// cached; the returned reference stays valid for the life of the program.
const GaussLegendre& gauss_legendre(int n);

// The estimate of an integral and of its absolute error, per channel.
template <std::size_t N>
struct Estimate {
    std::array<double, N> value{};
    std::array<double, N> error{};
    int evaluations = 0;

    double max_error() const { return *std::max_element(error.begin(), error.end()); }
};

namespace detail {
inline constexpr std::array<double, 8> kXgk = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
inline constexpr std::array<double, 8> kWgk = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
// Gauss weights of the 7-point rule, at kXgk[1], kXgk[3], kXgk[5], kXgk[7].
inline constexpr std::array<double, 4> kWg = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

template <std::size_t N>
struct Interval {
    double a, b;
    std::array<double, N> value;
    std::array<double, N> error;
    double worst;  // largest error among the controlled channels
};

// One Kronrod-15 panel on [a, b]. The error estimate per channel is
// QUADPACK's: resasc * min(1, (200 |K15 - G7| / resasc)^1.5), with resasc the
// K15 integral of |f - mean|. It models the much faster convergence of K15
// than of G7 on smooth integrands; tests check it against finer runs.
template <std::size_t N, class F>
Interval<N> kronrod_panel(F& f, double a, double b, std::size_t controlled) {
    const double c = 0.5 * (a + b);
    const double h = 0.5 * (b - a);
    std::array<std::array<double, N>, 15> y;
    std::array<double, 15> wk, wg;
    y[0] = f(c);
    wk[0] = kWgk[7];
    wg[0] = kWg[3];
    for (int j = 0; j < 7; ++j) {
        const double dx = h * kXgk[j];
        y[1 + 2 * j] = f(c - dx);
        y[2 + 2 * j] = f(c + dx);
        wk[1 + 2 * j] = wk[2 + 2 * j] = kWgk[j];
        wg[1 + 2 * j] = wg[2 + 2 * j] = (j % 2 == 1) ? kWg[j / 2] : 0.0;
    }
    Interval<N> r{a, b, {}, {}, 0.0};
    for (std::size_t i = 0; i < N; ++i) {
        double k = 0.0, g = 0.0;
        for (int n = 0; n < 15; ++n) {
            k += wk[n] * y[n][i];
            g += wg[n] * y[n][i];
        }
        const double mean = 0.5 * k;
        double asc = 0.0;
        for (int n = 0; n < 15; ++n) asc += wk[n] * std::abs(y[n][i] - mean);
        asc *= std::abs(h);
        double err = std::abs((k - g) * h);
        if (asc != 0.0 && err != 0.0) {
            const double r = std::min(1.0, 200.0 * err / asc);
            err = asc * r * std::sqrt(r);  // asc min(1, r)^1.5 without pow()
        }
        // Never below what double rounding of the sum can resolve.
        err = std::max(err, 50.0 * 2.220446049250313e-16 * std::abs(k * h));
        r.value[i] = k * h;
        r.error[i] = err;
        if (i < controlled) r.worst = std::max(r.worst, err);
    }
    return r;
}
}  // namespace detail

struct AdaptiveOptions {
    double abs_tol = 1e-10;  // stop when every channel's summed error is below this
    int max_intervals = 200; // hard cap on the work per integral
    // Only the first `controlled` channels steer the subdivision; later ones
    // (for example an integrated error estimate) are carried along.
    std::size_t controlled = static_cast<std::size_t>(-1);
};

// Integrates f over [a, b]; f maps a double to std::array<double, N>.
// Globally adaptive: the interval with the largest error is bisected until
// the summed error of every channel is below abs_tol.
template <std::size_t N, class F>
Estimate<N> integrate_adaptive(F&& f, double a, double b, const AdaptiveOptions& opt = {}) {
    Estimate<N> out;
    if (!(b > a)) return out;
    std::vector<detail::Interval<N>> heap;
    heap.reserve(static_cast<std::size_t>(opt.max_intervals) + 1);
    auto less = [](const detail::Interval<N>& p, const detail::Interval<N>& q) {
        return p.worst < q.worst;
    };
    heap.push_back(detail::kronrod_panel<N>(f, a, b, opt.controlled));
    out.evaluations = 15;
    auto total_error_ok = [&]() {
        std::array<double, N> e{};
        for (const auto& iv : heap)
            for (std::size_t i = 0; i < N; ++i) e[i] += iv.error[i];
        for (std::size_t i = 0; i < N && i < opt.controlled; ++i)
            if (e[i] > opt.abs_tol) return false;
        return true;
    };
    while (static_cast<int>(heap.size()) < opt.max_intervals && !total_error_ok()) {
        std::pop_heap(heap.begin(), heap.end(), less);
        const detail::Interval<N> worst = heap.back();
        heap.pop_back();
        const double m = 0.5 * (worst.a + worst.b);
        if (!(m > worst.a && m < worst.b)) {  // cannot split further
            heap.push_back(worst);
            std::push_heap(heap.begin(), heap.end(), less);
            break;
        }
        heap.push_back(detail::kronrod_panel<N>(f, worst.a, m, opt.controlled));
        std::push_heap(heap.begin(), heap.end(), less);
        heap.push_back(detail::kronrod_panel<N>(f, m, worst.b, opt.controlled));
        std::push_heap(heap.begin(), heap.end(), less);
        out.evaluations += 30;
    }
    // Sum in a fixed order (by position) so the result does not depend on
    // the heap's internal arrangement beyond the set of intervals.
    std::sort(heap.begin(), heap.end(),
              [](const auto& p, const auto& q) { return p.a < q.a; });
    for (const auto& iv : heap)
        for (std::size_t i = 0; i < N; ++i) {
            out.value[i] += iv.value[i];
            out.error[i] += iv.error[i];
        }
    return out;
}

// Fixed-order Gauss-Legendre over [a, b] for a vector-valued integrand.
template <std::size_t N, class F>
std::array<double, N> integrate_gauss(F&& f, double a, double b, int n) {
    const GaussLegendre& rule = gauss_legendre(n);
    const double c = 0.5 * (a + b), h = 0.5 * (b - a);
    std::array<double, N> s{};
    for (int j = 0; j < n; ++j) {
        const std::array<double, N> y = f(c + h * rule.x[j]);
        for (std::size_t i = 0; i < N; ++i) s[i] += rule.w[j] * y[i];
    }
    for (auto& v : s) v *= h;
    return s;
}

}  // namespace brdflut
