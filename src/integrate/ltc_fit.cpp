// Fitting an LTC to a lobe (GGX, Charlie sheen, EON: LtcLobe) by
// deterministic quadrature (integrate/ltc_quadrature.h, which the error
// figures of any LTC against the lobe it stands for, ltc_report.cpp, share).
// One fitter for every lobe; what differs is the
// lobe's description: f cos, its exact norm (ltc_norms) and where its peak
// is looked for (LtcLobe::peaks_near_mirror), which sets the initial guess
// and the frame of the quadrature (step 2).
//
// Heitz, Dupuy, Hill and Neubelt 2016, "Real-Time Polygonal-Light Shading
//   with Linearly Transformed Cosines"
// Nelder and Mead 1965, "A Simplex Method for Function Minimization"
//
// The fit, per texel (nothing depends on other texels or on threads):
//  1. The target p(w) = f(wo, w) cos(theta) / n0, a density on the upper
//     hemisphere (n0 = the lobe's directional albedo, by the catalogue's
//     quadrature of it: ggx_split_sum, sheen_charlie_albedo, lobe_albedo).
//  2. A product quadrature over the whole sphere in polar coordinates
//     (beta, phi) about the lobe's average direction: tan(beta/2) =
//     w u / (1 - u) with Gauss-Legendre nodes in u on [0, 1] (half the
//     nodes inside the angular width w of the lobe, the tail out to the
//     antipode in the rest), and the midpoint rule in phi on [0, pi] (the
//     lobe is even in y; the rule is spectrally accurate for a smooth
//     periodic integrand). The average direction and the width come from
//     a first quadrature of p about the mirror direction: w = s0 / 2 with
//     s0 = 1 / sqrt(pi p_max), the scale of the cosine whose peak density
//     equals the lobe's.
//     The wide lobes (sheen, EON) take coordinates about the normal
//     instead, w = 1, with half as many radial nodes again (lobe_shape,
//     make_setup): about one side of a sheen ring (its lobe at normal view)
//     the quadrature was not even in x, and the fit of a lobe symmetric
//     about the normal came out tilted.
//  3. The objective: Heitz's error measure, int |p - D|^3 / (p + D) dw
//     / int p^2 dw over the sphere (p = 0 below the horizon, so LTC mass
//     there costs), by quadrature where Heitz samples it, plus (for the
//     wide lobes, sheen and EON) 0.3 times the triangular discrimination
//     int (p - D)^2 / (p + D) dw, which bounds the integrated-light error
//     of every polygon (objective() says why and how it is weighted).
//     (The relative L3 error, int |p - D|^3 / int p^3, reported for
//     every texel, gave larger integrated-light errors when used as the
//     objective.) Near grazing
//     view (mu_o < 0.4) a third term holds the LTC's light to the lobe's
//     over a bank of polygon lights (light_weight_of says why).
//  4. The parameters: M = R(theta) [[m11, 0, m13], [0, m22, 0], [0, 0, 1]]
//     with R(theta) the rotation about y taking z to (sin theta, 0, cos
//     theta), optimised as (theta, ln m11, ln m22, m13 / m11): all four
//     degrees of freedom of a y-symmetric LTC (Heitz fixes theta at the
//     average direction), invariant to the lobe's scale.
//  5. The initial guess, computed from the texel alone: theta at the
//     lobe's peak, m11 and m22 the scales of the cosine with the lobe's
//     half-maximum widths (initial_scale), m13 = 0.
//  6. Nelder-Mead in double from that guess, restarted from its best
//     vertex with smaller simplices until a restart no longer improves J.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "brdflut/error.h"
#include "brdflut/ggx_integrals.h"
#include "brdflut/lobe_integrals.h"
#include "brdflut/ltc.h"
#include "brdflut/ltc_fit.h"
#include "brdflut/oren_nayar.h"
#include "brdflut/quadrature.h"
#include "brdflut/sheen.h"
#include "brdflut/sheen_integrals.h"
#include "integrate/ltc_quadrature.h"
#include "integrate/ltc_simd.h"
#include "integrate/simd_lanes.h"

namespace brdflut {

using namespace ltc_detail;

namespace {

double clamp_alpha(double alpha) { return std::max(alpha, kLtcMinAlpha); }

// The weight of the light term of the objective (fit_objective) at view
// cosine mu: kLtcFitLightWeight (1 - mu / kLtcFitLightMu)^2 below
// kLtcFitLightMu, 0 above (the ramp and its slope continuous, so that the
// fits do not step where it starts). Near grazing view the lobe is cut by
// the horizon under its peak, and a light there that straddles the horizon
// receives the LTC's mass on both sides of it (a shader clips the polygon in
// the cosine's frame only) but the lobe's only above it: the density terms
// see that mass but weigh it lightly, and the light of the peak came out up
// to 0.19 of n0 off. The term holds the LTC's light to the lobe's over a
// bank of eight lights of its own (ltc_fit_light_bank, not the report's
// bank). Measured on the 64x64 GGX table against Heitz's (bench/RESULTS.md):
// without the term the refit's light error was above his by more than 0.05
// of n0 at 9 texels of the last row, by 0.105 at most; with it at none, by
// 0.028 at most, the median 0.0103 as before. (The variants, measured with
// the triangular discrimination at 0.3 in the objective too,
// ltc_mass_weight:) weight 1 left 2 texels above by 0.05; weight 10 lowered
// the largest excess to 0.032 but tripled the error at the roughest grazing
// texel; the term over the whole table (weight 1 at every mu) moved the
// median to 0.0109. The bank's overhead light sits 31 degrees toward the
// view: at the normal, or at 17 degrees, it doubled to tripled the error of
// the roughest grazing texels (its placement was chosen by the report's
// figures of the last row, among six).
double light_weight_of(double mu) {
    const double r = std::max(0.0, 1.0 - mu / kLtcFitLightMu);
    return kLtcFitLightWeight * r * r;
}

// The setup of the fit's objective (fit_objective): make_setup at the
// options' grid, with the light term's weight and the lobe's exact light
// over the fit bank where the weight is not 0.
Setup make_fit_setup(const LtcLobe& lobe, double n0, const LtcFitOptions& opt) {
    Setup s = make_setup(lobe, n0, opt.radial_nodes, opt.azimuth_nodes);
    // The two-parameter form has no rotation to spend on the lights near
    // grazing view, and their exact integrals cost most of a fit of a
    // narrow lobe there: it fits the densities alone.
    s.light_weight = opt.two_parameter ? 0.0 : light_weight_of(lobe.mu_o);
    if (s.light_weight > 0.0) {
        s.lights = ltc_fit_light_bank(lobe.mu_o);
        for (const LtcLight& l : s.lights)
            s.light_mass.push_back(polygon_light(lobe, s.frame, l, opt.light_tolerance * n0) / n0);
    }
    return s;
}

// The fit's objective: Heitz's error measure, computed by quadrature instead
// of by sampling, plus a multiple of the triangular discrimination T of the
// two densities,
//   J = int |p - D|^3 / (p + D) dw / int p^2 dw + w T,
//   T = int (p - D)^2 / (p + D) dw,   w = ltc_mass_weight(lobe).
// T bounds the integrated-light error of every polygon:
// the LTC's light is n0 times its mass in the polygon and the lobe's n0
// times p's, and the largest difference of two densities' masses over any
// region is half their L1 distance, which is at most sqrt(2 T) (Cauchy-
// Schwarz with int (p + D) = 2). Heitz's measure alone, weighted by p^2,
// barely sees mass that the LTC spreads thinly far from the peak: at
// grazing view and small roughness its optimum put a quarter of the LTC's
// mass behind the viewer, and the light of the peak lost as much. Where
// p = 0 the integrand of T is D, so T is computed as the quadrature over
// p > 0 plus 1 - (the quadrature of D over p > 0), with int D = 1 exactly:
// LTC mass anywhere outside the lobe counts, whether or not a node of the
// grid falls on it. Both terms are smooth in the parameters (an L1 term,
// with its kink at p = D inside the panels, made the fitted table noisy).
// The weight: 0.3 for the wide lobes (sheen, EON), 0 for GGX. Measured on
// the 64x64 GGX table before the light term (fit_objective) existed, the
// largest integrated-light error was 0.36 of n0 with Heitz's measure alone,
// 0.19 at w = 0.3, 0.18 at w = 1 and 0.28 at w = 0.1, all of it at grazing
// view. With the light term there, T's weight only costs: at w = 0.3, 0.1,
// 0.03 and 0 the largest light error is 0.158, 0.150, 0.146 and 0.144, the
// texels above twice Heitz's error (floor 1e-3) 67, 63, 53 and 32, the
// relative L3 median 0.041, 0.039, 0.036 and 0.034; and the minima of the
// two terms part in the middle of the table, where the fitted coefficients
// stepped from one to the other along a line of texels (the largest second
// difference between neighbours, as a fraction of max(1, |coefficient|),
// outside the last row: 0.047 at w = 0.3, 0.018 at w = 0). For the sheen
// T still pays: its light error median is 0.028 at w = 0.3 and 0.031 at
// w = 0, its largest 0.068 and 0.073 (EON 0.0043 and 0.0046).

// The three sums of the objective over the grid, node i in lane i % 4 and
// the lanes added as (l0 + l1) + (l2 + l3), written once over the lane
// types (ltc_objective_kernel.inc): AVX2 takes the four lanes in one
// register, SSE2 two per register, the scalar path one at a time, by the
// same operations in the same order, so the fit does not depend on which
// one runs. (Two divisions per node: the divisions are most of the fit's
// time.)
struct ObjectiveSums {
    double heitz = 0.0, tri = 0.0, inside = 0.0;
};
// The grid's arrays (a whole number of lane groups long, make_grid).
struct GridView {
    const double *x, *y, *z, *p, *w;
    std::size_t n;
};

namespace lanes_scalar {
using simd::scalar::V;
#include "integrate/ltc_objective_kernel.inc"
}  // namespace lanes_scalar

#if defined(__SSE2__)
namespace lanes_sse2 {
using simd::sse2::V;
#include "integrate/ltc_objective_kernel.inc"
}  // namespace lanes_sse2
#endif

}  // namespace

#if defined(BRDFLUT_HAVE_AVX2_KERNELS)
// Compiled for AVX2 whatever the build's target, and called only when the
// processor has it. AVX2 alone implies no fused multiply-add, so each lane
// rounds as in the SSE2 and scalar sums.
BRDFLUT_AVX2_BEGIN
namespace {
namespace lanes_avx2 {
using simd::avx2::V;
#include "integrate/ltc_objective_kernel.inc"
}  // namespace lanes_avx2
}  // namespace
BRDFLUT_AVX2_END
#endif

namespace {

int widest_objective() {
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
const int kWidestObjective = widest_objective();
int g_objective_width = kWidestObjective;

ObjectiveSums objective_sums(const SphereGrid& grid, const Mat3& minv, double det_over_pi) {
    const GridView g{grid.x.data(), grid.y.data(), grid.z.data(), grid.p.data(), grid.w.data(), grid.size()};
#if defined(BRDFLUT_HAVE_AVX2_KERNELS)
    if (g_objective_width == 4) return lanes_avx2::objective_sums(g, minv, det_over_pi);
#endif
#if defined(__SSE2__)
    if (g_objective_width == 2) return lanes_sse2::objective_sums(g, minv, det_over_pi);
#endif
    return lanes_scalar::objective_sums(g, minv, det_over_pi);
}

double objective(const SphereGrid& g, const Mat3& minv) {
    const ObjectiveSums s = objective_sums(g, minv, std::abs(minv.det()) / kPi);
    return s.heitz / g.p2 + g.mass_weight * (s.tri + std::max(0.0, 1.0 - s.inside));
}

double fit_objective(const Setup& s, const Mat3& minv) {
    double j = objective(s.grid, minv);
    if (s.light_weight > 0.0) {
        double l = 0.0;
        for (std::size_t k = 0; k < s.lights.size(); ++k) {
            const double d = ltc_polygon_integral(minv, s.lights[k].vertices.data(), 4) - s.light_mass[k];
            l += d * d;
        }
        j += s.light_weight * l;
    }
    return j;
}

// expansion 2, contraction 1/2, shrink 1/2), from x0 with steps `step`.
template <int N, class F>
std::array<double, N> nelder_mead(F&& f, const std::array<double, N>& x0, const std::array<double, N>& step,
                                  double& fbest, int max_evals, int& evals) {
    std::array<std::array<double, N>, N + 1> x;
    std::array<double, N + 1> fx;
    x[0] = x0;
    fx[0] = f(x0);
    ++evals;
    for (int i = 0; i < N; ++i) {
        x[i + 1] = x0;
        x[i + 1][i] += step[i];
        fx[i + 1] = f(x[i + 1]);
        ++evals;
    }
    std::array<int, N + 1> order;
    int budget = max_evals;
    while (budget > 0) {
        std::iota(order.begin(), order.end(), 0);
        // Stable order by value then index, so ties resolve the same way always.
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return fx[a] < fx[b]; });
        const int best = order[0], worst = order[N], second = order[N - 1];
        const double spread = fx[worst] - fx[best];
        double size = 0.0;
        for (int i = 0; i <= N; ++i)
            for (int k = 0; k < N; ++k) size = std::max(size, std::abs(x[i][k] - x[best][k]));
        if (spread <= 1e-13 * std::abs(fx[best]) + 1e-300 || size < 1e-9) break;
        std::array<double, N> c{};
        for (int i = 0; i <= N; ++i)
            if (i != worst)
                for (int k = 0; k < N; ++k) c[k] += x[i][k] / N;
        auto along = [&](double t) {
            std::array<double, N> y;
            for (int k = 0; k < N; ++k) y[k] = c[k] + t * (x[worst][k] - c[k]);
            return y;
        };
        const std::array<double, N> xr = along(-1.0);
        const double fr = f(xr);
        --budget;
        if (fr < fx[best]) {
            const std::array<double, N> xe = along(-2.0);
            const double fe = f(xe);
            --budget;
            if (fe < fr) {
                x[worst] = xe;
                fx[worst] = fe;
            } else {
                x[worst] = xr;
                fx[worst] = fr;
            }
        } else if (fr < fx[second]) {
            x[worst] = xr;
            fx[worst] = fr;
        } else {
            const bool outside = fr < fx[worst];
            const std::array<double, N> xc = along(outside ? -0.5 : 0.5);
            const double fc = f(xc);
            --budget;
            if (fc < (outside ? fr : fx[worst])) {
                x[worst] = xc;
                fx[worst] = fc;
            } else {
                for (int i = 0; i <= N; ++i) {
                    if (i == best) continue;
                    for (int k = 0; k < N; ++k) x[i][k] = x[best][k] + 0.5 * (x[i][k] - x[best][k]);
                    fx[i] = f(x[i]);
                    --budget;
                }
            }
        }
    }
    const int best = static_cast<int>(std::min_element(fx.begin(), fx.end()) - fx.begin());
    evals += max_evals - budget;
    fbest = fx[best];
    return x[best];
}

}  // namespace

std::string to_string(LtcLobeKind kind) {
    switch (kind) {
        case LtcLobeKind::ggx: return "ggx";
        case LtcLobeKind::charlie_sheen: return "charlie_sheen";
        case LtcLobeKind::eon: return "eon";
        case LtcLobeKind::generic: return "generic";
    }
    return "unknown";
}

double ltc_mass_weight(const LtcLobe& lobe) { return lobe.peaks_near_mirror() ? 0.0 : kLtcWideLobeMassWeight; }

namespace {
double clamp_param(LtcLobeKind kind, double p) {
    switch (kind) {
        case LtcLobeKind::ggx: return clamp_alpha(p);
        case LtcLobeKind::charlie_sheen: return std::clamp(p, kLtcSheenMinAlpha, 1.0);
        case LtcLobeKind::eon: return std::clamp(p, 0.0, 1.0);
        case LtcLobeKind::generic: return p;  // the lobe clamps its own parameter
    }
    return p;
}
}  // namespace

namespace {
// Nelder-Mead from x0, restarted from its best vertex with simplices 5 times
// smaller until a restart no longer improves f.
template <std::size_t N, class F>
std::array<double, N> descend_from(F&& f, std::array<double, N> x, const std::array<double, N>& step0, double& fx,
                                   int& evals) {
    fx = f(x);
    ++evals;
    double shrink = 1.0;
    for (int restart = 0; restart < 8; ++restart) {
        double fn = 0.0;
        std::array<double, N> steps = step0;
        for (double& v : steps) v *= shrink;
        const std::array<double, N> xn = nelder_mead<N>(f, x, steps, fn, 800, evals);
        const bool improved = fn < fx * (1.0 - 1e-9);
        if (fn < fx) {
            x = xn;
            fx = fn;
        }
        if (!improved && restart > 0) break;
        shrink *= 0.2;
    }
    return x;
}
}  // namespace

LtcLobe::LtcLobe(double mu, double alpha, Visibility v) : LtcLobe(LtcLobeKind::ggx, mu, alpha, v) {}

LtcLobe::LtcLobe(LtcLobeKind k, double mu, double p, Visibility v)
    : kind(k), param(clamp_param(k, p)), ggx{k == LtcLobeKind::ggx ? clamp_param(k, p) : kLtcMinAlpha}, vis(v),
      wo(direction_from_mu(clamp_mu(mu))), mu_o(clamp_mu(mu)), peaked_(k == LtcLobeKind::ggx) {
    if (k == LtcLobeKind::generic)
        throw Error("a generic LTC lobe is built from its GenericLobe (LtcLobe(lobe, mu_o, param, key, tolerance))");
}

LtcLobe::LtcLobe(std::shared_ptr<const GenericLobe> lobe, double mu, double p, std::uint64_t k, double tol)
    : kind(LtcLobeKind::generic), param(p), wo(direction_from_mu(clamp_mu(mu))), mu_o(clamp_mu(mu)),
      generic(std::move(lobe)), key(k), norm_tolerance(tol) {
    if (!generic) throw Error("a generic LTC lobe needs its GenericLobe");
    peaked_ = generic->hints(wo).has_peak;
}

// GGX: f cos(theta_i) = D(h) G2(o, i) / (4 mu_o), h = wo + wi (not
// normalized). D = a^2 / (pi (sin^2 + a^2 cos^2)^2) of the half vector's
// angle, written with sin^2 from h.x^2 + h.y^2 instead of 1 - cos^2: at
// alpha = 1e-5 the peak is at sin^2 ~ 1e-10, which 1 - cos^2 resolves only
// to ~1e-6. The other lobes: their BRDF (sheen.h, oren_nayar.h) times
// cos(theta_i).
double LtcLobe::operator()(const Vec3& wi) const {
    if (wi.z <= 0.0 || wo.z <= 0.0) return 0.0;
    switch (kind) {
        case LtcLobeKind::ggx: {
            const Vec3 h = add(wo, wi);
            if (h.z <= 0.0) return 0.0;
            const double a2 = ggx.alpha * ggx.alpha;
            const double s2 = h.x * h.x + h.y * h.y, c2 = h.z * h.z, l2 = s2 + c2;
            const double t = s2 + a2 * c2;
            const double D = a2 * l2 * l2 / (kPi * t * t);
            return D * ggx.G2(mu_o, wi.z, vis) / (4.0 * mu_o);
        }
        case LtcLobeKind::charlie_sheen: return charlie_sheen_brdf(Charlie{param}, wo, wi) * wi.z;
        case LtcLobeKind::eon: return Eon{FujiiOrenNayar{param}}.brdf(wo, wi) * wi.z;
        case LtcLobeKind::generic: return generic->f(wo, wi) * wi.z;
    }
    return 0.0;
}

std::vector<Vec3> LtcLobe::point_kinks() const {
    switch (kind) {
        case LtcLobeKind::charlie_sheen: return {Vec3{-wo.x, -wo.y, wo.z}};
        case LtcLobeKind::generic: return generic->hints(wo).point_kinks;
        case LtcLobeKind::ggx:
        case LtcLobeKind::eon: return {};
    }
    return {};
}

LtcNorms ltc_norms(const LtcLobe& lobe) {
    LtcNorms n;
    switch (lobe.kind) {
        case LtcLobeKind::ggx: {
            const Estimate<2> e = ggx_split_sum(lobe.mu_o, lobe.ggx.alpha, lobe.vis, kGgxTableTolerance);
            n.n0 = e.value[0] + e.value[1];
            n.n1 = e.value[1];
            n.n0_error = e.error[0] + e.error[1];
            n.n1_error = e.error[1];
            break;
        }
        case LtcLobeKind::charlie_sheen: {
            const Estimate<1> e = sheen_charlie_albedo(lobe.mu_o, lobe.param, kSheenAbsTolerance);
            n.n0 = e.value[0];
            n.n0_error = e.error[0];
            break;
        }
        case LtcLobeKind::eon: {
            const Estimate<1> e = lobe_albedo(Lobe::eon, lobe.mu_o, lobe.param, kLobeAbsTolerance);
            n.n0 = e.value[0];
            n.n0_error = e.error[0];
            break;
        }
        case LtcLobeKind::generic: {
            if (lobe.known_n0 >= 0.0) {
                n.n0 = lobe.known_n0;
                n.n0_error = lobe.known_n0_error;
                n.n1 = lobe.known_n1;
                n.n1_error = lobe.known_n1_error;
                break;
            }
            // The lobe's own route to {n0, n1}, else the split sums {A, B}
            // of the generic path: n0 = A + B, n1 = B.
            Estimate<2> own;
            if (lobe.generic->own_moments(lobe.mu_o, lobe.norm_tolerance, own)) {
                n.n0 = own.value[0];
                n.n1 = own.value[1];
                n.n0_error = own.error[0];
                n.n1_error = own.error[1];
                break;
            }
            GenericOptions opt;
            opt.abs_tol = lobe.norm_tolerance;
            const Estimate<2> e = generic_moments<2>(*lobe.generic, lobe.mu_o, kSplitSumWeights, opt);
            n.n0 = e.value[0] + e.value[1];
            n.n1 = e.value[1];
            n.n0_error = e.error[0] + e.error[1];
            n.n1_error = e.error[1];
            break;
        }
    }
    return n;
}

LtcFitOptions ltc_fit_options(int quality_level) {
    LtcFitOptions o;
    if (quality_level <= 0) {
        o.radial_nodes = 16;
        o.azimuth_nodes = 10;
        o.light_tolerance = 1e-4;
    } else if (quality_level >= 2) {
        o.radial_nodes = 56;
        o.azimuth_nodes = 32;
        o.light_tolerance = 1e-8;
    }
    return o;
}

LtcInverse ltc_inverse_from_params(const std::array<double, 4>& p) {
    const double ct = std::cos(p[0]), st = std::sin(p[0]);
    const double m11 = std::exp(p[1]), m22 = std::exp(p[2]), m13 = p[3] * m11;
    const Mat3 r{{{{ct, 0, st}, {0, 1, 0}, {-st, 0, ct}}}};
    const Mat3 s{{{{m11, 0, m13}, {0, m22, 0}, {0, 0, 1}}}};
    return LtcInverse::from_matrix((r * s).inverse());
}

double ltc_objective(const LtcLobe& lobe, const std::array<double, 4>& params, const LtcFitOptions& opt) {
    const Setup s = make_fit_setup(lobe, ltc_norms(lobe).n0, opt);
    return fit_objective(s, ltc_inverse_from_params(params).matrix());
}

double ltc_local_minimum_drop(const LtcLobe& lobe, const LtcFit& fit, const LtcFitOptions& opt) {
    const Setup s = make_fit_setup(lobe, ltc_norms(lobe).n0, opt);
    const double j0 = fit_objective(s, ltc_inverse_from_params(fit.params).matrix());
    // Steps relative to each parameter's scale: theta in units of the lobe's width.
    const double width = std::min(std::exp(fit.params[1]), 1.0);
    const double steps[4] = {1e-3 * width, 1e-3, 1e-3, 1e-3};
    double drop = -std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < 4; ++k)
        for (double sgn : {-1.0, 1.0}) {
            // The two-parameter form moves ln m11 and ln m22 together and
            // keeps theta at 0.
            if (opt.two_parameter && (k == 0 || k == 2)) continue;
            std::array<double, 4> p = fit.params;
            p[k] += sgn * steps[k];
            if (opt.two_parameter && k == 1) p[2] = p[1];
            drop = std::max(drop, (j0 - fit_objective(s, ltc_inverse_from_params(p).matrix())) / j0);
        }
    return drop;
}

double ltc_objective(double mu, double alpha, Visibility vis, const std::array<double, 4>& params,
                     const LtcFitOptions& opt) {
    return ltc_objective(LtcLobe(mu, alpha, vis), params, opt);
}

LtcFit fit_ggx_ltc(double mu, double alpha, Visibility vis, const LtcFitOptions& opt) {
    return fit_ltc(LtcLobe(mu, alpha, vis), opt);
}

LtcFit fit_ltc(const LtcLobe& lobe, const LtcFitOptions& opt) { return fit_ltc_from(lobe, nullptr, opt); }

LtcFit fit_ltc_from(const LtcLobe& lobe, const std::array<double, 4>* start, const LtcFitOptions& opt) {
    LtcFit out;
    const LtcNorms norms = ltc_norms(lobe);
    out.n0 = norms.n0;
    out.n1 = norms.n1;
    out.n0_error = norms.n0_error;
    out.n1_error = norms.n1_error;
    const Setup s = make_fit_setup(lobe, out.n0, opt);
    auto f = [&](const std::array<double, 4>& p) { return fit_objective(s, ltc_inverse_from_params(p).matrix()); };

    int evals = 0;
    if (opt.two_parameter) {
        // theta = 0 and m22 = m11: the parameters (ln m11, m13 / m11).
        auto f2 = [&](const std::array<double, 2>& q) { return f({0.0, q[0], q[0], q[1]}); };
        const std::array<double, 4>& x0 = start ? *start : s.x0;
        double fx = 0.0;
        const std::array<double, 2> q = descend_from<2>(f2, {0.5 * (x0[1] + x0[2]), x0[3]},
                                                        {0.5 * (s.step[1] + s.step[2]), s.step[3]}, fx, evals);
        out.params = {0.0, q[0], q[0], q[1]};
        out.minv = ltc_inverse_from_params(out.params);
        out.objective = fx;
        out.below_horizon = below_horizon_of(out.minv);
        out.evaluations = evals;
        return out;
    }
    auto descend = [&](const std::array<double, 4>& x0, const std::array<double, 4>& step0, double& fx) {
        return descend_from<4>(f, x0, step0, fx, evals);
    };
    double fx = 0.0;
    std::array<double, 4> x = descend(start ? *start : s.x0, s.step, fx);
    // A lobe too wide for its half-maximum widths to place the cosine (rough
    // lobes at grazing view, nearly uniform over the hemisphere) can send
    // the simplex to a cosine turned below the horizon: then start again
    // from the unit cosine turned to the peak, and keep the better fit.
    if (below_horizon_of(ltc_inverse_from_params(x)) > 0.05) {
        double f2 = 0.0;
        const std::array<double, 4> x2 = descend({s.x0[0], 0.0, 0.0, 0.0}, {0.25, 0.3, 0.3, 0.3}, f2);
        if (f2 < fx) {
            x = x2;
            fx = f2;
        }
    }
    out.params = x;
    out.minv = ltc_inverse_from_params(x);
    out.objective = fx;
    out.below_horizon = below_horizon_of(out.minv);
    out.evaluations = evals;
    return out;
}

// ---- The fit's light bank ----

std::vector<LtcLight> ltc_fit_light_bank(double mu) {
    mu = clamp_mu(mu);
    const double s = safe_sqrt(1.0 - mu * mu);
    const Vec3 r{-s, 0.0, mu};
    return {
        square("fit: peak 3 deg", r, 3.0),
        square("fit: peak 10 deg", r, 10.0),
        square("fit: peak 25 deg", r, 25.0),
        square("fit: 20 deg toward the view, 15 deg", rotate_y(r, 20.0), 15.0),
        square("fit: 15 deg beyond the mirror direction, 10 deg", rotate_y(r, -15.0), 10.0),
        square("fit: side, 20 deg", from_angles(std::asin(mu) * 180.0 / kPi, 120.0), 20.0),
        square("fit: horizon, 12 deg", from_angles(8.0, 160.0), 12.0),
        square("fit: 31 deg from the normal toward the view, 35 deg", Vec3{0.6, 0, 1}, 35.0),
    };
}

namespace detail {
int ltc_objective_simd_width() { return g_objective_width; }
int set_ltc_objective_simd_width(int width) {
    const int w = std::min(width, kWidestObjective);
    g_objective_width = w >= 4 ? 4 : w >= 2 ? 2 : 1;
    return g_objective_width;
}
}  // namespace detail

}  // namespace brdflut
