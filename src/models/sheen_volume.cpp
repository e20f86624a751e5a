#include "brdflut/sheen_volume.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "brdflut/error.h"
#include "brdflut/math.h"
#include "brdflut/quadrature.h"
#include "brdflut/random.h"
#include "brdflut/zeltner_sheen.h"
#include "integrate/simd_lanes.h"

namespace brdflut {
namespace {

// Extinction of the unit-density layer along a direction of cosine nu: the
// fibre SGGX's projected area.
double extinction(double sigma, double nu) {
    return std::sqrt(std::max(0.0, (1.0 - nu) * (1.0 + nu) + sigma * sigma * nu * nu));
}

// m_k(x) = integral over t in [0, 1] of e^(-x t) t^k, k = 0..3: by the
// series for x < 1, else by the upward recurrence m_k = (k m_(k-1) - e^-x) / x.
std::array<double, 4> exp_moments(double x) {
    std::array<double, 4> m{};
    if (x < 1.0) {
        for (int k = 0; k < 4; ++k) {
            double term = 1.0, sum = 0.0;
            for (int j = 0; j < 40; ++j) {
                sum += term / (k + j + 1);
                term *= -x / (j + 1);
                if (std::abs(term) < 1e-18) break;
            }
            m[static_cast<std::size_t>(k)] = sum;
        }
        return m;
    }
    const double e = std::exp(-x);
    m[0] = -std::expm1(-x) / x;
    for (int k = 1; k < 4; ++k) m[static_cast<std::size_t>(k)] = (k * m[static_cast<std::size_t>(k - 1)] - e) / x;
    return m;
}

// The cubic through four depth nodes, as four polynomials in t = distance
// from the segment's evaluated end / its length: coef[m][k] multiplies t^k
// in node m's Lagrange polynomial.
struct SegmentBasis {
    std::size_t start = 0;
    double coef[4][4] = {};
};

SegmentBasis segment_basis(const std::vector<double>& z, std::size_t seg, bool from_lower_end) {
    const std::size_t nz = z.size();
    SegmentBasis b;
    b.start = std::min(seg > 0 ? seg - 1 : 0, nz - 4);
    const double end = from_lower_end ? z[seg] : z[seg + 1], h = z[seg + 1] - z[seg];
    double t[4];
    // Signed coordinates: t grows into the segment.
    for (std::size_t q = 0; q < 4; ++q) t[q] = (from_lower_end ? z[b.start + q] - end : end - z[b.start + q]) / h;
    for (std::size_t m = 0; m < 4; ++m) {
        double poly[4] = {1.0, 0.0, 0.0, 0.0};  // running product, ascending powers
        double denom = 1.0;
        for (std::size_t q = 0; q < 4; ++q) {
            if (q == m) continue;
            for (std::size_t k = 3; k > 0; --k) poly[k] = poly[k - 1] - t[q] * poly[k];
            poly[0] = -t[q] * poly[0];
            denom *= t[m] - t[q];
        }
        for (std::size_t k = 0; k < 4; ++k) b.coef[m][k] = poly[k] / denom;
    }
    return b;
}

// Weights on the four stencil nodes of the integral over a segment of
// length h of lambda e^(-rate u) G, u the distance from the evaluated end.
std::array<double, 4> segment_weights(const SegmentBasis& b, double lambda, double rate, double h) {
    const std::array<double, 4> mom = exp_moments(rate * h);
    std::array<double, 4> w{};
    for (std::size_t m = 0; m < 4; ++m) {
        double acc = 0.0;
        for (std::size_t k = 0; k < 4; ++k) acc += b.coef[m][k] * mom[k];
        w[m] = lambda * h * acc;
    }
    return w;
}

// Integrates over [a, b] by 8-point Gauss-Legendre pieces graded
// geometrically (ratio 2, from 1e-13) away from the point p, where the
// integrand may peak; add(t, weight) receives each node.
template <class Add>
void graded_rule(double a, double b, double p, Add&& add) {
    const GaussLegendre& rule = gauss_legendre(8);
    auto gl = [&](double lo, double hi) {
        const double c = 0.5 * (lo + hi), h = 0.5 * (hi - lo);
        for (std::size_t k = 0; k < rule.x.size(); ++k) add(c + h * rule.x[k], std::abs(h) * rule.w[k]);
    };
    // From the end `near` (nearer p) to `far`, p not strictly between them.
    auto piece = [&](double near, double far) {
        const double dir = far > near ? 1.0 : -1.0;
        const double d0 = std::abs(near - p), d1 = std::abs(far - p);
        if (d0 > 0.0 && d1 <= 2.0 * d0) return gl(near, far);
        double r = std::max(d0, 1e-13);
        if (r > d0) gl(p + dir * d0, p + dir * std::min(r, d1));
        while (r < d1) {
            const double r2 = std::min(2.0 * r, d1);
            gl(p + dir * r, p + dir * r2);
            r = r2;
        }
    };
    if (p > a && p < b) {
        piece(p, a);
        piece(p, b);
    } else if (p <= a) {
        piece(a, b);
    } else {
        piece(b, a);
    }
}

// Product-integration weights of the scattering integral from a direction of
// cosine nu_in, per azimuthal mode m < modes: rows[m][j] multiplies the
// unknown at ordinate j (j < n: +nodes[j], n + j: -nodes[j]); exact when the
// unknown is the local cubic through the four nearest nodes of its
// hemisphere.
std::vector<std::vector<double>> scattering_rows(double sigma, double nu_in, const std::vector<double>& nodes,
                                                 int modes) {
    const int n = static_cast<int>(nodes.size());
    const std::size_t count = static_cast<std::size_t>(modes);
    std::vector<std::vector<double>> rows(count, std::vector<double>(2 * static_cast<std::size_t>(n), 0.0));
    std::vector<double> phase(count);
    std::vector<double> acc(4 * count);
    for (int hemi = 0; hemi < 2; ++hemi) {
        const double sign = hemi == 0 ? 1.0 : -1.0;
        // The phase function peaks at nu = nu_in: in t = |nu| on its own
        // hemisphere, mirrored below t = 0 on the other.
        const double peak = (nu_in > 0.0) == (hemi == 0) ? std::abs(nu_in) : -std::abs(nu_in);
        for (int k = 0; k <= n; ++k) {
            const double lo = k == 0 ? 0.0 : nodes[static_cast<std::size_t>(k - 1)];
            const double hi = k == n ? 1.0 : nodes[static_cast<std::size_t>(k)];
            const int st = std::clamp(k - 2, 0, n - 4);
            const double* x = &nodes[static_cast<std::size_t>(st)];
            std::fill(acc.begin(), acc.end(), 0.0);
            graded_rule(lo, hi, peak, [&](double t, double wt) {
                fibre_phase_modes(sigma, nu_in, sign * t, modes, phase.data());
                for (std::size_t q = 0; q < 4; ++q) {
                    double l = wt;
                    for (std::size_t r = 0; r < 4; ++r)
                        if (r != q) l *= (t - x[r]) / (x[q] - x[r]);
                    for (std::size_t m = 0; m < count; ++m) acc[4 * m + q] += phase[m] * l;
                }
            });
            for (std::size_t m = 0; m < count; ++m)
                for (std::size_t q = 0; q < 4; ++q) rows[m][static_cast<std::size_t>(hemi * n + st) + q] += acc[4 * m + q];
        }
    }
    return rows;
}

std::vector<double> scattering_row(double sigma, double nu_in, const std::vector<double>& nodes) {
    return scattering_rows(sigma, nu_in, nodes, 1)[0];
}

// Depth mesh on [0, 1], symmetric, graded towards both faces: steps from
// 1e-8 growing by 1.15 up to 1/48, uniform in the middle; `refine` divides
// the first step and the largest by refine and takes the ratio's
// refine-th root.
std::vector<double> depth_mesh(int refine) {
    const double f = refine;
    const double h0 = 1e-8 / f, hmax = (1.0 / 48.0) / f, ratio = std::pow(1.15, 1.0 / f);
    std::vector<double> half{0.0};
    double h = h0;
    while (half.back() + h < 0.5 && h < hmax) {
        half.push_back(half.back() + h);
        h *= ratio;
    }
    const double rest = 0.5 - half.back();
    const int steps = std::max(1, static_cast<int>(std::ceil(rest / hmax)));
    const double start = half.back();
    for (int i = 1; i <= steps; ++i) half.push_back(i == steps ? 0.5 : start + rest * i / steps);
    std::vector<double> mesh = half;
    for (int i = static_cast<int>(half.size()) - 2; i >= 0; --i) mesh.push_back(1.0 - half[static_cast<std::size_t>(i)]);
    return mesh;
}

// Direction cosines on (0, 1): Gauss-Legendre on panels graded towards the
// horizon (edges 0, h 2^k below 0.9, [top_edge,] 1), where the escape
// probability exp(-s z / nu) varies on the scale of nu itself.
std::vector<double> direction_nodes(int per_panel, double horizon, double top_edge = 0.0) {
    std::vector<double> edges{0.0};
    for (double e = horizon; e < 0.9; e *= 2.0) edges.push_back(e);
    if (top_edge > 0.0) edges.push_back(top_edge);
    edges.push_back(1.0);
    const GaussLegendre& rule = gauss_legendre(per_panel);
    std::vector<double> nodes;
    for (std::size_t p = 0; p + 1 < edges.size(); ++p) {
        const double a = edges[p], b = edges[p + 1];
        for (double x : rule.x) nodes.push_back(a + 0.5 * (b - a) * (x + 1.0));
    }
    return nodes;
}

// The scattering source of the layer solve, g = W v split by the layer's
// symmetry: for each up ordinate j and depth i, Gu = sum over l of ws_jl
// S_l + wd_jl D_l and Gd = sum of ws_jl S_l - wd_jl D_l (S = v_up + v_down,
// D = v_up - v_down; ws, wd the n x n halves sum_ab, diff_ab; rows of nz
// depths). Each value sums its terms over l in order, as (p + q) and (p -
// q) added to a running sum from 0; two ordinates and eight depths at a
// time are held in registers across l, so that S and D are read once for
// both.
BRDFLUT_WIDEST_CLONES void scatter_source(const double* ws, const double* wd, const double* S, const double* D,
                                          double* g, std::size_t n, std::size_t nz) {
    // Four depths a vector (two SSE2 registers without AVX), two vectors a
    // tile; lane by lane the operations of the scalar loop below.
    using V = double __attribute__((vector_size(32)));
    auto load = [](V& v, const double* p) { std::memcpy(&v, p, sizeof v); };
    auto store = [](double* p, const V& v) { std::memcpy(p, &v, sizeof v); };
    auto one = [&](std::size_t j, std::size_t i0, std::size_t count) {
        for (std::size_t i = i0; i < i0 + count; ++i) {
            double u = 0.0, d = 0.0;
            for (std::size_t l = 0; l < n; ++l) {
                const double p = ws[j * n + l] * S[l * nz + i], q = wd[j * n + l] * D[l * nz + i];
                u += p + q;
                d += p - q;
            }
            g[j * nz + i] = u;
            g[(j + n) * nz + i] = d;
        }
    };
    std::size_t j = 0;
    for (; j + 2 <= n; j += 2) {
        std::size_t i0 = 0;
        for (; i0 + 8 <= nz; i0 += 8) {
            // [ordinate of the pair][four depths]: the sums into g's up and
            // down rows.
            V up[2][2]{}, down[2][2]{};
            for (std::size_t l = 0; l < n; ++l) {
                V sv[2], dv[2];
                for (std::size_t h = 0; h < 2; ++h) {
                    load(sv[h], &S[l * nz + i0 + 4 * h]);
                    load(dv[h], &D[l * nz + i0 + 4 * h]);
                }
                for (std::size_t o = 0; o < 2; ++o) {
                    const double a = ws[(j + o) * n + l], b = wd[(j + o) * n + l];
                    for (std::size_t h = 0; h < 2; ++h) {
                        const V p = a * sv[h], q = b * dv[h];
                        up[o][h] += p + q;
                        down[o][h] += p - q;
                    }
                }
            }
            for (std::size_t o = 0; o < 2; ++o)
                for (std::size_t h = 0; h < 2; ++h) {
                    store(&g[(j + o) * nz + i0 + 4 * h], up[o][h]);
                    store(&g[(j + o + n) * nz + i0 + 4 * h], down[o][h]);
                }
        }
        one(j, i0, nz - i0);
        one(j + 1, i0, nz - i0);
    }
    if (j < n) one(j, 0, nz);
}

}  // namespace

void fibre_phase_modes(double sigma, double nu_in, double nu, int count, double* out) {
    const double s2 = sigma * sigma;
    const double d = nu - nu_in;
    const double c = (1.0 - s2) * d * d;
    const double s_in = extinction(sigma, nu_in);
    const double scale = 1.0 / (2.0 * sigma * s_in);
    if (c == 0.0) {
        // nu = nu_in: the integrand is constant in the azimuth.
        for (int m = 0; m < count; ++m) out[m] = m == 0 ? scale : 0.0;
        return;
    }
    const double a = 1.0 - nu * nu_in;
    const double S = std::sqrt(std::max(0.0, (1.0 - nu) * (1.0 + nu) * (1.0 - nu_in) * (1.0 + nu_in)));
    // A - B = d^2 (2 sigma^2 / (a + S) + 1 - sigma^2), without cancellation;
    // rho = B / (A + Q), and the integral of cos(m phi) / (A - B cos phi)^k
    // is 2 pi rho^m / Q for k = 1 and 2 pi rho^m (m / Q^2 + A / Q^3) for k = 2.
    const double A = 2.0 * s2 * a + c, B = 2.0 * s2 * S;
    const double a_minus_b = d * d * (2.0 * s2 / (a + S) + 1.0 - s2);
    const double Q = std::sqrt(a_minus_b * (A + B));
    const double rho = B / (A + Q);
    // Far from the peak (c >> sigma^2) the closed form's three terms cancel
    // for m = 0 and 1 (they tend to rho^m (m - 1)): those two moments are
    // then taken by the trapezoid rule over the azimuth, whose error on the
    // periodic integrand falls as (B / A / 2)^(24 - m) with B / A < 1/5.
    const bool far = c > 8.0 * s2 * a;
    if (far) {
        constexpr int n = 24;
        const double cd = std::cos(2.0 * kPi / n), sd = std::sin(2.0 * kPi / n);
        double ck = 1.0, sk = 0.0;  // cos and sin of 2 pi k / n, by rotation
        double m0 = 0.0, m1 = 0.0;
        for (int k = 0; k < n; ++k) {
            const double L = 2.0 * (a - S * ck);
            const double u = s2 * L + c;
            const double v = (L / u) * (L / u);
            m0 += v;
            m1 += v * ck;
            const double c_next = ck * cd - sk * sd;
            sk = sk * cd + ck * sd;
            ck = c_next;
        }
        const double f = s2 * sigma / (2.0 * n * s_in);
        out[0] = m0 * f;
        if (count > 1) out[1] = m1 * f;
    }
    double rho_m = 1.0;
    for (int m = 0; m < count; ++m) {
        if (!(far && m < 2)) {
            const double bracket =
                (m == 0 ? 1.0 : 0.0) - 2.0 * c * rho_m / Q + c * c * rho_m * (m / (Q * Q) + A / (Q * Q * Q));
            out[m] = (m == 0 ? std::max(0.0, bracket) : bracket) * scale;
        }
        rho_m *= rho;
    }
}

double fibre_phase_azimuthal(double sigma, double nu_in, double nu) {
    double p = 0.0;
    fibre_phase_modes(sigma, nu_in, nu, 1, &p);
    return p;
}

SheenVolumeLayer::SheenVolumeLayer(double alpha, const SheenVolumeOptions& options)
    : sigma_(alpha * alpha), options_(options) {
    if (!(alpha > 0.0 && alpha <= 1.0)) throw Error("sheen volume: alpha must be in (0, 1]");
    if (options.nodes_per_panel < 4) throw Error("sheen volume: at least 4 nodes a panel");
    if (!(options.horizon_panel > 0.0 && options.horizon_panel < 0.5))
        throw Error("sheen volume: horizon_panel must be in (0, 0.5)");
    if (options.depth_refine < 1) throw Error("sheen volume: depth_refine must be at least 1");
    if (options.cut_after < 0) throw Error("sheen volume: cut_after must be 0 (none) or a number of scatterings");
    nodes_ = direction_nodes(options.nodes_per_panel, options.horizon_panel);
    const std::size_t n = nodes_.size();
    depth_ = depth_mesh(options.depth_refine);
    const std::size_t dirs = 2 * n, nz = depth_.size(), segs = nz - 1;

    // Scattering weights: rows for the up ordinates; a down ordinate's row is
    // its mirror (the layer is symmetric under z -> -z).
    std::vector<double> W(dirs * dirs);
    for (std::size_t j = 0; j < n; ++j) {
        const std::vector<double> row = scattering_row(sigma_, nodes_[j], nodes_);
        for (std::size_t l = 0; l < dirs; ++l) {
            W[j * dirs + l] = row[l];
            W[(j + n) * dirs + (l < n ? l + n : l - n)] = row[l];
        }
    }
    // Transport per ordinate and mesh segment: the decay across it and the
    // weights of the cubic interpolant's stencil. Light travelling up is
    // evaluated at a segment's deeper end, light travelling down at its
    // shallower end.
    std::vector<SegmentBasis> up_basis(segs), down_basis(segs);
    for (std::size_t i = 0; i < segs; ++i) {
        up_basis[i] = segment_basis(depth_, i, false);
        down_basis[i] = segment_basis(depth_, i, true);
    }
    // One discrete system: the transport coefficients and W split by the
    // layer's symmetry, W = [[A, B], [B, A]] on (up, down), so that W v =
    // ((A + B)(v_up + v_down) +- (A - B)(v_up - v_down)) / 2, two products of
    // half the size. `keep_in_closed_form`: the weight an ordinate keeps is
    // summed in closed form (scattering into the same direction only lowers
    // its extinction), and W's diagonal is 0.
    struct System {
        std::vector<double> decay;
        std::vector<std::array<double, 4>> weight;
        std::vector<double> sum_ab, diff_ab;
    };
    auto make_system = [&](bool keep_in_closed_form) {
        System sys;
        sys.decay.resize(dirs * segs);
        sys.weight.resize(dirs * segs);
        std::vector<double> keep(dirs, 0.0);
        for (std::size_t j = 0; j < dirs; ++j) {
            const double lambda = extinction(sigma_, nodes_[j % n]) / nodes_[j % n];
            if (keep_in_closed_form) keep[j] = std::min(W[j * dirs + j], 1.0 - 1e-15);
            const double rate = lambda * (1.0 - keep[j]);
            for (std::size_t i = 0; i < segs; ++i) {
                const double h = depth_[i + 1] - depth_[i];
                sys.decay[j * segs + i] = std::exp(-rate * h);
                sys.weight[j * segs + i] = segment_weights(j < n ? up_basis[i] : down_basis[i], lambda, rate, h);
            }
        }
        sys.sum_ab.resize(n * n);
        sys.diff_ab.resize(n * n);
        for (std::size_t j = 0; j < n; ++j)
            for (std::size_t l = 0; l < n; ++l) {
                const double a = l == j && keep_in_closed_form ? 0.0 : W[j * dirs + l], b = W[j * dirs + l + n];
                sys.sum_ab[j * n + l] = 0.5 * (a + b);
                sys.diff_ab[j * n + l] = 0.5 * (a - b);
            }
        return sys;
    };
    // One transport sweep: out = boundary + transport of the source g, per
    // ordinate. Target 0 counts the top, 1 the bottom, -1 neither.
    auto sweep = [&](const System& sys, const std::vector<double>& g, std::vector<double>& out, int target) {
        for (std::size_t j = 0; j < dirs; ++j) {
            const double* G = &g[j * nz];
            double* I = &out[j * nz];
            const double* e = &sys.decay[j * segs];
            const std::array<double, 4>* w = &sys.weight[j * segs];
            auto stencil = [&](std::size_t i, const SegmentBasis& b) {
                const double* Gs = G + b.start;
                return w[i][0] * Gs[0] + w[i][1] * Gs[1] + w[i][2] * Gs[2] + w[i][3] * Gs[3];
            };
            if (j < n) {
                // Travelling up, depth decreasing: segment i - 1 ends at depth z[i].
                I[0] = target == 0 ? 1.0 : 0.0;
                for (std::size_t i = 1; i < nz; ++i) I[i] = e[i - 1] * I[i - 1] + stencil(i - 1, up_basis[i - 1]);
            } else {
                I[nz - 1] = target == 1 ? 1.0 : 0.0;
                for (std::size_t i = nz - 1; i-- > 0;) I[i] = e[i] * I[i + 1] + stencil(i, down_basis[i]);
            }
        }
    };
    std::vector<double> vs(n * nz), vd(n * nz);
    // g = W v, [ordinate][depth].
    auto scatter = [&](const System& sys, const std::vector<double>& v, std::vector<double>& g) {
        for (std::size_t k = 0; k < n * nz; ++k) {
            vs[k] = v[k] + v[n * nz + k];
            vd[k] = v[k] - v[n * nz + k];
        }
        scatter_source(sys.sum_ab.data(), sys.diff_ab.data(), vs.data(), vd.data(), g.data(), n, nz);
    };
    auto dotp = [](const std::vector<double>& x, const std::vector<double>& y) {
        double sum = 0.0;
        for (std::size_t k = 0; k < x.size(); ++k) sum += x[k] * y[k];
        return sum;
    };
    auto max_abs = [](const std::vector<double>& x) {
        double m = 0.0;
        for (double e : x) m = std::max(m, std::abs(e));
        return m;
    };
    const std::size_t size = dirs * nz;
    std::vector<double> g(size, 0.0), zero(size, 0.0);

    // Every order: (I - T W) v = b, b the light that reaches the target
    // without scattering (but for the kept weight), by BiCGSTAB: the orders'
    // own iteration v <- b + T W v converges as slowly as light creeps
    // between directions (thousands of orders at alpha = 0.01).
    if (options.every_order) {
        const System sys = make_system(true);
        for (int target = 0; target < (options.transmission ? 2 : 1); ++target) {
            std::vector<double> b(size), v(size), r(size), p(size, 0.0), q(size, 0.0), sv(size), t(size);
            sweep(sys, zero, b, target);
            auto apply = [&](const std::vector<double>& x, std::vector<double>& out) {
                scatter(sys, x, g);
                sweep(sys, g, out, -1);
                for (std::size_t k = 0; k < size; ++k) out[k] = x[k] - out[k];
            };
            v = b;
            apply(v, r);
            for (std::size_t k = 0; k < size; ++k) r[k] = b[k] - r[k];
            const std::vector<double> r0 = r;
            double rho = 1.0, step = 1.0, omega = 1.0, residual = max_abs(r);
            constexpr int kMaxIterations = 4000;
            int it = 0;
            for (; it < kMaxIterations && residual > 1e-14; ++it) {
                const double rho_next = dotp(r0, r);
                const double beta = (rho_next / rho) * (step / omega);
                for (std::size_t k = 0; k < size; ++k) p[k] = r[k] + beta * (p[k] - omega * q[k]);
                apply(p, q);
                step = rho_next / dotp(r0, q);
                for (std::size_t k = 0; k < size; ++k) sv[k] = r[k] - step * q[k];
                apply(sv, t);
                const double tt = dotp(t, t);
                omega = tt > 0.0 ? dotp(t, sv) / tt : 0.0;
                for (std::size_t k = 0; k < size; ++k) {
                    v[k] += step * p[k] + omega * sv[k];
                    r[k] = sv[k] - omega * t[k];
                }
                rho = rho_next;
                residual = max_abs(r);
            }
            if (!(residual <= 1e-12))
                throw Error("sheen volume: the transport solve did not converge (residual " + std::to_string(residual) +
                            " after " + std::to_string(it) + " iterations)");
            if (target == 0) {
                iterations_ = it;
                residual_ = residual;
                to_top_ = std::move(v);
            } else {
                to_bottom_ = std::move(v);
            }
        }
    }
    // Single scattering, and the talk's walk cut after `cut_after`
    // scatterings (a walk still inside after the last counted when it points
    // up), order by order on the system without the closed form.
    const System raw = make_system(false);
    single_.resize(size);
    sweep(raw, zero, single_, 0);  // the light leaving after its first scattering
    if (options.cut_after > 0) {
        cut_.assign(size, 0.0);
        for (std::size_t j = 0; j < n; ++j) std::fill(cut_.begin() + static_cast<std::ptrdiff_t>(j * nz),
                                                       cut_.begin() + static_cast<std::ptrdiff_t>((j + 1) * nz), 1.0);
        std::vector<double> next(size);
        for (int order = 1; order < options.cut_after; ++order) {
            scatter(raw, cut_, g);
            sweep(raw, g, next, 0);
            cut_.swap(next);
        }
    }
}

std::array<double, 3> SheenVolumeLayer::reflectances(double mu) const {
    if (!(mu > 0.0 && mu <= 1.0)) throw Error("sheen volume: mu must be in (0, 1]");
    const std::vector<double> w = scattering_row(sigma_, -mu, nodes_);
    const double lambda = extinction(sigma_, mu) / mu;
    return {options_.every_order ? first_collision(w, lambda, to_top_) : std::nan(""),
            options_.cut_after > 0 ? first_collision(w, lambda, cut_) : std::nan(""),
            first_collision(w, lambda, single_)};
}

double SheenVolumeLayer::first_collision(const std::vector<double>& w, double lambda, const std::vector<double>& v) const {
    const std::size_t nz = depth_.size(), dirs = w.size();
    std::vector<double> G(nz, 0.0);
    for (std::size_t l = 0; l < dirs; ++l)
        for (std::size_t i = 0; i < nz; ++i) G[i] += w[l] * v[l * nz + i];
    // The first flight, downward from the top: collisions at depth z with
    // density lambda e^(-lambda z).
    double I = 0.0;
    for (std::size_t i = nz - 1; i-- > 0;) {
        const double h = depth_[i + 1] - depth_[i];
        const SegmentBasis b = segment_basis(depth_, i, true);
        const std::array<double, 4> sw = segment_weights(b, lambda, lambda, h);
        I = std::exp(-lambda * h) * I + sw[0] * G[b.start] + sw[1] * G[b.start + 1] + sw[2] * G[b.start + 2] +
            sw[3] * G[b.start + 3];
    }
    return I;
}

double SheenVolumeLayer::reflectance(double mu) const { return reflectances(mu)[0]; }

double SheenVolumeLayer::transmittance(double mu) const {
    if (!options_.transmission || !options_.every_order)
        throw std::logic_error("sheen volume: transmission was not computed");
    if (!(mu > 0.0 && mu <= 1.0)) throw Error("sheen volume: mu must be in (0, 1]");
    // Light that crosses without scattering leaves through the bottom too.
    const double lambda = extinction(sigma_, mu) / mu;
    return std::exp(-lambda) + first_collision(scattering_row(sigma_, -mu, nodes_), lambda, to_bottom_);
}

SheenVolumeEstimate sheen_volume_reflectance_mc(double alpha, double mu, int max_bounces, long long paths,
                                                std::uint64_t seed) {
    const FibreSggx sggx{alpha * alpha};
    Rng rng(seed, 0);
    long long reflected = 0;
    for (long long p = 0; p < paths; ++p) {
        Vec3 dir{-std::sqrt((1.0 - mu) * (1.0 + mu)), 0.0, -mu};  // propagation
        double depth = 0.0;                                     // 0 top, 1 bottom
        for (int bounce = 0;;) {
            depth += -std::log(1.0 - rng.uniform()) / sggx.projected_area(dir) * -dir.z;
            if (depth < 0.0) {
                ++reflected;
                break;
            }
            if (depth > 1.0) break;
            // A flake normal with density proportional to D(m) max(0, wi.m):
            // drawn from D on the sphere, turned to face wi, kept with
            // probability wi.m.
            const Vec3 wi{-dir.x, -dir.y, -dir.z};
            Vec3 m;
            double wm = 0.0;
            do {
                const double z = sggx.sample_cos_theta(rng.uniform()), st = safe_sqrt(1.0 - z * z);
                const double phi = kTwoPi * rng.uniform();
                m = {st * std::cos(phi), st * std::sin(phi), z};
                wm = dot(wi, m);
                if (wm < 0.0) {
                    m = {-m.x, -m.y, -m.z};
                    wm = -wm;
                }
            } while (rng.uniform() >= wm);
            dir = {2.0 * wm * m.x - wi.x, 2.0 * wm * m.y - wi.y, 2.0 * wm * m.z - wi.z};
            ++bounce;
            if (max_bounces > 0 && bounce >= max_bounces) {
                if (dir.z > 0.0) ++reflected;
                break;
            }
        }
    }
    const double n = static_cast<double>(paths), mean = reflected / n;
    return {mean, std::sqrt(mean * (1.0 - mean) / n)};
}

}  // namespace brdflut

namespace brdflut {
namespace {

// C = A B for n x n row-major matrices. Each C[i][j] sums A[i][k] B[k][j]
// over k in order from 0, sixteen columns of two rows at a time held in
// registers across k (four depths a vector, two SSE2 registers without
// AVX), so that each row of B is read once for both. A k where both rows'
// A[i][k] are 0 is skipped; a zero term of one row adds +-0 to a sum that
// is never -0, which leaves it as it is.
BRDFLUT_WIDEST_CLONES void multiply(const std::vector<double>& A, const std::vector<double>& B,
                                   std::vector<double>& C, std::size_t n) {
    using V = double __attribute__((vector_size(32)));
    constexpr std::size_t kColumns = 16;
    auto row_tail = [&](std::size_t i, std::size_t j0) {
        const double* a = &A[i * n];
        for (std::size_t j = j0; j < n; ++j) {
            double acc = 0.0;
            for (std::size_t k = 0; k < n; ++k)
                if (a[k] != 0.0) acc += a[k] * B[k * n + j];
            C[i * n + j] = acc;
        }
    };
    std::size_t i = 0;
    for (; i + 2 <= n; i += 2) {
        const double* a0 = &A[i * n];
        const double* a1 = &A[(i + 1) * n];
        std::size_t j0 = 0;
        for (; j0 + kColumns <= n; j0 += kColumns) {
            V p0{}, p1{}, p2{}, p3{}, q0{}, q1{}, q2{}, q3{};
            for (std::size_t k = 0; k < n; ++k) {
                const double x0 = a0[k], x1 = a1[k];
                if (x0 == 0.0 && x1 == 0.0) continue;
                V b0, b1, b2, b3;
                const double* b = &B[k * n + j0];
                std::memcpy(&b0, b, sizeof b0);
                std::memcpy(&b1, b + 4, sizeof b1);
                std::memcpy(&b2, b + 8, sizeof b2);
                std::memcpy(&b3, b + 12, sizeof b3);
                p0 += x0 * b0;
                p1 += x0 * b1;
                p2 += x0 * b2;
                p3 += x0 * b3;
                q0 += x1 * b0;
                q1 += x1 * b1;
                q2 += x1 * b2;
                q3 += x1 * b3;
            }
            double* c0 = &C[i * n + j0];
            double* c1 = &C[(i + 1) * n + j0];
            std::memcpy(c0, &p0, sizeof p0);
            std::memcpy(c0 + 4, &p1, sizeof p1);
            std::memcpy(c0 + 8, &p2, sizeof p2);
            std::memcpy(c0 + 12, &p3, sizeof p3);
            std::memcpy(c1, &q0, sizeof q0);
            std::memcpy(c1 + 4, &q1, sizeof q1);
            std::memcpy(c1 + 8, &q2, sizeof q2);
            std::memcpy(c1 + 12, &q3, sizeof q3);
        }
        row_tail(i, j0);
        row_tail(i + 1, j0);
    }
    for (; i < n; ++i) {
        const double* a = &A[i * n];
        std::size_t j0 = 0;
        for (; j0 + kColumns <= n; j0 += kColumns) {
            double acc[kColumns] = {};
            for (std::size_t k = 0; k < n; ++k) {
                if (a[k] == 0.0) continue;
                const double* b = &B[k * n + j0];
                for (std::size_t q = 0; q < kColumns; ++q) acc[q] += a[k] * b[q];
            }
            for (std::size_t q = 0; q < kColumns; ++q) C[i * n + j0 + q] = acc[q];
        }
        row_tail(i, j0);
    }
}

// Solves X Z = Y in place (Y becomes Z; X its LU factors), partial pivoting.
// X's lower part holds the multipliers (L), moved with their rows by the
// later swaps; Y is then permuted and reduced row by row, each Y[i][j] less
// L[i][k] Y[k][j] over k in order (the terms and order of eliminating Y
// alongside X), sixteen columns at a time held in registers across k.
BRDFLUT_WIDEST_CLONES void solve(std::vector<double>& X, std::vector<double>& Y, std::size_t n) {
    constexpr std::size_t kColumns = 16;
    std::vector<std::size_t> pivot(n);
    for (std::size_t k = 0; k < n; ++k) {
        std::size_t p = k;
        for (std::size_t i = k + 1; i < n; ++i)
            if (std::abs(X[i * n + k]) > std::abs(X[p * n + k])) p = i;
        if (X[p * n + k] == 0.0) throw Error("sheen volume: singular doubling step");
        pivot[k] = p;
        if (p != k)
            for (std::size_t j = 0; j < n; ++j) std::swap(X[p * n + j], X[k * n + j]);
        for (std::size_t i = k + 1; i < n; ++i) {
            const double f = X[i * n + k] / X[k * n + k];
            X[i * n + k] = f;
            if (f == 0.0) continue;
            for (std::size_t j = k + 1; j < n; ++j) X[i * n + j] -= f * X[k * n + j];
        }
    }
    for (std::size_t k = 0; k < n; ++k)
        if (pivot[k] != k)
            for (std::size_t j = 0; j < n; ++j) std::swap(Y[pivot[k] * n + j], Y[k * n + j]);
    for (std::size_t i = 1; i < n; ++i) {
        const double* l = &X[i * n];
        double* y = &Y[i * n];
        std::size_t j0 = 0;
        for (; j0 + kColumns <= n; j0 += kColumns) {
            double v[kColumns];
            for (std::size_t q = 0; q < kColumns; ++q) v[q] = y[j0 + q];
            for (std::size_t k = 0; k < i; ++k) {
                if (l[k] == 0.0) continue;
                const double* yk = &Y[k * n + j0];
                for (std::size_t q = 0; q < kColumns; ++q) v[q] -= l[k] * yk[q];
            }
            for (std::size_t q = 0; q < kColumns; ++q) y[j0 + q] = v[q];
        }
        for (std::size_t j = j0; j < n; ++j) {
            double v = y[j];
            for (std::size_t k = 0; k < i; ++k)
                if (l[k] != 0.0) v -= l[k] * Y[k * n + j];
            y[j] = v;
        }
    }
    // Back substitution, each Y[k][j] less X[k][i] Y[i][j] over i in order,
    // sixteen columns at a time held in registers across i.
    for (std::size_t k = n; k-- > 0;) {
        const double* x = &X[k * n];
        double* y = &Y[k * n];
        std::size_t j0 = 0;
        for (; j0 + kColumns <= n; j0 += kColumns) {
            double v[kColumns];
            for (std::size_t q = 0; q < kColumns; ++q) v[q] = y[j0 + q];
            for (std::size_t i = k + 1; i < n; ++i) {
                const double* yi = &Y[i * n + j0];
                for (std::size_t q = 0; q < kColumns; ++q) v[q] -= x[i] * yi[q];
            }
            for (std::size_t q = 0; q < kColumns; ++q) y[j0 + q] = v[q] / x[k];
        }
        for (std::size_t j = j0; j < n; ++j) {
            double v = y[j];
            for (std::size_t i = k + 1; i < n; ++i) v -= x[i] * Y[i * n + j];
            y[j] = v / x[k];
        }
    }
}

// (1 - e^-x) / x, also for x < 0.
double p1_signed(double x) { return std::abs(x) < 1e-8 ? 1.0 - 0.5 * x : -std::expm1(-x) / x; }

// The cubic Lagrange weights at t of the four nodes nearest it.
std::size_t cubic_stencil(const std::vector<double>& nodes, double t, double w[4]) {
    const std::size_t n = nodes.size();
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(nodes.begin(), nodes.end(), t) - nodes.begin());
    const std::size_t st = std::min(k > 2 ? k - 2 : 0, n - 4);
    for (std::size_t q = 0; q < 4; ++q) {
        double l = 1.0;
        for (std::size_t r = 0; r < 4; ++r)
            if (r != q) l *= (t - nodes[st + r]) / (nodes[st + q] - nodes[st + r]);
        w[q] = l;
    }
    return st;
}

}  // namespace

SheenVolumeLobe::SheenVolumeLobe(double alpha, const SheenVolumeBrdfOptions& o) : single_(alpha) {
    if (!(alpha > 0.0 && alpha <= 1.0)) throw Error("sheen volume: alpha must be in (0, 1]");
    if (o.nodes_per_panel < 4 || o.modes < 1 || o.doublings < 1 || o.doublings > 60 ||
        !(o.horizon_panel > 0.0 && o.horizon_panel < 0.5))
        throw Error("sheen volume: nodes_per_panel >= 4, modes >= 1, doublings in 1..60, horizon_panel in (0, 0.5)");
    const double sigma = alpha * alpha;
    // A panel [0.95, 1] besides: the exit density reconstructed at the last
    // node of a wide top panel was 2 % low (at alpha = 0.5), 0.3 % with it.
    nodes_ = direction_nodes(o.nodes_per_panel, o.horizon_panel, 0.95);
    const std::size_t n = nodes_.size(), modes = static_cast<std::size_t>(o.modes);
    // The masses the discrete layer returns at the nodes are integrals of
    // the exit density against the nodes' piecewise-cubic cardinal
    // functions l_k (the product integration's meaning): with the density
    // itself interpolated by the same functions, masses = G density,
    // G_kl = integral over (0, 1) of l_k l_l.
    std::vector<double> gram(n * n, 0.0);
    for (std::size_t k = 0; k <= n; ++k) {
        const double lo = k == 0 ? 0.0 : nodes_[k - 1], hi = k == n ? 1.0 : nodes_[k];
        const std::size_t st = std::min(k > 2 ? k - 2 : 0, n - 4);
        graded_rule(lo, hi, -1.0, [&](double t, double wt) {
            double l[4];
            for (std::size_t q = 0; q < 4; ++q) {
                l[q] = 1.0;
                for (std::size_t r = 0; r < 4; ++r)
                    if (r != q) l[q] *= (t - nodes_[st + r]) / (nodes_[st + q] - nodes_[st + r]);
            }
            for (std::size_t q = 0; q < 4; ++q)
                for (std::size_t r = 0; r < 4; ++r) gram[(st + q) * n + st + r] += wt * l[q] * l[r];
        });
    }
    std::vector<std::vector<std::vector<double>>> rows(n);
    std::vector<double> lambda(n);
    for (std::size_t j = 0; j < n; ++j) {
        rows[j] = scattering_rows(sigma, nodes_[j], nodes_, o.modes);
        lambda[j] = extinction(sigma, nodes_[j]) / nodes_[j];
    }
    const double delta = std::ldexp(1.0, -o.doublings);
    // The modes whose scattering weights are all below 1e-12 of mode 0's
    // largest (they fall as rho^m) are left out, with every mode above them.
    auto largest = [&](std::size_t m) {
        double w = 0.0;
        for (std::size_t j = 0; j < n; ++j)
            for (double v : rows[j][m]) w = std::max(w, std::abs(v));
        return w;
    };
    std::size_t used = 1;
    while (used < modes && largest(used) > 1e-12 * largest(0)) ++used;
    moments_.assign(used, std::vector<double>(n * n));
    std::vector<double> R(n * n), T(n * n), X(n * n), Z(n * n), TR(n * n), tmp(n * n);
    for (std::size_t m = 0; m < used; ++m) {
        // The thin layer, [out][in]: single scattering with its exact
        // attenuation; mass from node j into node l (same hemisphere: the
        // weight up -> up, which by symmetry is also down -> down; flipped:
        // up -> down, also down -> up).
        for (std::size_t j = 0; j < n; ++j)
            for (std::size_t l = 0; l < n; ++l) {
                const double same = rows[j][m][l], flip = rows[j][m][l + n];
                const double lj = lambda[j], ll = lambda[l];
                R[l * n + j] = flip * lj * delta * p1_signed((lj + ll) * delta);
                T[l * n + j] = (l == j ? std::exp(-lj * delta) : 0.0) +
                               same * lj * std::exp(-ll * delta) * delta * p1_signed((lj - ll) * delta);
            }
        // Doubling: a layer on its mirror image.
        for (int d = 0; d < o.doublings; ++d) {
            multiply(R, R, X, n);
            for (std::size_t k = 0; k < n * n; ++k) X[k] = -X[k];
            for (std::size_t k = 0; k < n; ++k) X[k * n + k] += 1.0;
            Z = T;
            solve(X, Z, n);  // Z = (I - R R)^-1 T
            multiply(T, R, TR, n);
            multiply(TR, Z, tmp, n);
            for (std::size_t k = 0; k < n * n; ++k) R[k] += tmp[k];
            multiply(T, Z, tmp, n);
            T.swap(tmp);
        }
        // Less the discrete single scattering of the whole layer; the exit
        // density over the cosine (G^-1 of the masses) over cos(theta_o):
        // the BRDF's moment. The moments are over the azimuth between the
        // propagation directions, which is pi more than the one between wo
        // and wi: cos(m (phi + pi)) = (-1)^m cos(m phi).
        const double factor = (m == 0 ? 1.0 : 2.0) * (m % 2 == 0 ? 1.0 : -1.0) / kTwoPi;
        for (std::size_t j = 0; j < n; ++j)
            for (std::size_t l = 0; l < n; ++l) {
                const double lj = lambda[j], ll = lambda[l];
                tmp[l * n + j] = R[l * n + j] - rows[j][m][l + n] * lj * p1_signed(lj + ll);
            }
        X = gram;
        solve(X, tmp, n);
        for (std::size_t l = 0; l < n; ++l)
            for (std::size_t j = 0; j < n; ++j) tmp[l * n + j] *= factor / nodes_[l];
        // The BRDF is reciprocal; the discrete operator is so only to its
        // discretization (product weights are not symmetric): keep the
        // symmetric part.
        for (std::size_t j = 0; j < n; ++j)
            for (std::size_t l = 0; l < n; ++l) moments_[m][l * n + j] = 0.5 * (tmp[l * n + j] + tmp[j * n + l]);
    }
}

double SheenVolumeLobe::interpolate(const std::vector<double>& table, double mu_o, double mu_i) const {
    const std::size_t n = nodes_.size();
    double wo[4], wi[4];
    const std::size_t so = cubic_stencil(nodes_, mu_o, wo), si = cubic_stencil(nodes_, mu_i, wi);
    double sum = 0.0;
    for (std::size_t a = 0; a < 4; ++a)
        for (std::size_t b = 0; b < 4; ++b) sum += wo[a] * wi[b] * table[(so + a) * n + si + b];
    return sum;
}

double SheenVolumeLobe::f(const Vec3& wo, const Vec3& wi) const {
    if (!(wo.z > 0.0) || !(wi.z > 0.0)) return 0.0;
    const double so = std::sqrt(std::max(0.0, wo.x * wo.x + wo.y * wo.y));
    const double si = std::sqrt(std::max(0.0, wi.x * wi.x + wi.y * wi.y));
    const double c = so > 0.0 && si > 0.0 ? std::clamp((wo.x * wi.x + wo.y * wi.y) / (so * si), -1.0, 1.0) : 1.0;
    double ms = 0.0, prev = 1.0, cur = c;
    for (std::size_t m = 0; m < moments_.size(); ++m) {
        const double cm = m == 0 ? 1.0 : cur;
        ms += interpolate(moments_[m], wo.z, wi.z) * cm;
        if (m >= 1) {
            const double next = 2.0 * c * cur - prev;
            prev = cur;
            cur = next;
        }
    }
    return single_.terms(wo, wi)[0] + ms;
}

double SheenVolumeLobe::multiple_scattering_albedo(double mu_o) const {
    // The interpolant is cubic in mu_i between nodes: 3-point Gauss-Legendre
    // on each interval integrates it times mu_i exactly.
    const GaussLegendre& rule = gauss_legendre(3);
    const std::size_t n = nodes_.size();
    double sum = 0.0;
    for (std::size_t k = 0; k <= n; ++k) {
        const double lo = k == 0 ? 0.0 : nodes_[k - 1], hi = k == n ? 1.0 : nodes_[k];
        const double c = 0.5 * (lo + hi), h = 0.5 * (hi - lo);
        for (std::size_t q = 0; q < rule.x.size(); ++q) {
            const double t = c + h * rule.x[q];
            sum += h * rule.w[q] * interpolate(moments_[0], mu_o, t) * t;
        }
    }
    return kTwoPi * sum;
}

}  // namespace brdflut
