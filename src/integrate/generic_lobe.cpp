// The generic lobe path (generic_lobe.h): nested adaptive Gauss-Kronrod in
// polar coordinates about the lobe's peak, and Monte Carlo.
#include "brdflut/generic_lobe.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "brdflut/fresnel.h"
#include "brdflut/random.h"

namespace brdflut {

double moment_weight::one(double, double) { return 1.0; }
double moment_weight::schlick(double c, double) { return schlick_weight(c); }
double moment_weight::one_minus_schlick(double c, double) { return 1.0 - schlick_weight(c); }
double moment_weight::schlick_power(double c, double p) { return std::pow(std::max(1.0 - c, 0.0), p); }
double moment_weight::f82(double c, double) {
    const double m = std::max(1.0 - c, 0.0), m2 = m * m;
    return c * m2 * m2 * m2;
}
double moment_weight::dielectric_fresnel(double c, double p) { return fresnel_dielectric(c, p); }
double moment_weight::dielectric_remapped(double c, double p) {
    const double r = (p - 1.0) / (p + 1.0), f0 = r * r;
    if (!(f0 < 1.0) || !(f0 > 0.0)) return 0.0;
    return std::clamp((fresnel_dielectric(c, p) - f0) / (1.0 - f0), 0.0, 1.0);
}

// Where the weights defined above are not smooth in c. A weight w(c) of
// c = wo.h depends on wi only through the angle 2 acos(c) between wo and wi
// (wo.wi = 2 c^2 - 1), so a feature at c is a cone about wo.
std::vector<double> weight_view_cones(const MomentWeight& w) {
    std::vector<double> angles;
    const auto cone = [&angles](double c) { angles.push_back(2.0 * std::acos(std::clamp(c, 0.0, 1.0))); };
    if (w.f == moment_weight::schlick_power) {
        // (1 - c)^e is (angle from wo)^(2e) near c = 1: smooth for an integer
        // e, a cusp otherwise, sharp for small e. The cones 1 - c = 10^-k,
        // k = 1..8, let the rule resolve it at every scale; above e = 6 the
        // rule's own order covers it.
        if (w.p > 0.0 && w.p < 6.0 && w.p != std::round(w.p))
            for (int k = 1; k <= 8; ++k) cone(1.0 - std::pow(10.0, -k));
        return angles;
    }
    if (w.f != moment_weight::dielectric_fresnel && w.f != moment_weight::dielectric_remapped) return angles;
    const double eta = w.p;
    if (!(eta > 0.0) || eta == 1.0) return angles;
    // Total internal reflection (eta < 1): F = 1 for c below the critical cosine.
    if (eta < 1.0) cone(std::sqrt((1.0 - eta) * (1.0 + eta)));
    if (w.f == moment_weight::dielectric_remapped) {
        // (F - F0) / (1 - F0) is clamped at 0 where the unpolarized reflectance
        // dips below F0 (eta above about 3, between c* and 1): a kink at c*.
        const double r = (eta - 1.0) / (eta + 1.0), f0 = r * r;
        const auto g = [&](double c) { return fresnel_dielectric(c, eta) - f0; };
        constexpr int kSteps = 256;
        double c0 = 1e-6, g0 = g(c0);
        for (int i = 1; i < kSteps; ++i) {  // c = 1 itself is a root of every eta
            const double c1 = static_cast<double>(i) / kSteps, g1 = g(c1);
            if ((g0 < 0.0) != (g1 < 0.0) && g0 != 0.0 && g1 != 0.0) {
                double lo = c0, hi = c1;
                for (int it = 0; it < 60; ++it) {
                    const double mid = 0.5 * (lo + hi);
                    ((g(mid) < 0.0) == (g0 < 0.0) ? lo : hi) = mid;
                }
                cone(0.5 * (lo + hi));
            }
            c0 = c1;
            g0 = g1;
        }
    }
    return angles;
}

LobeHints microfacet_reflection_hints(const Vec3& wo, double alpha) {
    LobeHints h;
    h.has_peak = true;
    h.peak = {-wo.x, -wo.y, wo.z};
    h.width = 2.0 * alpha;
    h.aspect = std::min(1.0, wo.z + alpha);
    return h;
}

namespace {

constexpr std::size_t kMaxWeights = 4;
// Four moments and, last, the integrated error estimate of the inner rule.
using Row = std::array<double, kMaxWeights + 1>;

// A piece in ln(theta) is integrated from panels of at most this many units
// (each then bisected as needed): the integrand has complex singularities
// about one unit off the real axis near the lobe's width, so a long range
// would be bisected down to about that anyway.
constexpr double kLnPanelWidth = 2.0;
// The loosest tolerance of an inner integral relative to its size (its first
// panel's value): far in the tail, where the outer weight is tiny, the
// budget alone would accept a panel that has resolved nothing.
constexpr double kMaxInnerRelTol = 1e-6;
// ... but never below this fraction of the budget: a ring whose whole value
// is far below the budget needs no relative accuracy.
constexpr double kTailFraction = 1e-3;
// The range of E_avg in ln(mu) is integrated from panels of at most this width.
constexpr double kLnMuPanelWidth = 3.0;
// The loosest tolerance of a moment inside E_avg.
constexpr double kMaxNestedTol = 1e-5;
// Half the spacing of doubles in [0.5, 1): the rounding of a unit vector's
// largest components.
constexpr double kDirectionUlp = 0x1.0p-53;

// A cone of LobeHints in the frame: wi.d > cos(beta) inside, gamma the
// polar angle of its axis d about the peak.
struct FrameCone {
    Vec3 d;
    double beta, cos_beta, gamma;
};

// The view direction, the lobe's frame and its shape.
struct Frame {
    Vec3 wo;
    Vec3 p, e1, e2;  // peak; up in the plane of p and the normal; horizontal
    double w = 1.0, aspect = 1.0;
    double theta_a = 0.0;  // below: whole rings above the horizon
    double theta_end = kPi;
    bool hemisphere = true;
    // Over the lower hemisphere: the frame and the polar coordinates are
    // those of the mirror image (wi.z -> -wi.z), f sees wi itself.
    bool below = false;
    // The declared cones (LobeHints::support, kink_cones), their axes in
    // the frame's hemisphere.
    std::vector<FrameCone> support, kink_cones;
    bool has_peak = false;
    // Points where f is not smooth, in polar coordinates (theta, psi): over
    // the sphere wi = -wo, where the half vector is undefined and f has a
    // direction-dependent limit, and the lobe's point kinks
    // (LobeHints::point_kinks).
    struct Point {
        double theta, psi;
    };
    std::vector<Point> points;
    // A point kink is the centre of the rings itself (theta = 0).
    bool peak_kink = false;
    // Relative error of f from the rounding of the directions (see moments_core).
    double rel_rounding = 0.0;
};

Frame make_frame(const GenericLobe& lobe, double mu_o, LobeDomain domain, const MomentWeight* weights,
                 std::size_t n) {
    Frame fr;
    const double sin_o = std::sqrt((1.0 - mu_o) * (1.0 + mu_o));
    fr.wo = {sin_o, 0.0, mu_o};
    LobeHints h = lobe.hints(fr.wo);
    for (std::size_t k = 0; k < n; ++k)
        for (double a : weight_view_cones(weights[k])) h.kink_cones.push_back({fr.wo, a});
    fr.has_peak = h.has_peak;
    fr.below = domain == LobeDomain::lower_hemisphere;
    if (h.has_peak) {
        fr.p = h.peak;
        if (fr.below) fr.p.z = -fr.p.z;
        fr.w = std::clamp(h.width, 1e-12, 1.0);
        fr.aspect = std::clamp(h.aspect, 1e-12, 1.0);
    } else {
        fr.p = {0.0, 0.0, 1.0};
    }
    const double len = std::sqrt(dot(fr.p, fr.p));
    fr.p = {fr.p.x / len, fr.p.y / len, fr.p.z / len};
    const double ph = std::sqrt(fr.p.x * fr.p.x + fr.p.y * fr.p.y);
    if (ph > 0.0) {
        fr.e1 = {-fr.p.z * fr.p.x / ph, -fr.p.z * fr.p.y / ph, ph};
        fr.e2 = {-fr.p.y / ph, fr.p.x / ph, 0.0};
    } else {
        fr.e1 = {1.0, 0.0, 0.0};
        fr.e2 = {0.0, 1.0, 0.0};
    }
    // wi reaches f as a unit vector in double, each component rounded by up
    // to kDirectionUlp; a lobe of width w and aspect a varies by about that
    // over w a radians, so f carries a relative error of about kDirectionUlp
    // / (w a) that no quadrature removes (it shows at grazing view with
    // alpha below 1e-4, where w a ~ 2 alpha^2). Bounded generously.
    if (fr.has_peak) fr.rel_rounding = 2.0 * kDirectionUlp / (fr.w * fr.aspect);
    fr.hemisphere = domain != LobeDomain::sphere;
    if (fr.hemisphere) {
        fr.theta_a = std::atan2(std::max(fr.p.z, 0.0), ph);
        fr.theta_end = kPi - fr.theta_a;
    } else {
        fr.theta_a = kPi;
        fr.theta_end = kPi;
    }
    auto frame_point = [&](const Vec3& d) {
        const double theta = std::acos(std::clamp(dot(fr.p, d), -1.0, 1.0));
        if (theta <= 1e-12) fr.peak_kink = true;
        else fr.points.push_back({theta, std::abs(std::atan2(dot(fr.e2, d), dot(fr.e1, d)))});
    };
    if (!fr.hemisphere) frame_point({-fr.wo.x, -fr.wo.y, -fr.wo.z});
    for (const Vec3& k : h.point_kinks) {
        const double kl = std::sqrt(dot(k, k));
        frame_point({k.x / kl, k.y / kl, (fr.below ? -k.z : k.z) / kl});
    }
    auto frame_cone = [&](const LobeCone& c) {
        const double dl = std::sqrt(dot(c.axis, c.axis));
        FrameCone k;
        k.d = {c.axis.x / dl, c.axis.y / dl, (fr.below ? -c.axis.z : c.axis.z) / dl};
        k.beta = std::clamp(c.angle, 0.0, kPi);
        k.cos_beta = std::cos(k.beta);
        k.gamma = std::acos(std::clamp(dot(fr.p, k.d), -1.0, 1.0));
        return k;
    };
    for (const LobeCone& c : h.support) {
        fr.support.push_back(frame_cone(c));
        // No ring beyond the polar angle gamma + beta reaches into the cone.
        fr.theta_end = std::min(fr.theta_end, fr.support.back().gamma + fr.support.back().beta);
    }
    for (const LobeCone& c : h.kink_cones) fr.kink_cones.push_back(frame_cone(c));
    return fr;
}

// The psi' integrand at one polar angle: f w_k (cos) dpsi/dpsi', channels of
// the weights given (the rest 0).
struct RingIntegrand {
    const GenericLobe& lobe;
    const Frame& fr;
    const MomentWeight* weights;
    std::size_t n;
    double cos_t, sin_t, rho;
    int* evaluations;

    std::array<double, kMaxWeights> operator()(double psi1) const {
        std::array<double, kMaxWeights> y{};
        const double cs = std::cos(psi1), sn = std::sin(psi1);
        const double q2 = cs * cs + rho * rho * (sn * sn);
        const double q = std::sqrt(q2);
        const double cp = cs / q, sp = rho * sn / q;
        const double jac = rho / q2;
        const double a = sin_t * cp, b = sin_t * sp;
        Vec3 wi{cos_t * fr.p.x + a * fr.e1.x + b * fr.e2.x, cos_t * fr.p.y + a * fr.e1.y + b * fr.e2.y,
                cos_t * fr.p.z + a * fr.e1.z + b * fr.e2.z};
        double v;
        if (fr.hemisphere) {
            const double cos_i = wi.z;  // |cos(theta_i)|: wi is the mirror image below
            if (!(cos_i > 0.0)) return y;
            if (fr.below) wi.z = -cos_i;
            v = lobe.f(fr.wo, wi) * cos_i * jac;
        } else {
            v = lobe.f(fr.wo, wi) * jac;
        }
        ++*evaluations;
        if (v == 0.0) return y;
        const Vec3 h{fr.wo.x + wi.x, fr.wo.y + wi.y, fr.wo.z + wi.z};
        const double hl = std::sqrt(dot(h, h));
        const double c = hl > 0.0 ? std::clamp(dot(fr.wo, h) / hl, 0.0, 1.0) : 0.0;
        for (std::size_t k = 0; k < n; ++k) y[k] = v * weights[k](c);
        return y;
    }
};

// Integral over the ring at polar angle theta (psi in [-psi_max, psi_max],
// as twice [0, psi_max]) to the absolute tolerance budget / weight, or to
// kMaxInnerRelTol of its size if that is tighter, but not below
// kTailFraction of the budget: {moments, error estimate}. cut_scratch has
// room for 2 + 2 fr.points.size() + fr.kink_cones.size() values.
Row ring_integral(const GenericLobe& lobe, const Frame& fr, const MomentWeight* weights, std::size_t n,
                  double theta, double budget, double weight, int max_intervals, int* evaluations,
                  std::vector<double>& cut_scratch) {
    Row out{};
    const double cos_t = std::cos(theta), sin_t = std::sin(theta);
    double end = kPi;  // psi' range [0, end]
    const double rho = std::clamp(fr.aspect * fr.w / std::max(theta, 1e-300), fr.aspect, 1.0);
    if (fr.hemisphere) {
        const double up = sin_t * fr.e1.z, base = cos_t * fr.p.z;  // wi.z = base + up cos(psi)
        if (!(up > 0.0)) {
            if (!(base > 0.0)) return out;
        } else {
            const double c = -base / up;
            if (c >= 1.0) return out;
            if (c > -1.0) {
                const double s = std::sqrt((1.0 - c) * (1.0 + c));
                end = std::atan2(s, rho * c);  // tan(psi') = tan(psi) / rho
            }
        }
    }
    // The ring crosses a cone where wi.d - cos(beta) = base + up cos(psi)
    // changes sign, at most once in [0, pi]: {-1: the ring is outside, 1:
    // inside, 0: inside for psi' below (up > 0) or above (up < 0) the
    // crossing v}.
    struct Crossing {
        int whole;
        double v;
        bool inside_below;
    };
    auto cross = [&](const FrameCone& k) -> Crossing {
        const double up = sin_t * dot(fr.e1, k.d), base = cos_t * dot(fr.p, k.d) - k.cos_beta;
        if (up == 0.0) return {base > 0.0 ? 1 : -1, 0.0, false};
        const double c = -base / up;
        if (up > 0.0 ? c >= 1.0 : c <= -1.0) return {-1, 0.0, false};
        if (up > 0.0 ? c <= -1.0 : c >= 1.0) return {1, 0.0, false};
        const double s = std::sqrt((1.0 - c) * (1.0 + c));
        return {0, std::atan2(s, rho * c), up > 0.0};
    };
    double begin = 0.0;
    for (const FrameCone& k : fr.support) {
        const Crossing x = cross(k);
        if (x.whole < 0) return out;
        if (x.whole == 0) {
            if (x.inside_below) end = std::min(end, x.v);
            else begin = std::max(begin, x.v);
        }
    }
    if (!(begin < end)) return out;
    const RingIntegrand f{lobe, fr, weights, n, cos_t, sin_t, rho, evaluations};
    AdaptiveOptions opt;
    opt.rule = KronrodRule::k21;
    opt.controlled = n;
    opt.max_intervals = max_intervals;
    // psi -> psi' (tan(psi') = tan(psi) / rho, both in [0, pi]).
    auto to_psi1 = [rho](double psi) { return std::atan2(std::sin(psi), rho * std::cos(psi)); };
    // Start from one panel, or, next to a point where f is not smooth (on
    // the sphere wi = -wo, or a point kink of the lobe), from panels that
    // isolate it (the ring passes within |theta - theta_point| of it, where
    // f turns over an arc of about that length). The cuts go in the
    // caller's scratch (room for 2 + two per point + one per kink cone): a
    // ring is integrated millions of times per table, and an allocation per
    // ring is most of the cost in a sanitized build.
    double* const cuts = cut_scratch.data();
    std::size_t ncuts = 0;
    cuts[ncuts++] = begin;
    for (const Frame::Point& pt : fr.points) {
        if (!(sin_t > 0.0)) break;
        const double half = 2.0 * std::abs(theta - pt.theta) / sin_t;
        if (half < 0.25 * kPi)
            for (double psi : {pt.psi - half, pt.psi + half}) {
                const double v = to_psi1(psi);
                if (psi > 0.0 && psi < kPi && v > begin && v < end) cuts[ncuts++] = v;
            }
    }
    for (const FrameCone& k : fr.kink_cones) {
        const Crossing x = cross(k);
        if (x.whole == 0 && x.v > begin && x.v < end) cuts[ncuts++] = x.v;
    }
    std::sort(cuts, cuts + ncuts);
    cuts[ncuts++] = end;
    const double wanted = weight > 0.0 ? budget / weight : HUGE_VAL;
    // The tolerance for a ring whose first panels are `size`; never below
    // what the rounding of f lets the rule resolve.
    auto tolerance = [&](double size) {
        return std::max(std::min(wanted, std::max({kMaxInnerRelTol * size, kTailFraction * wanted, 1e-300})),
                        4.0 * fr.rel_rounding * size);
    };
    Estimate<kMaxWeights> e;
    e.evaluations = 0;
    double size = 0.0;
    if (ncuts == 2) {  // one panel (the common case): no work list unless it is bisected
        const auto first = detail::kronrod_panel<kMaxWeights>(f, cuts[0], cuts[1], n, opt.rule);
        for (std::size_t k = 0; k < n; ++k) size = std::max(size, std::abs(first.value[k]));
        opt.abs_tol = tolerance(size);
        e = detail::adaptive_from_one<kMaxWeights>(f, first, opt, e);
    } else {
        std::vector<detail::Interval<kMaxWeights>> heap = detail::interval_heap<kMaxWeights>(ncuts - 1, opt);
        for (std::size_t i = 0; i + 1 < ncuts; ++i) {
            heap.push_back(detail::kronrod_panel<kMaxWeights>(f, cuts[i], cuts[i + 1], n, opt.rule));
            for (std::size_t k = 0; k < n; ++k) size = std::max(size, std::abs(heap.back().value[k]));
        }
        opt.abs_tol = tolerance(size);
        e = detail::adaptive_from<kMaxWeights>(f, std::move(heap), opt, e);
    }
    for (std::size_t k = 0; k < n; ++k) {
        out[k] = 2.0 * e.value[k];
        out[kMaxWeights] += 2.0 * e.error[k];
    }
    return out;
}

// s in [0, 1] -> [0, 1] with its slope, flat (third order) at the ends marked.
struct EndMap {
    bool flat_left, flat_right;
    std::array<double, 2> operator()(double u) const {
        const double r = 1.0 - u;
        if (flat_left && flat_right)  // 10 u^3 - 15 u^4 + 6 u^5
            return {u * u * u * (10.0 + u * (-15.0 + 6.0 * u)), 30.0 * u * u * r * r};
        if (flat_left) return {u * u * u, 3.0 * u * u};
        if (flat_right) return {1.0 - r * r * r, 3.0 * r * r};
        return {u, 1.0};
    }
};

Estimate<kMaxWeights> moments_pass(const GenericLobe& lobe, const Frame& fr, const MomentWeight* weights,
                                   std::size_t n, const GenericOptions& opt) {
    Estimate<kMaxWeights> out;

    // Break points of theta: the horizon clip, the width, the points and
    // the cones.
    struct Point {
        double theta;
        bool kink;
    };
    std::vector<Point> pts{{0.0, fr.peak_kink}, {fr.theta_end, (fr.hemisphere || !fr.support.empty()) && fr.theta_end < kPi}};
    auto add_point = [&](double t, bool kink) {
        if (t > 0.0 && t < fr.theta_end) pts.push_back({t, kink});
    };
    if (fr.hemisphere) add_point(fr.theta_a, true);
    for (const Frame::Point& pt : fr.points) add_point(pt.theta, true);
    // Where the rings start or stop crossing a cone (they touch it there),
    // and, over a hemisphere, the ring through the points where the cone's
    // edge meets the horizon (w = (cos phi, sin phi, 0) with w.d = cos beta):
    // the part of the rings inside the cone and above the horizon ends there.
    for (const auto* cones : {&fr.support, &fr.kink_cones})
        for (const FrameCone& k : *cones) {
            add_point(std::abs(k.beta - k.gamma), true);
            add_point(k.gamma + k.beta, true);
            add_point(2.0 * kPi - k.beta - k.gamma, true);
            if (fr.hemisphere && std::abs(k.d.x) > 0.0) {
                const double cos_phi = k.cos_beta / k.d.x;
                if (std::abs(cos_phi) <= 1.0) add_point(std::acos(std::clamp(fr.p.x * cos_phi, -1.0, 1.0)), true);
            }
        }
    add_point(fr.w, false);
    add_point(fr.aspect * fr.w, false);
    std::sort(pts.begin(), pts.end(), [](const Point& a, const Point& b) { return a.theta < b.theta; });
    std::vector<Point> merged;
    for (const Point& p : pts) {
        if (!merged.empty() && p.theta <= merged.back().theta * (1.0 + 1e-12)) {
            merged.back().kink = merged.back().kink || p.kink;
            continue;
        }
        merged.push_back(p);
    }
    const std::size_t pieces = merged.size() - 1;
    if (pieces == 0) return out;

    AdaptiveOptions outer_opt;
    outer_opt.abs_tol = 0.5 * opt.abs_tol / static_cast<double>(pieces);
    outer_opt.controlled = n;
    outer_opt.rule = KronrodRule::k21;
    outer_opt.max_intervals = opt.max_intervals;
    const double inner_budget = 0.25 * opt.abs_tol / static_cast<double>(pieces);
    // The rings' cuts, one at a time (see ring_integral).
    std::vector<double> cut_scratch(2 + 2 * fr.points.size() + fr.kink_cones.size());
    int evaluations = 0;

    for (std::size_t i = 0; i < pieces; ++i) {
        const double lo = merged[i].theta, hi = merged[i + 1].theta;
        const EndMap map{merged[i].kink, merged[i + 1].kink};
        // About a peak: the piece from the peak up to the narrow width
        // aspect * w in s = theta^2, every other piece in ln(theta). Between
        // aspect * w and w a ring's integral of an elongated lobe falls as
        // 1 / theta (its arc across the lobe shrinks as the ring grows),
        // smooth in ln(theta) but a singularity s^(-1/2) cut off at
        // (aspect w)^2 in s; and a piece that starts at the horizon clip
        // theta_a changes on the scale of theta_a, which ln(theta) resolves
        // however small it is. About the normal (no peak, w = aspect = 1):
        // every piece below w in s (a sheen's pieces there start at its
        // mirror ring, and take several times longer in ln(theta)). A piece
        // that starts at a point kink at the centre is taken in theta: f
        // goes as theta^q there, which s would make s^(q/2).
        const bool in_theta = lo == 0.0 && fr.peak_kink;
        const bool in_s = !in_theta && (lo == 0.0 || !fr.has_peak) && hi <= fr.aspect * fr.w * (1.0 + 1e-12);
        const double v0 = in_theta ? lo : in_s ? lo * lo : std::log(lo);
        const double v1 = in_theta ? hi : in_s ? hi * hi : std::log(hi);
        const double len = v1 - v0;
        auto integrand = [&](double u) -> std::array<double, kMaxWeights + 1> {
            const std::array<double, 2> m = map(u);
            const double v = v0 + len * m[0];
            double theta, dw;  // dw: solid angle per unit v and unit psi
            if (in_theta) {
                theta = v;
                dw = std::sin(theta);
            } else if (in_s) {
                theta = std::sqrt(v);
                dw = theta > 0.0 ? 0.5 * std::sin(theta) / theta : 0.5;
            } else {
                theta = std::exp(v);
                dw = std::sin(theta) * theta;
            }
            const double weight = dw * len * m[1];
            if (!(weight > 0.0)) return {};
            Row r = ring_integral(lobe, fr, weights, n, theta, inner_budget, weight, opt.max_intervals, &evaluations,
                                  cut_scratch);
            for (double& x : r) x *= weight;
            return r;
        };
        const int panels = in_s || in_theta ? 1 : std::max(1, static_cast<int>(std::ceil(len / kLnPanelWidth)));
        const Estimate<kMaxWeights + 1> e = integrate_adaptive_panels<kMaxWeights + 1>(integrand, 0.0, 1.0, panels,
                                                                                       outer_opt);
        for (std::size_t k = 0; k < n; ++k) {
            out.value[k] += e.value[k];
            out.error[k] += e.error[k] + e.value[kMaxWeights];
        }
    }
    out.evaluations = evaluations;
    return out;
}

Estimate<kMaxWeights> moments_core(const GenericLobe& lobe, double mu_o, const MomentWeight* weights, std::size_t n,
                                   const GenericOptions& opt) {
    if (n == 0) return {};
    mu_o = std::clamp(std::isnan(mu_o) ? 0.0 : mu_o, kGenericGrazingMu, 1.0);
    const Frame fr = make_frame(lobe, mu_o, opt.domain, weights, n);
    Estimate<kMaxWeights> out;
    if (fr.rel_rounding > 0.1 * opt.abs_tol) {
        // The rounding of f may lie above the tolerance: find the moments'
        // size at a loose tolerance, and ask no more than the rounding allows.
        GenericOptions loose = opt;
        loose.abs_tol = std::max(opt.abs_tol, 1e-6);
        out = moments_pass(lobe, fr, weights, n, loose);
        double size = 0.0;
        for (std::size_t k = 0; k < n; ++k) size = std::max(size, std::abs(out.value[k]));
        const double tol = std::max(opt.abs_tol, 2.0 * fr.rel_rounding * size);
        if (tol < loose.abs_tol) {
            GenericOptions tight = opt;
            tight.abs_tol = tol;
            const int spent = out.evaluations;
            out = moments_pass(lobe, fr, weights, n, tight);
            out.evaluations += spent;
        }
    } else {
        out = moments_pass(lobe, fr, weights, n, opt);
    }
    for (std::size_t k = 0; k < n; ++k) out.error[k] += fr.rel_rounding * std::abs(out.value[k]);
    return out;
}

Estimate<kMaxWeights> average_core(const GenericLobe& lobe, const MomentWeight* weights, std::size_t n,
                                   const GenericOptions& opt) {
    Estimate<kMaxWeights> out;
    if (n == 0) return out;
    const LobeHints normal = lobe.hints({0.0, 0.0, 1.0});
    const double b = normal.has_peak ? std::clamp(normal.width, kGenericGrazingMu, 1.0) : 1.0;
    AdaptiveOptions aopt;
    aopt.abs_tol = 0.25 * opt.abs_tol;
    aopt.controlled = n;
    aopt.rule = KronrodRule::k21;
    aopt.max_intervals = opt.max_intervals;
    // Each M(mu) is computed to the accuracy its weight 2 mu jac needs, so
    // that the weighted errors integrate to at most 0.25 abs_tol per range.
    double span = 1.0;
    auto integrand = [&](double mu, double jac) -> std::array<double, kMaxWeights + 1> {
        const double w = 2.0 * mu * jac;
        const double budget = 0.25 * opt.abs_tol / span;
        GenericOptions inner = opt;
        inner.abs_tol = w * kMaxNestedTol > budget ? budget / w : kMaxNestedTol;
        const Estimate<kMaxWeights> m = moments_core(lobe, mu, weights, n, inner);
        out.evaluations += m.evaluations;
        std::array<double, kMaxWeights + 1> r{};
        for (std::size_t k = 0; k < n; ++k) {
            r[k] = w * m.value[k];
            r[kMaxWeights] = std::max(r[kMaxWeights], w * m.error[k]);
        }
        return r;
    };
    auto accumulate = [&](const Estimate<kMaxWeights + 1>& e) {
        for (std::size_t k = 0; k < n; ++k) {
            out.value[k] += e.value[k];
            out.error[k] += e.error[k] + e.value[kMaxWeights];
        }
    };
    // Break points: b, then the lobe's view kinks; each piece gets the share
    // of its range's tolerance that its length is of the range.
    std::vector<double> breaks;
    for (double k : lobe.view_kinks())
        if (k > 0.0 && k < 1.0 && k != b) breaks.push_back(k);
    std::sort(breaks.begin(), breaks.end());
    std::vector<double> low = {0.0}, high;  // u = sqrt(mu / b) on [0, 1]; ln(mu) on [ln b, 0]
    for (double k : breaks) (k < b ? low : high).push_back(k < b ? std::sqrt(k / b) : std::log(k));
    low.push_back(1.0);
    for (std::size_t i = 0; i + 1 < low.size(); ++i) {
        AdaptiveOptions piece = aopt;
        piece.abs_tol = aopt.abs_tol * (low[i + 1] - low[i]);
        accumulate(integrate_adaptive<kMaxWeights + 1>([&](double u) { return integrand(b * u * u, 2.0 * b * u); },
                                                       low[i], low[i + 1], piece));
    }
    if (b < 1.0) {
        span = -std::log(b);
        high.insert(high.begin(), std::log(b));
        high.push_back(0.0);
        for (std::size_t i = 0; i + 1 < high.size(); ++i) {
            const double length = high[i + 1] - high[i];
            AdaptiveOptions piece = aopt;
            piece.abs_tol = aopt.abs_tol * length / span;
            accumulate(integrate_adaptive_panels<kMaxWeights + 1>(
                [&](double v) {
                    const double mu = std::exp(v);
                    return integrand(mu, mu);
                },
                high[i], high[i + 1], static_cast<int>(std::ceil(length / kLnMuPanelWidth)), piece));
        }
    }
    return out;
}

template <std::size_t N>
Estimate<N> first_channels(const Estimate<kMaxWeights>& e) {
    Estimate<N> out;
    for (std::size_t k = 0; k < N; ++k) {
        out.value[k] = e.value[k];
        out.error[k] = e.error[k];
    }
    out.evaluations = e.evaluations;
    return out;
}

// One Monte Carlo draw of f w_k cos / pdf at view cosine mu_o.
void mc_draw(const GenericLobe& lobe, const Vec3& wo, const MomentWeight* weights, std::size_t n, Rng& rng,
             double* y) {
    for (std::size_t k = 0; k < n; ++k) y[k] = 0.0;
    const double u1 = rng.uniform(), u2 = rng.uniform();
    Vec3 wi;
    double pdf;
    if (lobe.has_sampler()) {
        const LobeSample s = lobe.sample(wo, u1, u2);
        wi = s.wi;
        pdf = s.pdf;
    } else {
        const double r = std::sqrt(u1), phi = kTwoPi * u2;
        wi = {r * std::cos(phi), r * std::sin(phi), std::sqrt(1.0 - u1)};
        pdf = wi.z * kInvPi;
    }
    if (!(pdf > 0.0) || !(wi.z > 0.0)) return;
    const double v = lobe.f(wo, wi) * wi.z / pdf;
    const Vec3 h{wo.x + wi.x, wo.y + wi.y, wo.z + wi.z};
    const double hl = std::sqrt(dot(h, h));
    const double c = hl > 0.0 ? std::clamp(dot(wo, h) / hl, 0.0, 1.0) : 0.0;
    for (std::size_t k = 0; k < n; ++k) y[k] = v * weights[k](c);
}

Vec3 view(double mu_o) {
    mu_o = std::clamp(std::isnan(mu_o) ? 0.0 : mu_o, kGenericGrazingMu, 1.0);
    return {std::sqrt((1.0 - mu_o) * (1.0 + mu_o)), 0.0, mu_o};
}

}  // namespace

template <std::size_t N>
Estimate<N> generic_moments(const GenericLobe& lobe, double mu_o, const std::array<MomentWeight, N>& weights,
                            const GenericOptions& opt) {
    static_assert(N >= 1 && N <= kMaxWeights);
    return first_channels<N>(moments_core(lobe, mu_o, weights.data(), N, opt));
}

Estimate<1> generic_albedo(const GenericLobe& lobe, double mu_o, const GenericOptions& opt) {
    return generic_moments<1>(lobe, mu_o, {kWeightOne}, opt);
}

template <std::size_t N>
Estimate<N> generic_moment_average(const GenericLobe& lobe, const std::array<MomentWeight, N>& weights,
                                   const GenericOptions& opt) {
    static_assert(N >= 1 && N <= kMaxWeights);
    return first_channels<N>(average_core(lobe, weights.data(), N, opt));
}

Estimate<1> generic_albedo_average(const GenericLobe& lobe, const GenericOptions& opt) {
    return generic_moment_average<1>(lobe, {kWeightOne}, opt);
}

template <std::size_t N>
Estimate<N> generic_moments_mc(const GenericLobe& lobe, double mu_o, const std::array<MomentWeight, N>& weights,
                               long long samples, std::uint64_t seed) {
    const Vec3 wo = view(mu_o);
    Rng rng(seed, 11);
    MeanAccumulator<static_cast<int>(N)> acc;
    double y[N];
    for (long long s = 0; s < samples; ++s) {
        mc_draw(lobe, wo, weights.data(), N, rng, y);
        acc.add(y);
    }
    return acc.estimate();
}

template <std::size_t N>
Estimate<N> generic_moment_average_mc(const GenericLobe& lobe, const std::array<MomentWeight, N>& weights,
                                      long long samples, std::uint64_t seed) {
    Rng rng(seed, 12);
    MeanAccumulator<static_cast<int>(N)> acc;
    double y[N];
    for (long long s = 0; s < samples; ++s) {
        const double mu = std::sqrt(1.0 - rng.uniform());  // density 2 mu on (0, 1]
        mc_draw(lobe, view(mu), weights.data(), N, rng, y);
        acc.add(y);
    }
    return acc.estimate();
}

#define BRDFLUT_GENERIC_INSTANTIATE(N)                                                                          \
    template Estimate<N> generic_moments<N>(const GenericLobe&, double, const std::array<MomentWeight, N>&,      \
                                            const GenericOptions&);                                             \
    template Estimate<N> generic_moment_average<N>(const GenericLobe&, const std::array<MomentWeight, N>&,      \
                                                   const GenericOptions&);                                      \
    template Estimate<N> generic_moments_mc<N>(const GenericLobe&, double, const std::array<MomentWeight, N>&,   \
                                               long long, std::uint64_t);                                       \
    template Estimate<N> generic_moment_average_mc<N>(const GenericLobe&, const std::array<MomentWeight, N>&,   \
                                                      long long, std::uint64_t);
BRDFLUT_GENERIC_INSTANTIATE(1)
BRDFLUT_GENERIC_INSTANTIATE(2)
BRDFLUT_GENERIC_INSTANTIATE(3)
BRDFLUT_GENERIC_INSTANTIATE(4)
#undef BRDFLUT_GENERIC_INSTANTIATE

}  // namespace brdflut
