// Quadrature and Monte Carlo estimates of the GGX split-sum integrals.
//
// Quadrature. Substituting the half vector h for wi (dw_i = 4 (wo.h) dw_h):
//
//   integral of f cos(theta_i) dw_i = integral of D(h) G2 (wo.h) / mu_o dw_h.
//
// With t = tan(theta_h) and x = ln(t / alpha), the measure D cos(theta_h) dw_h
// becomes (1/2) sech^2(x) dx dphi / (2 pi): the GGX distribution is a smooth
// bump of unit width in x whatever alpha is, so the integrand has no boundary
// layers left for small alpha. The reflected direction stays above the
// horizon exactly when cos(phi) > c(t) = -mu_o (1 - t^2) / (2 t sin(theta_o)):
//   t <= t_a = mu_o / (1 + sin(theta_o))   every phi    (full circle)
//   t_a < t < t_b = (1 + sin(theta_o)) / mu_o   |phi| < acos(c(t))
//   t >= t_b                                      none.
// The outer variable is integrated with adaptive Gauss-Kronrod (15, 31) in
// three ranges: up to t = min(alpha, t_a) in xi = t^2 / (alpha^2 + t^2)
// (uniform measure; (7, 15) there), then in x up to t_a, then across the
// clipped band; both x ranges are flattened by a change of variable at t_a,
// where the phi integral behaves like (t - t_a)^(3/2) (and G2 dips where the
// reflected direction grazes the horizon). The full circle in phi uses the
// doubling trapezoidal rule (cosines from a table); a clipped range uses
// Gauss-Kronrod in tan(phi / 2), where the integrand is rational: one (7, 15)
// or (10, 21) panel where G2's branch points lie far from the arc against its
// length, else (or when that panel misses the tolerance) adaptive (15, 31).
// Each inner integral gets the tolerance its outer weight requires (budget /
// (weight * range)), and its error estimate is integrated along with the
// values, so the reported error covers both levels. The phi integrands are
// evaluated four nodes at a time with AVX2 when the processor has it, else two
// with SSE2, by exactly the operations of one node at a time
// (ggx_phi_kernels.inc), and with AVX2 the arcs' Kronrod panel sums take two
// nodes per register by the operations of detail::panel_sums, so the values do
// not depend on the machine.
#include "brdflut/ggx_integrals.h"

#include <cmath>
#include <vector>

#include "integrate/ggx_simd.h"
#include "integrate/half_circle.h"
#include "integrate/reflection_clip.h"
#include "integrate/simd_lanes.h"

namespace brdflut {
namespace {

// Upper end of the x range: beyond it the weight 2 e^(-2x), against an
// integrand that grows at most like e^x, leaves less than 1e-15.
constexpr double kHighX = 36.0;

// The loosest absolute tolerance of a phi integral. Looser ones let the
// doubling trapezoid stop before it resolves the narrow dip of G2 where the
// reflected direction grazes the horizon (width ~ sqrt(alpha / mu_o) in phi).
constexpr double kMaxInnerTol = 1e-6;
// The same for a clipped phi range (adaptive Kronrod panels, whose estimate
// does not share the trapezoid's blind spot), relative to the size of its
// integrand, 1 / (mu_o cos(theta_h)): far out in the tail at grazing view
// that is up to 1e15, and an absolute cap would ask for less than double
// rounding can resolve (every panel split to the work limit, for a value
// whose weight is below 1e-20).
constexpr double kMaxClippedTol = 1e-4;

// The clipped band is integrated from panels of at most this many units of x
// (each then bisected as needed).
constexpr double kBandPanelWidth = 3.0;

// The range of E_avg in ln(mu) is integrated from panels of at most this
// width.
constexpr double kLnMuPanelWidth = 3.0;

// The loosest tolerance of an E(mu) inside E_avg.
constexpr double kMaxNestedTol = 1e-5;

// G2 falls from its plateau to 0 as mu_i drops below about alpha; a clipped
// phi range is cut where mu_i = kDipWidths alpha (see clipped_circle).
constexpr double kDipWidths = 8.0;

// A clipped arc far inside G2's dip starts from a QK15 panel only when its
// tolerance is at least this fraction of the size of its integrand (see
// clipped_circle); below, the 7-point Gauss rule inside QUADPACK's estimate
// rarely gets there in one panel.
constexpr double kQk15RelTol = 1e-10;

// A clipped phi range is integrated in s = tan(phi / 2) up to
// s = kMaxTanHalf, that is for cos(phi_max) >= kSplitCos, and beyond in
// tan(phi / 4).
constexpr double kMaxTanHalf = 4.0;
constexpr double kSplitCos = (1.0 - kMaxTanHalf * kMaxTanHalf) / (1.0 + kMaxTanHalf * kMaxTanHalf);

// What the phi kernels need of a SplitSumIntegrand and its Ring.
struct PhiConstants {
    double a1, a0, two_cos_h, scale;  // the Ring
    double mu_o, alpha2, s, k;        // the integrand
};

// The phi kernels, one set per instruction set: each does the nodes it can
// in whole vectors and returns how many (the caller does the rest one at a
// time).
struct PhiKernels {
    int (*circle)(const PhiConstants&, const double* cos_phi, double* y, int n);
    int (*arc_half)(const PhiConstants&, double a1s, double kj, const double* u, double* y, int n);
    int (*arc_quarter)(const PhiConstants&, double a1s, double kj, const double* u, double* y, int n);
    // The Kronrod panel sums of two channels (detail::panel_sums,
    // panel_sums_21: y holds K pairs; k, g, asc get a pair each), or null
    // where the generic ones are used.
    using Sums = void (*)(const double* y, double* k, double* g, double* asc);
    Sums sums15 = nullptr, sums21 = nullptr, sums31 = nullptr;
};

// The panel weights in node order as plain arrays, for the AVX2 panel sums
// (which use no library templates; see ggx_phi_kernels.inc).
template <int K>
struct SumWeights {
    double wk[K], wg[K];
};
template <int K>
constexpr SumWeights<K> sum_weights() {
    constexpr detail::PanelWeights<K> w = detail::panel_weights<K>();
    SumWeights<K> t{};
    for (int n = 0; n < K; ++n) {
        t.wk[n] = w.wk[static_cast<std::size_t>(n)];
        t.wg[n] = w.wg[static_cast<std::size_t>(n)];
    }
    return t;
}
template <int K>
inline constexpr SumWeights<K> kSumWeights = sum_weights<K>();
// Instantiated here, outside the code compiled for AVX2.
static_assert(kSumWeights<15>.wk[0] > 0.0 && kSumWeights<21>.wk[0] > 0.0 && kSumWeights<31>.wk[0] > 0.0);

int no_circle(const PhiConstants&, const double*, double*, int) { return 0; }
int no_arc(const PhiConstants&, double, double, const double*, double*, int) { return 0; }

#if defined(__SSE2__)
namespace sse2 {
using simd::sse2::V;
#include "integrate/ggx_phi_kernels.inc"
int circle(const PhiConstants& k, const double* c, double* y, int n) { return circle_kernel(k, c, y, n); }
template <bool kQuarter>
int arc(const PhiConstants& k, double a1s, double kj, const double* u, double* y, int n) {
    return arc_kernel<kQuarter>(k, a1s, kj, u, y, n);
}
}  // namespace sse2
#endif

#if defined(BRDFLUT_HAVE_AVX2_KERNELS)
// Compiled for AVX2 whatever the target of the build, and called only when
// the processor has it. AVX2 alone implies no fused multiply-add, so the
// lanes round exactly as the SSE2 ones.
BRDFLUT_AVX2_BEGIN
namespace avx2 {
using simd::avx2::V;
#include "integrate/ggx_phi_kernels.inc"

// detail::panel_sums (K = 15, 31) and panel_sums_21 for two channels, two
// nodes per register: {k0, k1} and {k2, k3} of the partial sums side by
// side, each partial sum taking its nodes in the same order by the same
// operations, so the bits are those of the SSE2 and scalar sums.
inline __m256d pair_weights(const double* w, int n) { return _mm256_setr_pd(w[n], w[n], w[n + 1], w[n + 1]); }
inline __m128d lo(__m256d v) { return _mm256_castpd256_pd128(v); }
inline __m128d hi(__m256d v) { return _mm256_extractf128_pd(v, 1); }
template <int K>
void panel_sums2(const double* y, double* k, double* g, double* asc) {
    constexpr bool k21 = K == 21;  // K = 4 m + 1; else K = 4 m + 3
    constexpr int groups = (K - 1) / 4;  // whole groups of four nodes after the first
    const double* wk = kSumWeights<K>.wk;
    const double* wg = kSumWeights<K>.wg;
    // 0 + x for the partial sum that starts from 0 (exactly x, also for -0).
    const __m256d zero_k3 = _mm256_setr_pd(-0.0, -0.0, 0.0, 0.0);
    auto yy = [y](int n) { return _mm256_loadu_pd(y + 2 * n); };
    __m256d a = _mm256_mul_pd(pair_weights(wk, 0), yy(0));
    __m256d b = _mm256_mul_pd(pair_weights(wk, 2), yy(2));
    if (!k21) b = _mm256_add_pd(b, zero_k3);
    for (int m = 1; m < groups; ++m) {
        a = _mm256_add_pd(a, _mm256_mul_pd(pair_weights(wk, 4 * m), yy(4 * m)));
        b = _mm256_add_pd(b, _mm256_mul_pd(pair_weights(wk, 4 * m + 2), yy(4 * m + 2)));
    }
    __m128d k0 = lo(a), k1 = hi(a), k2 = lo(b);
    const __m128d k3 = hi(b);
    if (k21) {
        k0 = _mm_add_pd(k0, _mm_mul_pd(_mm_set1_pd(wk[K - 1]), _mm_loadu_pd(y + 2 * (K - 1))));
    } else {
        const int n = 4 * groups;  // K - 3
        const __m256d last = _mm256_mul_pd(pair_weights(wk, n), yy(n));
        k0 = _mm_add_pd(k0, lo(last));
        k1 = _mm_add_pd(k1, hi(last));
        k2 = _mm_add_pd(k2, _mm_mul_pd(_mm_set1_pd(wk[K - 1]), _mm_loadu_pd(y + 2 * (K - 1))));
    }
    const __m128d kv = _mm_add_pd(_mm_add_pd(k0, k1), _mm_add_pd(k2, k3));
    // Gauss: the pairs of nodes (3, 4), (7, 8), ..; {g1, g0} for K = 4 m + 3
    // (g0 starting from the centre, g1 from 0), {g0, g1} for QK21.
    __m256d gr;
    if (k21) {
        gr = _mm256_mul_pd(pair_weights(wg, 3), yy(3));
    } else {
        const __m128d centre = _mm_mul_pd(_mm_set1_pd(wg[0]), _mm_loadu_pd(y));
        gr = _mm256_insertf128_pd(_mm256_setzero_pd(), centre, 1);
        gr = _mm256_add_pd(gr, _mm256_mul_pd(pair_weights(wg, 3), yy(3)));
    }
    for (int n = 7; n + 1 < K; n += 4) gr = _mm256_add_pd(gr, _mm256_mul_pd(pair_weights(wg, n), yy(n)));
    const __m128d gv = k21 ? _mm_add_pd(lo(gr), hi(gr)) : _mm_add_pd(hi(gr), lo(gr));
    // Sum of |y - mean|, mean = K / 2, in the partial sums of K.
    const __m128d mean = _mm_mul_pd(_mm_set1_pd(0.5), kv);
    const __m256d mean2 = _mm256_insertf128_pd(_mm256_castpd128_pd256(mean), mean, 1);
    const __m256d sign = _mm256_set1_pd(-0.0);
    auto dev = [&](int n) {
        return _mm256_mul_pd(pair_weights(wk, n), _mm256_andnot_pd(sign, _mm256_sub_pd(yy(n), mean2)));
    };
    __m256d da = dev(0), db = dev(2);
    if (!k21) db = _mm256_add_pd(db, zero_k3);
    for (int m = 1; m < groups; ++m) {
        da = _mm256_add_pd(da, dev(4 * m));
        db = _mm256_add_pd(db, dev(4 * m + 2));
    }
    __m128d a0 = lo(da), a1 = hi(da), a2 = lo(db);
    const __m128d a3 = hi(db);
    const __m128d dlast = _mm_mul_pd(_mm_set1_pd(wk[K - 1]),
                                     _mm_andnot_pd(_mm_set1_pd(-0.0), _mm_sub_pd(_mm_loadu_pd(y + 2 * (K - 1)), mean)));
    if (k21) {
        a0 = _mm_add_pd(a0, dlast);
    } else {
        const __m256d d = dev(4 * groups);
        a0 = _mm_add_pd(a0, lo(d));
        a1 = _mm_add_pd(a1, hi(d));
        a2 = _mm_add_pd(a2, dlast);
    }
    _mm_storeu_pd(k, kv);
    _mm_storeu_pd(g, gv);
    _mm_storeu_pd(asc, _mm_add_pd(_mm_add_pd(a0, a1), _mm_add_pd(a2, a3)));
}

// Whole vectors of 4, then a pair of 2 (SSE2 rounding is the same), then a
// last odd node as a pair with a copy of itself (each lane computes alone).
int circle(const PhiConstants& k, const double* c, double* y, int n) {
    int i = circle_kernel(k, c, y, n);
    i += sse2::circle_kernel(k, c + i, y + 2 * i, n - i);
    if (i + 1 == n) {
        const double c2[2] = {c[i], c[i]};
        double y2[4];
        sse2::circle_kernel(k, c2, y2, 2);
        y[2 * i] = y2[0];
        y[2 * i + 1] = y2[1];
        ++i;
    }
    return i;
}
template <bool kQuarter>
int arc(const PhiConstants& k, double a1s, double kj, const double* u, double* y, int n) {
    int i = arc_kernel<kQuarter>(k, a1s, kj, u, y, n);
    i += sse2::arc_kernel<kQuarter>(k, a1s, kj, u + i, y + 2 * i, n - i);
    if (i + 1 == n) {
        const double u2[2] = {u[i], u[i]};
        double y2[4];
        sse2::arc_kernel<kQuarter>(k, a1s, kj, u2, y2, 2);
        y[2 * i] = y2[0];
        y[2 * i + 1] = y2[1];
        ++i;
    }
    return i;
}
}  // namespace avx2
BRDFLUT_AVX2_END
#endif

PhiKernels pick_phi_kernels(int width) {
#if defined(BRDFLUT_HAVE_AVX2_KERNELS)
    if (width >= 4)
        return {avx2::circle, avx2::arc<false>, avx2::arc<true>, avx2::panel_sums2<15>, avx2::panel_sums2<21>,
                avx2::panel_sums2<31>};
#endif
#if defined(__SSE2__)
    if (width >= 2) return {sse2::circle, sse2::arc<false>, sse2::arc<true>};
#endif
    (void)width;
    return {no_circle, no_arc, no_arc};
}

int widest_phi_kernels() {
#if defined(BRDFLUT_HAVE_AVX2_KERNELS)
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx2")) return 4;
#endif
#if defined(__SSE2__)
    return 2;
#else
    return 1;
#endif
}

struct PhiKernelChoice {
    int width;
    PhiKernels kernels;
};
PhiKernelChoice& phi_kernel_choice() {
    static PhiKernelChoice c = [] {
        const int w = widest_phi_kernels();
        return PhiKernelChoice{w, pick_phi_kernels(w)};
    }();
    return c;
}
const PhiKernels& phi_kernels() { return phi_kernel_choice().kernels; }

struct SplitSumIntegrand {
    double alpha2;
    double mu_o, sin_o;
    // G2 = k P / (s P + alpha^2 (1 - mu_i^2)), P = 2 mu_i (r + mu_i),
    // r = sqrt(mu_i^2 + alpha^2 (1 - mu_i^2)): height-correlated
    // 1 / (1 + Lambda_o + Lambda_i) with s = 1 + Lambda_o, k = 1; separable
    // G1(o) G1(i) with s = 1, k = G1(o). One square root and one division.
    double s, k;
    // Other visibility terms (Schlick-Smith) go through Ggx::G2.
    Ggx ggx_;
    Visibility vis_;
    bool generic_;

    SplitSumIntegrand(const Ggx& ggx, Visibility vis, double mu_o_, double sin_o_)
        : alpha2(ggx.alpha * ggx.alpha), mu_o(mu_o_), sin_o(sin_o_),
          s(vis == Visibility::separable ? 1.0 : 1.0 + ggx.lambda(mu_o_)),
          k(vis == Visibility::separable ? ggx.G1(mu_o_) : 1.0), ggx_(ggx), vis_(vis),
          generic_(vis != Visibility::height_correlated && vis != Visibility::separable) {}

    // What depends on t = tan(theta_h) only, hoisted out of the phi loop.
    struct Ring {
        double a1, a0;     // wo.h = a1 cos(phi) + a0
        double two_cos_h;  // mu_i = two_cos_h (wo.h) - mu_o
        double scale;      // 1 / (mu_o cos(theta_h))
    };
    Ring ring(double t) const {
        const double cos_h = 1.0 / std::sqrt(1.0 + t * t);
        const double sin_h = t * cos_h;
        return {sin_o * sin_h, mu_o * cos_h, 2.0 * cos_h, 1.0 / (mu_o * cos_h)};
    }

    // Integrand over phi at fixed t, without the 1/pi normalization (applied
    // by the caller): {A, B} parts of G2 (wo.h) / (mu_o cos(theta_h)).
    std::array<double, 2> at(const Ring& q, double cos_phi) const {
        const double o_h = q.a1 * cos_phi + q.a0;
        const double mu_i = q.two_cos_h * o_h - mu_o;
        if (mu_i <= 0.0 || o_h <= 0.0) return {0.0, 0.0};
        double v;
        if (generic_) {  // Schlick-Smith: no fast form, use the model's G2
            v = ggx_.G2(mu_o, mu_i, vis_) * o_h * q.scale;
        } else {
            const double r = std::sqrt(mu_i * mu_i + alpha2 * (1.0 - mu_i * mu_i));
            const double p = 2.0 * mu_i * (r + mu_i);
            v = k * p * o_h * q.scale / (s * p + alpha2 * (1.0 - mu_i * mu_i));
        }
        const double fc = schlick_weight(o_h);
        return {v - v * fc, v * fc};
    }

    // at at n values of cos(phi), several at a time where SIMD is available
    // (phi_kernels(): the same operations in the same order, so bit for bit
    // the same values).
    void at_batch(const Ring& q, const double* cos_phi, std::array<double, 2>* y, int n) const {
        int i = 0;
        if (!generic_) i = phi_kernels().circle(constants(q), cos_phi, reinterpret_cast<double*>(y), n);
        for (; i < n; ++i) y[i] = at(q, cos_phi[i]);
    }

    // The same on a clipped arc in u = tan(phi / 2) (Arc::half, sign = 1),
    // u = tan((pi - phi) / 2) (Arc::half, sign = -1) or u = tan(phi / 4)
    // (Arc::quarter), times dphi / du. With q = 1 + u^2 and
    //   half:    cos(phi) = sign (1 - u^2) / q,            dphi/du = 2 / q,
    //   quarter: cos(phi) = (1 - 6 u^2 + u^4) / q^2,       dphi/du = 4 q / q^2,
    // write cos(phi) = C / D (D = q, or q^2); then wo.h = O / D and
    // mu_i = M / D with O, M polynomial in u. G2 is homogeneous of degree 0
    // in (M, D), so it is evaluated on (M, D) directly, and the one division
    // 1 / (D den) gives both 1 / D and 1 / den.
    enum class Arc { half, quarter };
    template <Arc kind>
    std::array<double, 2> at_arc(const Ring& r, double sign, double u) const {
        const double s2 = u * u;
        const double q = 1.0 + s2;
        const double d = kind == Arc::half ? q : q * q;
        const double cn = kind == Arc::half ? 1.0 - s2 : (1.0 - 6.0 * s2) + s2 * s2;
        if (generic_) {
            std::array<double, 2> y = at(r, sign * cn / d);
            const double j = kind == Arc::half ? 2.0 / q : 4.0 / q;
            return {y[0] * j, y[1] * j};
        }
        const ArcConstants a = arc_constants<kind>(r, sign);
        const double o = a.a1s * cn + r.a0 * d;       // (wo.h) D
        const double m = r.two_cos_h * o - mu_o * d;  // mu_i D
        if (!((m > 0.0) & (o > 0.0))) return {0.0, 0.0};
        const double e = alpha2 * ((d - m) * (d + m));  // alpha^2 (1 - mu_i^2) D^2
        const double rr = std::sqrt(m * m + e);          // r D
        const double p = (2.0 * m) * (rr + m);           // P D^2
        const double den = s * p + e;
        const double inv = 1.0 / (d * den);
        // k (p / den) (o / D) scale dphi/du, with 1 / D = den inv and
        // dphi/du = 2 / D (half) or 4 q / D (quarter)
        double v = ((a.kj * p) * o * den) * (inv * inv);
        if constexpr (kind == Arc::quarter) v *= q;
        const double y = 1.0 - (o * den) * inv;  // 1 - wo.h
        const double y2 = y * y;
        const double b = v * ((y2 * y2) * y);
        return {v - b, b};
    }

    // at_arc at n nodes, several at a time as at_batch.
    template <Arc kind>
    void at_arc_batch(const Ring& r, double sign, const double* u, std::array<double, 2>* y, int n) const {
        int i = 0;
        if (!generic_) {
            const ArcConstants a = arc_constants<kind>(r, sign);
            const PhiKernels& kernels = phi_kernels();
            i = (kind == Arc::half ? kernels.arc_half : kernels.arc_quarter)(constants(r), a.a1s, a.kj, u,
                                                                            reinterpret_cast<double*>(y), n);
        }
        for (; i < n; ++i) y[i] = at_arc<kind>(r, sign, u[i]);
    }

private:
    PhiConstants constants(const Ring& q) const { return {q.a1, q.a0, q.two_cos_h, q.scale, mu_o, alpha2, s, k}; }
    struct ArcConstants {
        double a1s;  // a1 sign
        double kj;   // k scale times 2 (half) or 4 (quarter)
    };
    template <Arc kind>
    ArcConstants arc_constants(const Ring& r, double sign) const {
        return {r.a1 * sign, (kind == Arc::half ? 2.0 : 4.0) * k * r.scale};
    }
};

// The integrand of a full circle in cos(phi), as the trapezoid takes it: one
// node at a time or many at once.
struct CircleIntegrand {
    const SplitSumIntegrand& f;
    const SplitSumIntegrand::Ring& ring;
    std::array<double, 2> operator()(double cos_phi) const { return f.at(ring, cos_phi); }
    void batch(const double* c, std::array<double, 2>* y, int n) const { f.at_batch(ring, c, y, n); }
};

// The integrand of a clipped arc in tan(phi / 2), as the Kronrod panels take
// it: one node at a time or all of a panel's nodes at once.
template <SplitSumIntegrand::Arc kind>
struct ArcIntegrand {
    const SplitSumIntegrand& f;
    const SplitSumIntegrand::Ring& ring;
    double sign;
    std::array<double, 2> operator()(double u) const { return f.at_arc<kind>(ring, sign, u); }
    void batch(const double* u, std::array<double, 2>* y, int n) const { f.at_arc_batch<kind>(ring, sign, u, y, n); }
    // The panel sums, with AVX2 where the phi kernels use it (the same bits
    // as detail::panel_sums and panel_sums_21).
    template <std::size_t K>
    void sums(const std::array<std::array<double, 2>, K>& y, std::array<double, 2>& k, std::array<double, 2>& g,
              std::array<double, 2>& asc) const {
        const PhiKernels& kernels = phi_kernels();
        const PhiKernels::Sums s = K == 15 ? kernels.sums15 : K == 21 ? kernels.sums21 : kernels.sums31;
        if (s != nullptr)
            s(y[0].data(), k.data(), g.data(), asc.data());
        else if constexpr (K == 21)
            detail::panel_sums_21<2>(y, k, g, asc);
        else
            detail::panel_sums<static_cast<int>(K), 2>(y, k, g, asc);
    }
};


}  // namespace

namespace detail {
int ggx_phi_simd_width() { return phi_kernel_choice().width; }
int set_ggx_phi_simd_width(int width) {
    PhiKernelChoice& c = phi_kernel_choice();
    c.width = std::min(std::max(width, 1), widest_phi_kernels());
    if (c.width == 3) c.width = 2;
    c.kernels = pick_phi_kernels(c.width);
    return c.width;
}
}  // namespace detail

Estimate<2> ggx_split_sum(double mu_o, double alpha, Visibility vis, double abs_tol) {
    Estimate<2> out;
    if (!(mu_o >= 0.0)) return out;
    mu_o = std::max(mu_o, kGrazingMu);  // the grazing limit
    if (mu_o > 1.0) mu_o = 1.0;
    if (!(alpha > 0.0)) {            // mirror limit
        const double fc = schlick_weight(mu_o);
        out.value = {1.0 - fc, fc};
        return out;
    }
    const double sin_o = safe_sqrt(1.0 - mu_o * mu_o);
    const Ggx ggx{alpha};
    const SplitSumIntegrand f(ggx, vis, mu_o, sin_o);
    const double ln_alpha = std::log(alpha);

    // (1/2) sech^2(x) / pi: the measure in x times the phi normalization,
    // with phi integrated over [0, pi] only (the integrand is even in phi),
    // from e = exp(x) (cosh(x) = (e + 1 / e) / 2), which gives t = alpha e too.
    auto weight = [](double e) {
        const double c = 0.5 * (e + 1.0 / e);
        return 0.5 / (c * c) * kInvPi;
    };

    // Error budget: per region, 0.3 abs_tol for the outer rule and
    // 0.03 abs_tol for the inner integrals it accumulates (three regions).
    AdaptiveOptions outer_opt;
    outer_opt.abs_tol = 0.3 * abs_tol;
    outer_opt.controlled = 2;
    outer_opt.rule = KronrodRule::k31;
    const double inner_budget = 0.03 * abs_tol;
    // The inner tolerance at an outer node is the budget divided by the
    // outer weight there times the length of the outer range, so that the
    // weighted inner errors integrate to at most the budget: far out in the
    // tail of the distribution, where the weight is tiny, the phi integral
    // needs far less absolute accuracy. Capped so the inner rule always
    // resolves something.
    auto inner_tol = [&](double outer_weight, double span, double cap = kMaxInnerTol) {
        const double wt = outer_weight * span;
        return wt * cap > inner_budget ? inner_budget / wt : cap;
    };

    // Integral over phi in [0, pi] at fixed t: {A, B, error estimate}. The
    // integrand is smooth, even and 2 pi periodic in phi, so the trapezoidal
    // rule converges exponentially; double the nodes until two successive
    // sums agree.
    int evaluations = 0;  // of the phi integrand, in every inner integral
    auto full_circle = [&](double t, double tol) -> std::array<double, 3> {
        const SplitSumIntegrand::Ring q = f.ring(t);
        return detail::trapezoid_half_circle<2>(CircleIntegrand{f, q}, tol, &evaluations);
    };

    // Integral over phi in [0, phi_max], cos(phi_max) = c in (-1, 1), at
    // fixed t: {A, B, error estimate}. In s = tan(phi / 2) the integrand is
    // rational in s (cos(phi) = (1 - s^2) / (1 + s^2), dphi = 2 ds / (1 + s^2)),
    // so no trigonometric function is evaluated; tan(phi_max / 2) =
    // sqrt((1 - c) / (1 + c)). When phi_max is close to pi (s large) the
    // range is done in u = tan(phi / 4) <= 1 instead, which is rational too,
    // in one piece.
    auto clipped_circle = [&](double t, double c, double tol) -> std::array<double, 3> {
        using Arc = SplitSumIntegrand::Arc;
        const SplitSumIntegrand::Ring q = f.ring(t);
        const bool near_pi = c < kSplitCos;
        // Where mu_i = kDipWidths alpha, when the dip of G2 (mu_i below about
        // alpha, next to phi_max) is narrow against the range, the range is
        // cut: the panels then find the dip at once instead of by repeated
        // bisection. That piece, cos(phi) in [c, c + dip], is done in
        // tan(phi / 2), or near pi in tan((pi - phi) / 2) <= 1 (there
        // c + dip < 0).
        const double dip = kDipWidths * alpha / (q.two_cos_h * q.a1);  // in cos(phi)
        const bool cut = dip < 0.25 * (1.0 - c);
        AdaptiveOptions inner_opt;
        inner_opt.rule = KronrodRule::k31;
        inner_opt.abs_tol = cut ? tol / 2 : tol;
        // The panel each piece starts from. G2's branch points, mu_i =
        // +-i alpha / sqrt(1 - alpha^2), lie next to the arc's end (mu_i = 0).
        // An arc that is not cut has mu_i <= mu_max = beta (1 - c) (beta =
        // 2 cos(theta_h) a1, mu_i = beta (cos(phi) - c)), and reach = dip /
        // (1 - c) = kDipWidths alpha / mu_max: the larger, the farther the
        // branch points from the arc against its length, and the fewer nodes
        // a panel needs. Below kDipWidths / 2 (mu_max above 2 alpha) the arc
        // starts from a QK31 panel, up to 4 kDipWidths (mu_max down to
        // alpha / 4) from QK21, beyond from QK15 unless the tolerance is
        // below kQk15RelTol of the integrand's size. Both pieces of a cut arc
        // start from QK21. A first panel whose estimate misses the tolerance
        // is not bisected but replaced by the adaptive QK31 run (its nodes
        // still counted), so every piece meets its tolerance by QUADPACK's
        // estimate as before. The generic (Schlick-Smith) visibility keeps
        // QK31 throughout.
        KronrodRule first = KronrodRule::k21;
        if (f.generic_) {
            first = KronrodRule::k31;
        } else if (!cut) {
            const double reach = dip / (1.0 - c);
            if (reach < 0.5 * kDipWidths)
                first = KronrodRule::k31;
            else if (reach >= 4.0 * kDipWidths && inner_opt.abs_tol >= kQk15RelTol * q.scale)
                first = KronrodRule::k15;
        }
        std::array<double, 3> r{};
        auto add = [&](auto integrand, double s0, double s1) {
            Estimate<2> in;
            if (first != KronrodRule::k31) {
                AdaptiveOptions one = inner_opt;
                one.rule = first;
                one.max_intervals = 1;
                in = integrate_adaptive<2>(integrand, s0, s1, one);
                if (!(in.error[0] <= inner_opt.abs_tol && in.error[1] <= inner_opt.abs_tol)) {
                    const int spent = in.evaluations;
                    in = integrate_adaptive<2>(integrand, s0, s1, inner_opt);
                    in.evaluations += spent;
                }
            } else {
                in = integrate_adaptive<2>(integrand, s0, s1, inner_opt);
            }
            evaluations += in.evaluations;
            r[0] += in.value[0];
            r[1] += in.value[1];
            r[2] += in.error[0] + in.error[1];
        };
        double lo = c;
        if (cut) {
            lo = c + dip;
            if (near_pi)
                add(ArcIntegrand<Arc::half>{f, q, -1.0}, std::sqrt((1.0 + c) / (1.0 - c)),
                    std::sqrt((1.0 + lo) / (1.0 - lo)));
            else
                add(ArcIntegrand<Arc::half>{f, q, 1.0}, std::sqrt((1.0 - lo) / (1.0 + lo)),
                    std::sqrt((1.0 - c) / (1.0 + c)));
        }
        // phi in [0, acos(lo)]; tan(phi / 4) = sin(phi / 2) / (1 + cos(phi / 2)).
        if (near_pi)
            add(ArcIntegrand<Arc::quarter>{f, q, 1.0}, 0.0,
                std::sqrt(0.5 * (1.0 - lo)) / (1.0 + std::sqrt(0.5 * (1.0 + lo))));
        else
            add(ArcIntegrand<Arc::half>{f, q, 1.0}, 0.0, std::sqrt((1.0 - lo) / (1.0 + lo)));
        return r;
    };

    // Outer integrand in x, weighted by w(x) jac: {A, B, accumulated inner error}.
    auto outer = [&](double x, bool clipped, double jac, double span) -> std::array<double, 3> {
        const double e = std::exp(x);
        const double t = alpha * e;
        double c = -2.0;  // cos(phi_max); -2: the full circle
        if (clipped) {
            c = detail::reflection_cos_phi_max(t, mu_o, sin_o);
            if (c >= 1.0) return {0.0, 0.0, 0.0};
        }
        const double w = weight(e) * jac;
        const double size = std::max(1.0, std::sqrt(1.0 + t * t) / mu_o);
        std::array<double, 3> r = c > -1.0 ? clipped_circle(t, c, inner_tol(w, span, kMaxClippedTol * size))
                                           : full_circle(t, inner_tol(w, span));
        for (double& v : r) v *= w;
        return r;
    };

    auto accumulate = [&](const Estimate<3>& e) {
        for (int c = 0; c < 2; ++c) {
            out.value[c] += e.value[c];
            out.error[c] += e.error[c] + e.value[2];
        }
    };

    // Full circle for t <= t_a (normal incidence: t_a = 1, nothing beyond).
    const detail::ReflectionBand band = detail::reflection_band(mu_o, sin_o);
    const double x_a = sin_o == 0.0 ? -ln_alpha : std::log(band.t_a) - ln_alpha;
    const double x_b = sin_o == 0.0 ? x_a : std::log(band.t_b) - ln_alpha;
    // Up to t = alpha (x = 0) integrate in xi = t^2 / (alpha^2 + t^2), where
    // the distribution's measure is uniform: dxi dphi / (2 pi).
    const double x_split = std::min(0.0, x_a);
    {
        const double e2 = std::exp(2.0 * x_split);
        const double xi_end = e2 / (1.0 + e2);
        const double tol = inner_tol(kInvPi, xi_end);
        // When the whole of xi in [0, 1/2] is a full circle (x_a > 0), the
        // integrand is analytic there with its nearest singularity at
        // xi = 1 (t -> infinity; it depends on t^2 only). Otherwise the range
        // ends at t_a, where G2's dip appears at phi = pi; in xi that end is
        // still mild enough for the (7, 15) rule (one panel meets the table
        // tolerances on the whole default grid, where the (15, 31) rule used
        // 31 nodes), and a panel that misses its tolerance is bisected.
        AdaptiveOptions xi_opt = outer_opt;
        xi_opt.rule = KronrodRule::k15;
        accumulate(integrate_adaptive<3>(
            [&](double xi) -> std::array<double, 3> {
                const double t = alpha * std::sqrt(xi / (1.0 - xi));
                std::array<double, 3> r = full_circle(t, tol);
                for (double& v : r) v *= kInvPi;
                return r;
            },
            0.0, xi_end, xi_opt));
    }
    if (x_a > x_split) {
        // Towards x_a the phi integrand develops the dip of G2 at phi = pi, so
        // the outer integrand is not smooth there either: x = x_a - len (1 - u)^2
        // flattens that end.
        const double x_end = std::min(x_a, kHighX), len = x_end - x_split;
        accumulate(integrate_adaptive<3>(
            [&](double u) {
                const double v = 1.0 - u;
                return outer(x_end - len * v * v, false, 2.0 * len * v, 1.0);
            },
            0.0, 1.0, outer_opt));
    }
    const double p0 = x_a, p1 = std::min(x_b, kHighX);
    if (p1 > p0) {
        // x = p0 + (p1 - p0) s(u), s(u) = 3u^2 - 2u^3: smooth at both ends.
        // The integrand has poles a distance pi / 2 from the real x axis
        // (those of sech^2(x) and of cos(theta_h) at t = +-i), so a long
        // band needs panels of a few units of x whatever the tolerance:
        // start from them instead of bisecting down to them.
        const double len = p1 - p0;
        const int panels = static_cast<int>(std::ceil(len / kBandPanelWidth));
        accumulate(integrate_adaptive_panels<3>(
            [&](double u) {
                const double x = p0 + len * u * u * (3.0 - 2.0 * u);
                const double jac = len * 6.0 * u * (1.0 - u);
                return outer(x, true, jac, 1.0);
            },
            0.0, 1.0, panels, outer_opt));
    }
    out.evaluations = evaluations;
    return out;
}

Estimate<1> ggx_albedo_average(double alpha, Visibility vis, double abs_tol) {
    // E(mu) falls from about 1 to 0 where Lambda(mu) ~ 1, that is mu ~ alpha,
    // and varies on the scale of mu itself above that: integrate over
    // [0, b], b = min(alpha, 1), in mu = b u^2 (E(mu) behaves like mu ln(mu)
    // near 0, exactly so at alpha = 1; the map makes the integrand smooth),
    // and over [b, 1] in ln(mu).
    Estimate<1> out;
    if (!(alpha > 0.0)) {  // mirror limit: E = 1
        out.value[0] = 1.0;
        return out;
    }
    AdaptiveOptions opt;
    opt.abs_tol = 0.25 * abs_tol;
    opt.controlled = 1;
    // Each E(mu) is computed to the accuracy its weight 2 mu jac needs, so
    // that the weighted errors integrate to at most 0.25 abs_tol per range
    // (span: the length of the range); near mu = 0, where E(mu) is costly and
    // its weight small, far less work is done.
    double span = 1.0;
    auto integrand = [&](double mu, double jac) -> std::array<double, 2> {
        const double w = 2.0 * mu * jac;
        const double budget = 0.25 * abs_tol / span;
        const double tol = w * kMaxNestedTol > budget ? budget / w : kMaxNestedTol;
        const Estimate<2> s = ggx_split_sum(mu, alpha, vis, tol);
        out.evaluations += s.evaluations;
        return {w * (s.value[0] + s.value[1]), w * (s.error[0] + s.error[1])};
    };
    auto accumulate = [&](const Estimate<2>& e) {
        out.value[0] += e.value[0];
        out.error[0] += e.error[0] + e.value[1];
    };
    const double b = std::min(alpha, 1.0);
    accumulate(integrate_adaptive<2>(
        [&](double u) { return integrand(b * u * u, 2.0 * b * u); }, 0.0, 1.0, opt));
    if (b < 1.0) {
        // Started from panels of at most kLnMuPanelWidth in ln(mu): E(mu)
        // has complex singularities about pi/2 off the real ln(mu) axis
        // (near mu ~ alpha), so a long range is bisected down to about that
        // anyway.
        span = -std::log(b);
        accumulate(integrate_adaptive_panels<2>(
            [&](double v) {
                const double mu = std::exp(v);
                return integrand(mu, mu);
            },
            std::log(b), 0.0, static_cast<int>(std::ceil(span / kLnMuPanelWidth)), opt));
    }
    return out;
}

}  // namespace brdflut
