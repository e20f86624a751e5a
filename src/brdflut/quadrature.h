// Deterministic one-dimensional quadrature: Gauss-Legendre rules of any order
// and a globally adaptive Gauss-Kronrod (7, 15), (10, 21) or (15, 31)
// integrator for vector-valued integrands.
//
// Piessens et al. 1983, "QUADPACK: A Subroutine Package for Automatic
// Integration" (the Kronrod nodes and weights below are those of QK15, QK21
// and QK31).
//
// The adaptive rule is deterministic: the same integrand and tolerances give
// the same nodes in the same order, so results do not depend on threads.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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

// The Kronrod rule of a panel: QK15 (Gauss 7) is the default; QK31
// (Gauss 15) needs fewer panels on smooth integrands at tight tolerances;
// QK21 (Gauss 10) lies between, for ranges one QK15 panel cannot resolve to
// the tolerance and one QK31 panel resolves far beyond it.
enum class KronrodRule { k15, k21, k31 };

// Nodes per panel of a rule.
constexpr int kronrod_points(KronrodRule rule) {
    return rule == KronrodRule::k31 ? 31 : rule == KronrodRule::k21 ? 21 : 15;
}

namespace detail {
// Nodes (descending, the last is 0), Kronrod weights, and the weights of the
// embedded Gauss rule at the odd-indexed nodes (the last at node 0).
// Values of QUADPACK (QK15, QK21, QK31; L. W. Fullerton, 80-digit arithmetic).
template <int K>
struct KronrodNodes;
template <>
struct KronrodNodes<15> {
    static constexpr std::array<double, 8> x = {
        0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
        0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
        0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
        0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
    static constexpr std::array<double, 8> wk = {
        0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
        0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
        0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
        0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
    static constexpr std::array<double, 4> wg = {
        0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
        0.381830050505118944950369775488975, 0.417959183673469387755102040816327};
};
template <>
struct KronrodNodes<21> {
    static constexpr std::array<double, 11> x = {
        0.995657163025808080735527280689003, 0.973906528517171720077964012084452,
        0.930157491355708226001207180059508, 0.865063366688984510732096688423493,
        0.780817726586416897063717578345042, 0.679409568299024406234327365114874,
        0.562757134668604683339000099272694, 0.433395394129247190799265943165784,
        0.294392862701460198131126603103866, 0.148874338981631210884826001129720,
        0.000000000000000000000000000000000};
    static constexpr std::array<double, 11> wk = {
        0.011694638867371874278064396062192, 0.032558162307964727478818972459390,
        0.054755896574351996031381300244580, 0.075039674810919952767043140916190,
        0.093125454583697605535065465083366, 0.109387158802297641899210590325805,
        0.123491976262065851077958109831074, 0.134709217311473325928054001771707,
        0.142775938577060080797094273138717, 0.147739104901338491374841515972068,
        0.149445554002916905664936468389821};
    // Gauss 10 has no node at 0: its weights are those of the odd-indexed
    // nodes x[1], x[3], .., x[9].
    static constexpr std::array<double, 5> wg = {
        0.066671344308688137593568809893332, 0.149451349150580593145776339657697,
        0.219086362515982043995534934228163, 0.269266719309996355091226921569469,
        0.295524224714752870173892994651338};
};
template <>
struct KronrodNodes<31> {
    static constexpr std::array<double, 16> x = {
        0.998002298693397060285172840152271, 0.987992518020485428489565718586613,
        0.967739075679139134257347978784337, 0.937273392400705904307758947710209,
        0.897264532344081900882509656454496, 0.848206583410427216200648320774217,
        0.790418501442465932967649294817947, 0.724417731360170047416186054613938,
        0.650996741297416970533735895313275, 0.570972172608538847537226737253911,
        0.485081863640239680693655740232351, 0.394151347077563369897207370981045,
        0.299180007153168812166780024266389, 0.201194093997434522300628303394596,
        0.101142066918717499027074231447392, 0.000000000000000000000000000000000};
    static constexpr std::array<double, 16> wk = {
        0.005377479872923348987792051430128, 0.015007947329316122538374763075807,
        0.025460847326715320186874001019653, 0.035346360791375846222037948478360,
        0.044589751324764876608227299373280, 0.053481524690928087265343147239430,
        0.062009567800670640285139230960803, 0.069854121318728258709520077099147,
        0.076849680757720378894432777482659, 0.083080502823133021038289247286104,
        0.088564443056211770647275443693774, 0.093126598170825321225486872747346,
        0.096642726983623678505179907627589, 0.099173598721791959332393173484603,
        0.100769845523875595044946662617570, 0.101330007014791549017374792767493};
    static constexpr std::array<double, 8> wg = {
        0.030753241996117268354628393577204, 0.070366047488108124709267416450667,
        0.107159220467171935011869546685869, 0.139570677926154314447804794511028,
        0.166269205816993933553200860481209, 0.186161000015562211026800561866423,
        0.198431485327111576456118326443839, 0.202578241925561272880620199967519};
};
// The QK15 tables under their former names.
inline constexpr std::array<double, 8> kXgk = KronrodNodes<15>::x;
inline constexpr std::array<double, 8> kWgk = KronrodNodes<15>::wk;
inline constexpr std::array<double, 4> kWg = KronrodNodes<15>::wg;

// QUADPACK's error estimate of one panel from the difference of its Kronrod
// and Gauss integrals, resasc (the Kronrod integral of |f - mean|) and the
// Kronrod integral itself, all over the panel: resasc min(1, (200 |diff| /
// resasc)^1.5), never below what double rounding of the sum can resolve.
inline double kronrod_error(double diff, double resasc, double integral) {
    double err = std::abs(diff);
    if (resasc != 0.0 && err != 0.0) {
        const double r = std::min(1.0, 200.0 * err / resasc);
        err = resasc * r * std::sqrt(r);  // resasc min(1, r)^1.5 without pow()
    }
    return std::max(err, 50.0 * 2.220446049250313e-16 * std::abs(integral));
}

template <std::size_t N>
struct Interval {
    double a, b;
    std::array<double, N> value;
    std::array<double, N> error;
    double worst;  // largest error among the controlled channels
};

// The weights of a K-point panel in the order kronrod_panel_k evaluates its
// nodes (centre, then each pair c -+ h x_j): Kronrod, and embedded Gauss (0 at
// the Kronrod-only nodes).
template <int K>
struct PanelWeights {
    std::array<double, K> wk{}, wg{};
};
template <int K>
constexpr PanelWeights<K> panel_weights() {
    using R = KronrodNodes<K>;
    constexpr int half = K / 2;
    PanelWeights<K> p;
    p.wk[0] = R::wk[half];
    p.wg[0] = half % 2 == 1 ? R::wg[half / 2] : 0.0;  // QK21: Gauss 10 has no centre
    for (int j = 0; j < half; ++j) {
        p.wk[1 + 2 * j] = p.wk[2 + 2 * j] = R::wk[static_cast<std::size_t>(j)];
        p.wg[1 + 2 * j] = p.wg[2 + 2 * j] = (j % 2 == 1) ? R::wg[static_cast<std::size_t>(j / 2)] : 0.0;
    }
    return p;
}

// The Kronrod and Gauss sums of a panel's values y (in kronrod_panel_k's node
// order) and the Kronrod sum of |y - mean|, mean = Kronrod sum / 2, per
// channel. Each sum is split into short chains instead of one chain of K
// additions (each addition waiting for the one before): node n goes to
// partial sum n % 4 of the Kronrod sums, the Gauss nodes alternately to two,
// and the partial sums are added as (s0 + s1) + (s2 + s3). The order is
// fixed, so the bits do not depend on the machine; with SSE2 two channels go
// side by side by the same operations. The Gauss sum skips the nodes where
// its weight is 0 (the centre starts one chain, then each pair's nodes go one
// to each).
template <int K>
struct GaussNodes {
    static constexpr int count = K / 2;  // the centre and the pairs j = 1, 3, ..
    std::array<int, count> n{};
};
template <int K>
constexpr GaussNodes<K> gauss_nodes() {
    GaussNodes<K> g;
    int m = 0;
    g.n[static_cast<std::size_t>(m++)] = 0;
    for (int j = 1; j < K / 2; j += 2) {
        g.n[static_cast<std::size_t>(m++)] = 1 + 2 * j;
        g.n[static_cast<std::size_t>(m++)] = 2 + 2 * j;
    }
    return g;
}

// The same sums for QK21 (K = 4 m + 1; Gauss 10 at the pairs j = 1, 3, ..,
// 9, no centre): Kronrod node n to partial sum n % 4 as above, the Gauss
// pairs' nodes one to each of two partial sums; the same operations in
// every channel, with or without SSE2.
template <std::size_t N>
void panel_sums_21(const std::array<std::array<double, N>, 21>& y, std::array<double, N>& k,
                   std::array<double, N>& g, std::array<double, N>& asc) {
    using R = KronrodNodes<21>;
    static constexpr PanelWeights<21> W = panel_weights<21>();
    std::size_t i = 0;
#if defined(__SSE2__)
    for (; i + 2 <= N; i += 2) {
        auto at = [&](int n) { return _mm_loadu_pd(&y[static_cast<std::size_t>(n)][i]); };
        auto wk = [&](int n) { return _mm_set1_pd(W.wk[static_cast<std::size_t>(n)]); };
        __m128d k0 = _mm_mul_pd(wk(0), at(0)), k1 = _mm_mul_pd(wk(1), at(1)), k2 = _mm_mul_pd(wk(2), at(2)),
                k3 = _mm_mul_pd(wk(3), at(3));
        for (int n = 4; n < 20; n += 4) {
            k0 = _mm_add_pd(k0, _mm_mul_pd(wk(n), at(n)));
            k1 = _mm_add_pd(k1, _mm_mul_pd(wk(n + 1), at(n + 1)));
            k2 = _mm_add_pd(k2, _mm_mul_pd(wk(n + 2), at(n + 2)));
            k3 = _mm_add_pd(k3, _mm_mul_pd(wk(n + 3), at(n + 3)));
        }
        k0 = _mm_add_pd(k0, _mm_mul_pd(wk(20), at(20)));
        __m128d g0 = _mm_mul_pd(_mm_set1_pd(R::wg[0]), at(3)), g1 = _mm_mul_pd(_mm_set1_pd(R::wg[0]), at(4));
        for (int j = 3, m = 1; j < 10; j += 2, ++m) {
            const __m128d w = _mm_set1_pd(R::wg[static_cast<std::size_t>(m)]);
            g0 = _mm_add_pd(g0, _mm_mul_pd(w, at(1 + 2 * j)));
            g1 = _mm_add_pd(g1, _mm_mul_pd(w, at(2 + 2 * j)));
        }
        const __m128d kv = _mm_add_pd(_mm_add_pd(k0, k1), _mm_add_pd(k2, k3));
        const __m128d mean = _mm_mul_pd(_mm_set1_pd(0.5), kv);
        const __m128d sign = _mm_set1_pd(-0.0);
        auto dev = [&](int n) { return _mm_mul_pd(wk(n), _mm_andnot_pd(sign, _mm_sub_pd(at(n), mean))); };
        __m128d a0 = dev(0), a1 = dev(1), a2 = dev(2), a3 = dev(3);
        for (int n = 4; n < 20; n += 4) {
            a0 = _mm_add_pd(a0, dev(n));
            a1 = _mm_add_pd(a1, dev(n + 1));
            a2 = _mm_add_pd(a2, dev(n + 2));
            a3 = _mm_add_pd(a3, dev(n + 3));
        }
        a0 = _mm_add_pd(a0, dev(20));
        _mm_storeu_pd(&k[i], kv);
        _mm_storeu_pd(&g[i], _mm_add_pd(g0, g1));
        _mm_storeu_pd(&asc[i], _mm_add_pd(_mm_add_pd(a0, a1), _mm_add_pd(a2, a3)));
    }
#endif
    for (; i < N; ++i) {
        auto at = [&](int n) { return y[static_cast<std::size_t>(n)][i]; };
        auto wk = [&](int n) { return W.wk[static_cast<std::size_t>(n)]; };
        double k0 = wk(0) * at(0), k1 = wk(1) * at(1), k2 = wk(2) * at(2), k3 = wk(3) * at(3);
        for (int n = 4; n < 20; n += 4) {
            k0 += wk(n) * at(n);
            k1 += wk(n + 1) * at(n + 1);
            k2 += wk(n + 2) * at(n + 2);
            k3 += wk(n + 3) * at(n + 3);
        }
        k0 += wk(20) * at(20);
        double g0 = R::wg[0] * at(3), g1 = R::wg[0] * at(4);
        for (int j = 3, m = 1; j < 10; j += 2, ++m) {
            const double w = R::wg[static_cast<std::size_t>(m)];
            g0 += w * at(1 + 2 * j);
            g1 += w * at(2 + 2 * j);
        }
        const double kv = (k0 + k1) + (k2 + k3);
        const double mean = 0.5 * kv;
        auto dev = [&](int n) { return wk(n) * std::abs(at(n) - mean); };
        double a0 = dev(0), a1 = dev(1), a2 = dev(2), a3 = dev(3);
        for (int n = 4; n < 20; n += 4) {
            a0 += dev(n);
            a1 += dev(n + 1);
            a2 += dev(n + 2);
            a3 += dev(n + 3);
        }
        a0 += dev(20);
        k[i] = kv;
        g[i] = g0 + g1;
        asc[i] = (a0 + a1) + (a2 + a3);
    }
}

template <int K, std::size_t N>
void panel_sums(const std::array<std::array<double, N>, K>& y, std::array<double, N>& k,
                std::array<double, N>& g, std::array<double, N>& asc) {
    static constexpr PanelWeights<K> W = panel_weights<K>();
    static constexpr GaussNodes<K> G = gauss_nodes<K>();
    static_assert(K % 4 == 3 && G.count % 2 == 1, "the partial sums below assume K = 4 m + 3");
    std::size_t i = 0;
#if defined(__SSE2__)
    for (; i + 2 <= N; i += 2) {
        auto at = [&](int n) { return _mm_loadu_pd(&y[static_cast<std::size_t>(n)][i]); };
        auto wk = [&](int n) { return _mm_set1_pd(W.wk[static_cast<std::size_t>(n)]); };
        __m128d k0 = _mm_mul_pd(wk(0), at(0)), k1 = _mm_mul_pd(wk(1), at(1)), k2 = _mm_mul_pd(wk(2), at(2)),
                k3 = _mm_setzero_pd();
        for (int n = 3; n < K; n += 4) {
            k3 = _mm_add_pd(k3, _mm_mul_pd(wk(n), at(n)));
            k0 = _mm_add_pd(k0, _mm_mul_pd(wk(n + 1), at(n + 1)));
            k1 = _mm_add_pd(k1, _mm_mul_pd(wk(n + 2), at(n + 2)));
            k2 = _mm_add_pd(k2, _mm_mul_pd(wk(n + 3), at(n + 3)));
        }
        __m128d g0 = _mm_mul_pd(_mm_set1_pd(W.wg[0]), at(0)), g1 = _mm_setzero_pd();
        for (int m = 1; m < G.count; m += 2) {
            const int a = G.n[static_cast<std::size_t>(m)], b = G.n[static_cast<std::size_t>(m + 1)];
            g1 = _mm_add_pd(g1, _mm_mul_pd(_mm_set1_pd(W.wg[static_cast<std::size_t>(a)]), at(a)));
            g0 = _mm_add_pd(g0, _mm_mul_pd(_mm_set1_pd(W.wg[static_cast<std::size_t>(b)]), at(b)));
        }
        const __m128d kv = _mm_add_pd(_mm_add_pd(k0, k1), _mm_add_pd(k2, k3));
        const __m128d mean = _mm_mul_pd(_mm_set1_pd(0.5), kv);
        const __m128d sign = _mm_set1_pd(-0.0);
        auto dev = [&](int n) { return _mm_mul_pd(wk(n), _mm_andnot_pd(sign, _mm_sub_pd(at(n), mean))); };
        __m128d a0 = dev(0), a1 = dev(1), a2 = dev(2), a3 = _mm_setzero_pd();
        for (int n = 3; n < K; n += 4) {
            a3 = _mm_add_pd(a3, dev(n));
            a0 = _mm_add_pd(a0, dev(n + 1));
            a1 = _mm_add_pd(a1, dev(n + 2));
            a2 = _mm_add_pd(a2, dev(n + 3));
        }
        _mm_storeu_pd(&k[i], kv);
        _mm_storeu_pd(&g[i], _mm_add_pd(g0, g1));
        _mm_storeu_pd(&asc[i], _mm_add_pd(_mm_add_pd(a0, a1), _mm_add_pd(a2, a3)));
    }
#endif
    for (; i < N; ++i) {
        auto at = [&](int n) { return y[static_cast<std::size_t>(n)][i]; };
        auto wk = [&](int n) { return W.wk[static_cast<std::size_t>(n)]; };
        double k0 = wk(0) * at(0), k1 = wk(1) * at(1), k2 = wk(2) * at(2), k3 = 0.0;
        for (int n = 3; n < K; n += 4) {
            k3 += wk(n) * at(n);
            k0 += wk(n + 1) * at(n + 1);
            k1 += wk(n + 2) * at(n + 2);
            k2 += wk(n + 3) * at(n + 3);
        }
        double g0 = W.wg[0] * at(0), g1 = 0.0;
        for (int m = 1; m < G.count; m += 2) {
            const int a = G.n[static_cast<std::size_t>(m)], b = G.n[static_cast<std::size_t>(m + 1)];
            g1 += W.wg[static_cast<std::size_t>(a)] * at(a);
            g0 += W.wg[static_cast<std::size_t>(b)] * at(b);
        }
        const double kv = (k0 + k1) + (k2 + k3);
        const double mean = 0.5 * kv;
        auto dev = [&](int n) { return wk(n) * std::abs(at(n) - mean); };
        double a0 = dev(0), a1 = dev(1), a2 = dev(2), a3 = 0.0;
        for (int n = 3; n < K; n += 4) {
            a3 += dev(n);
            a0 += dev(n + 1);
            a1 += dev(n + 2);
            a2 += dev(n + 3);
        }
        k[i] = kv;
        g[i] = g0 + g1;
        asc[i] = (a0 + a1) + (a2 + a3);
    }
}

// One Kronrod panel (K = 15 or 31 points) on [a, b]. The error estimate
// per channel is QUADPACK's: resasc * min(1, (200 |K - G| / resasc)^1.5),
// with resasc the Kronrod integral of |f - mean|. It models the much faster
// convergence of the Kronrod than of the Gauss rule on smooth integrands;
// tests check it against finer runs.
template <int K, std::size_t N, class F>
Interval<N> kronrod_panel_k(F& f, double a, double b, std::size_t controlled) {
    using R = KronrodNodes<K>;
    constexpr int half = K / 2;  // pairs of nodes besides the centre
    const double c = 0.5 * (a + b);
    const double h = 0.5 * (b - a);
    std::array<std::array<double, N>, K> y;
    // An integrand with a member batch(const double* x, std::array<double,
    // N>* y, int n) evaluates the K nodes in one call (to use SIMD); it must
    // return exactly what f(x) returns at each node.
    if constexpr (requires(const double* xs, std::array<double, N>* ys) { f.batch(xs, ys, K); }) {
        std::array<double, K> xs;
        xs[0] = c;
        for (int j = 0; j < half; ++j) {
            const double dx = h * R::x[static_cast<std::size_t>(j)];
            xs[static_cast<std::size_t>(1 + 2 * j)] = c - dx;
            xs[static_cast<std::size_t>(2 + 2 * j)] = c + dx;
        }
        f.batch(xs.data(), y.data(), K);
    } else {
        y[0] = f(c);
        for (int j = 0; j < half; ++j) {
            const double dx = h * R::x[static_cast<std::size_t>(j)];
            y[1 + 2 * j] = f(c - dx);
            y[2 + 2 * j] = f(c + dx);
        }
    }
    std::array<double, N> k, g, asc;
    // An integrand with a member sums(y, k, g, asc) computes the panel sums
    // itself (to use wider SIMD); it must give exactly the bits of
    // panel_sums / panel_sums_21 (the same operations in the same order).
    if constexpr (requires(std::array<double, N>& o) { f.sums(y, o, o, o); })
        f.sums(y, k, g, asc);
    else if constexpr (K == 21)
        panel_sums_21<N>(y, k, g, asc);
    else
        panel_sums<K, N>(y, k, g, asc);
    Interval<N> r{a, b, {}, {}, 0.0};
    const double abs_h = std::abs(h);
    std::size_t i = 0;
#if defined(__SSE2__)
    // Two channels at a time: kronrod_error's operations lane by lane (the
    // division and square root are correctly rounded, min and max select as
    // std::min(1, q) and std::max(err, floor)), so the same bits.
    for (; i + 2 <= N; i += 2) {
        const __m128d hv = _mm_set1_pd(h), zero = _mm_setzero_pd(), sign = _mm_set1_pd(-0.0);
        const __m128d kv = _mm_loadu_pd(&k[i]);
        const __m128d integral = _mm_mul_pd(kv, hv);
        const __m128d diff = _mm_andnot_pd(sign, _mm_mul_pd(_mm_sub_pd(kv, _mm_loadu_pd(&g[i])), hv));
        const __m128d resasc = _mm_mul_pd(_mm_loadu_pd(&asc[i]), _mm_set1_pd(abs_h));
        const __m128d use = _mm_and_pd(_mm_cmpneq_pd(resasc, zero), _mm_cmpneq_pd(diff, zero));
        const __m128d q = _mm_min_pd(_mm_div_pd(_mm_mul_pd(_mm_set1_pd(200.0), diff), resasc), _mm_set1_pd(1.0));
        const __m128d scaled = _mm_mul_pd(_mm_mul_pd(resasc, q), _mm_sqrt_pd(q));
        const __m128d err = _mm_or_pd(_mm_and_pd(use, scaled), _mm_andnot_pd(use, diff));
        const __m128d floor = _mm_mul_pd(_mm_set1_pd(50.0 * 2.220446049250313e-16), _mm_andnot_pd(sign, integral));
        _mm_storeu_pd(&r.value[i], integral);
        _mm_storeu_pd(&r.error[i], _mm_max_pd(floor, err));
    }
#endif
    for (; i < N; ++i) {
        r.value[i] = k[i] * h;
        r.error[i] = kronrod_error((k[i] - g[i]) * h, asc[i] * abs_h, k[i] * h);
    }
    for (std::size_t c = 0; c < N && c < controlled; ++c) r.worst = std::max(r.worst, r.error[c]);
    return r;
}

template <std::size_t N, class F>
Interval<N> kronrod_panel(F& f, double a, double b, std::size_t controlled,
                          KronrodRule rule = KronrodRule::k15) {
    if (rule == KronrodRule::k31) return kronrod_panel_k<31, N>(f, a, b, controlled);
    if (rule == KronrodRule::k21) return kronrod_panel_k<21, N>(f, a, b, controlled);
    return kronrod_panel_k<15, N>(f, a, b, controlled);
}
}  // namespace detail

struct AdaptiveOptions {
    double abs_tol = 1e-10;  // stop when every channel's summed error is below this
    int max_intervals = 200; // hard cap on the work per integral
    // Only the first `controlled` channels steer the subdivision; later ones
    // (for example an integrated error estimate) are carried along.
    std::size_t controlled = static_cast<std::size_t>(-1);
    KronrodRule rule = KronrodRule::k15;  // the panel rule
};

namespace detail {
// The room adaptive_from reserves: the first panels and the usual few
// bisections (more grow the vector as needed).
inline std::size_t heap_room(std::size_t panels, const AdaptiveOptions& opt) {
    return std::max(panels, static_cast<std::size_t>(std::min(opt.max_intervals, 16))) + 1;
}
// An empty work list with that room, for `panels` first panels: filled and
// handed to adaptive_from, it is allocated once (an inner integral runs once
// per node of its outer one, and allocations are what a sanitized build
// spends most on there).
template <std::size_t N>
std::vector<Interval<N>> interval_heap(std::size_t panels, const AdaptiveOptions& opt) {
    std::vector<Interval<N>> heap;
    heap.reserve(heap_room(panels, opt));
    return heap;
}

// The bisection loop of integrate_adaptive, from the intervals in `heap`
// (out.evaluations counts those already evaluated).
template <std::size_t N, class F>
Estimate<N> adaptive_from(F& f, std::vector<Interval<N>> heap, const AdaptiveOptions& opt, Estimate<N> out);

// The same from one first panel: a panel that meets the tolerance (or no
// room to bisect) is the answer, with no work list (the common case of an
// inner integral, called once per outer node); else the bisection from it.
template <std::size_t N, class F>
Estimate<N> adaptive_from_one(F& f, const Interval<N>& first, const AdaptiveOptions& opt, Estimate<N> out) {
    bool settled = opt.max_intervals <= 1;
    if (!settled) {
        settled = true;
        for (std::size_t i = 0; i < N && i < opt.controlled; ++i)
            if (first.error[i] > opt.abs_tol) settled = false;
    }
    if (!settled) {
        std::vector<Interval<N>> heap = interval_heap<N>(1, opt);
        heap.push_back(first);
        return adaptive_from<N>(f, std::move(heap), opt, out);
    }
    for (std::size_t i = 0; i < N; ++i) {  // as adaptive_from sums
        out.value[i] += first.value[i];
        out.error[i] += first.error[i];
    }
    return out;
}

template <std::size_t N, class F>
Estimate<N> adaptive_from(F& f, std::vector<Interval<N>> heap, const AdaptiveOptions& opt, Estimate<N> out) {
    heap.reserve(heap_room(heap.size(), opt));
    auto less = [](const Interval<N>& p, const Interval<N>& q) { return p.worst < q.worst; };
    std::make_heap(heap.begin(), heap.end(), less);
    const int per_panel = kronrod_points(opt.rule);
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
        const Interval<N> worst = heap.back();
        heap.pop_back();
        const double m = 0.5 * (worst.a + worst.b);
        if (!(m > worst.a && m < worst.b)) {  // cannot split further
            heap.push_back(worst);
            std::push_heap(heap.begin(), heap.end(), less);
            break;
        }
        heap.push_back(kronrod_panel<N>(f, worst.a, m, opt.controlled, opt.rule));
        std::push_heap(heap.begin(), heap.end(), less);
        heap.push_back(kronrod_panel<N>(f, m, worst.b, opt.controlled, opt.rule));
        std::push_heap(heap.begin(), heap.end(), less);
        out.evaluations += 2 * per_panel;
    }
    // Sum in a fixed order (by position) so the result does not depend on
    // the heap's internal arrangement beyond the set of intervals.
    std::sort(heap.begin(), heap.end(), [](const auto& p, const auto& q) { return p.a < q.a; });
    for (const auto& iv : heap)
        for (std::size_t i = 0; i < N; ++i) {
            out.value[i] += iv.value[i];
            out.error[i] += iv.error[i];
        }
    return out;
}
}  // namespace detail

// Integrates f over [breaks[0], breaks[count - 1]]; f maps a double to
// std::array<double, N>. Globally adaptive from one first panel between each
// pair of neighbouring break points (increasing; a pair that is not
// increasing is skipped): the interval with the largest error is bisected
// until the summed error of every channel is below abs_tol (QUADPACK's
// QAGP). Break points go where the integrand is known not to be smooth (a
// kink, a cusp) or to change its scale, which bisection would otherwise
// have to find.
template <std::size_t N, class F>
Estimate<N> integrate_adaptive_breaks(F&& f, const double* breaks, std::size_t count,
                                      const AdaptiveOptions& opt = {}) {
    Estimate<N> out;
    if (count < 2 || !(breaks[count - 1] > breaks[0])) return out;
    const int per_panel = kronrod_points(opt.rule);
    if (count == 2) {
        out.evaluations = per_panel;
        return detail::adaptive_from_one<N>(f, detail::kronrod_panel<N>(f, breaks[0], breaks[1], opt.controlled, opt.rule),
                                            opt, out);
    }
    std::vector<detail::Interval<N>> heap = detail::interval_heap<N>(count - 1, opt);
    for (std::size_t k = 0; k + 1 < count; ++k)
        if (breaks[k + 1] > breaks[k])
            heap.push_back(detail::kronrod_panel<N>(f, breaks[k], breaks[k + 1], opt.controlled, opt.rule));
    out.evaluations = per_panel * static_cast<int>(heap.size());
    return detail::adaptive_from<N>(f, std::move(heap), opt, out);
}

// The same over [a, b] from `panels` equal panels instead of given break
// points: when the integrand is known to need several panels (a long range
// over which it varies on a shorter scale), this saves the evaluations of
// the coarse panels that bisection would discard. panels = 1 is
// integrate_adaptive.
template <std::size_t N, class F>
Estimate<N> integrate_adaptive_panels(F&& f, double a, double b, int panels,
                                      const AdaptiveOptions& opt = {}) {
    if (!(b > a)) return Estimate<N>{};
    if (panels <= 1) {  // no allocation: inner integrals run once per outer node
        const double ends[2] = {a, b};
        return integrate_adaptive_breaks<N>(f, ends, 2, opt);
    }
    std::vector<double> breaks(static_cast<std::size_t>(panels) + 1);
    for (int k = 0; k <= panels; ++k)
        breaks[static_cast<std::size_t>(k)] = k == 0 ? a : k == panels ? b : a + (b - a) * k / panels;
    return integrate_adaptive_breaks<N>(f, breaks.data(), breaks.size(), opt);
}

template <std::size_t N, class F>
Estimate<N> integrate_adaptive(F&& f, double a, double b, const AdaptiveOptions& opt = {}) {
    return integrate_adaptive_panels<N>(f, a, b, 1, opt);
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
