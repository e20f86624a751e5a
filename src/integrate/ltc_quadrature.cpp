// The quadrature of the LTC fit and of its error reports
// (integrate/ltc_quadrature.h): the grid about the lobe, the lobe's peak and
// widths, a texel's initial guess, and the exact light of a polygon.
#include "integrate/ltc_quadrature.h"

#include "brdflut/quadrature.h"

namespace brdflut::ltc_detail {

SphereGrid make_grid(const LtcLobe& lobe, double n0, const LobeFrame& f, int radial, int azimuth) {
    const int below = std::max(6, radial / 3);
    const GaussLegendre& up = gauss_legendre(radial);
    const GaussLegendre& low = gauss_legendre(below);
    SphereGrid g;
    const std::size_t n = static_cast<std::size_t>(radial + below) * static_cast<std::size_t>(azimuth);
    g.x.reserve(n);
    g.y.reserve(n);
    g.z.reserve(n);
    g.w.reserve(n);
    g.p.reserve(n);
    const double dphi = kPi / azimuth;
    for (int k = 0; k < azimuth; ++k) {
        const double phi = (k + 0.5) * dphi;
        const double kk = f.k(phi);
        const Vec3 t = f.tangent(phi);
        // d.z = cos(beta) axis.z + sin(beta) t.z = 0 (axis.z > 0).
        const double beta_h = std::atan2(f.axis.z, -t.z);
        const double u_h = f.u_of_beta(beta_h, kk);
        auto add_panel = [&](const GaussLegendre& rule, double u0, double u1, bool upper) {
            const double c = 0.5 * (u0 + u1), h = 0.5 * (u1 - u0);
            for (std::size_t j = 0; j < rule.x.size(); ++j) {
                const double u = c + h * rule.x[j];
                const double wt = h * rule.w[j] * f.measure(u, kk) * 2.0 * dphi;
                const Vec3 d = f.direction(f.beta_of_u(u, kk), t);
                const double pv = upper ? lobe(d) / n0 : 0.0;
                g.x.push_back(d.x);
                g.y.push_back(d.y);
                g.z.push_back(d.z);
                g.w.push_back(wt);
                g.p.push_back(pv);
                g.p3 += wt * pv * pv * pv;
                g.p2 += wt * pv * pv;
            }
        };
        add_panel(up, 0.0, u_h, true);
        add_panel(low, u_h, 1.0, false);
    }
    // Padded to whole groups of the objective's lanes with copies of the
    // last node of weight 0 and p = 0: they add exactly +0 to every sum
    // wherever that node's D is finite.
    while (g.x.size() % kObjectiveLanes != 0) {
        g.x.push_back(g.x.back());
        g.y.push_back(g.y.back());
        g.z.push_back(g.z.back());
        g.w.push_back(0.0);
        g.p.push_back(0.0);
    }
    return g;
}

LobeShape lobe_shape(const LtcLobe& lobe, double n0) {
    const double theta_m = -std::acos(lobe.mu_o);  // mirror direction, at -x
    auto at = [&](double theta) { return lobe(Vec3{std::sin(theta), 0.0, std::cos(theta)}) / n0; };
    const double lo_theta = -0.5 * kPi, hi_theta = 0.5 * kPi;
    std::vector<double> cand{theta_m};
    for (int k = 0; k <= 120; ++k) {
        const double off = std::pow(10.0, -12.0 + 0.1 * k);
        for (double t : {theta_m - off, theta_m + off})
            if (t > lo_theta && t < hi_theta) cand.push_back(t);
    }
    // A lobe that may peak anywhere (retro-reflection, a sheen ring about
    // the normal): the whole plane of incidence, every degree, too.
    if (!lobe.peaks_near_mirror())
        for (int k = 1; k < 180; ++k) cand.push_back(lo_theta + k * kPi / 180.0);
    std::sort(cand.begin(), cand.end());
    std::size_t best = 0;
    double pbest = -1.0;
    for (std::size_t i = 0; i < cand.size(); ++i) {
        const double v = at(cand[i]);
        if (v > pbest) {
            pbest = v;
            best = i;
        }
    }
    double a = best > 0 ? cand[best - 1] : lo_theta;
    double b = best + 1 < cand.size() ? cand[best + 1] : hi_theta;
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double x1 = b - g * (b - a), x2 = a + g * (b - a);
    double f1 = at(x1), f2 = at(x2);
    for (int it = 0; it < 100 && b - a > 1e-16; ++it) {
        if (f1 > f2) {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - g * (b - a);
            f1 = at(x1);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + g * (b - a);
            f2 = at(x2);
        }
    }
    double theta = f1 > f2 ? x1 : x2;
    double pmax = std::max(f1, f2);
    if (pbest > pmax) {
        theta = cand[best];
        pmax = pbest;
    }
    // Keep the axis above the horizon (the grid splits its rays there).
    theta = std::clamp(theta, -0.5 * kPi + 1e-12, 0.5 * kPi - 1e-12);
    LobeShape out;
    out.theta = theta;
    const Vec3 axis{std::sin(theta), 0.0, std::cos(theta)};
    const Vec3 t1{axis.z, 0.0, -axis.x};
    auto half_angle = [&](const Vec3& dir) {
        double lo = -14.0, hi = std::log10(kPi);
        auto p_at = [&](double l) {
            const double d = std::pow(10.0, l);
            const Vec3 w{std::cos(d) * axis.x + std::sin(d) * dir.x, std::sin(d) * dir.y,
                         std::cos(d) * axis.z + std::sin(d) * dir.z};
            return lobe(w) / n0;
        };
        if (p_at(hi) > 0.5 * pmax) return std::pow(10.0, hi);
        if (p_at(lo) < 0.5 * pmax) return std::pow(10.0, lo);
        for (int it = 0; it < 60; ++it) {
            const double m = 0.5 * (lo + hi);
            (p_at(m) > 0.5 * pmax ? lo : hi) = m;
        }
        return std::pow(10.0, 0.5 * (lo + hi));
    };
    out.half_in = 0.5 * (half_angle(t1) + half_angle(Vec3{-t1.x, 0.0, -t1.z}));
    out.half_across = half_angle(Vec3{0.0, 1.0, 0.0});
    if (!lobe.peaks_near_mirror()) {
        // A wide lobe, or a ring about the normal (sheen at normal view):
        // coordinates about the normal, the horizon at rho = 1, so that the
        // quadrature is even in x where the lobe is (at normal view) and
        // covers all sides of a ring alike.
        out.frame.axis = Vec3{0.0, 0.0, 1.0};
        out.frame.w1 = out.frame.w2 = 1.0;
        return out;
    }
    out.frame.axis = axis;
    // R = tan(beta/2) = beta/2 at the half-maximum angle when rho = 1.
    out.frame.w1 = std::clamp(0.5 * out.half_in, 1e-14, 1.0);
    out.frame.w2 = std::clamp(0.5 * out.half_across, 1e-14, 1.0);
    return out;
}

namespace {
// A cosine scaled by s along one axis falls to half its peak at the angle
// atan(s sqrt(sqrt(2) - 1)) from its axis.
constexpr double kHalfMaxScale = 0.6435942529055827;  // sqrt(sqrt(2) - 1)

// The scale s of the cosine M = diag(s, s, 1) whose density falls to half
// its peak at the angle atan(t) from its axis: D(t) / D(0) = (1 + t^2)^(3/2)
// / (1 + t^2 / s^2)^2 = 1/2. (For small t, s = t / kHalfMaxScale.)
double cosine_scale_of_half_max(double t) {
    return t / std::sqrt(std::sqrt(2.0) * std::pow(1.0 + t * t, 0.75) - 1.0);
}

// The initial scales from the lobe's half-maximum widths. GGX lobes are
// narrow where the fit is hard, and their guess takes the narrow cosine's
// t / kHalfMaxScale; the wide lobes (diffuse, sheen) the exact scale, so
// that a lobe that is a cosine (EON at sigma = 0) starts at its own LTC.
double initial_scale(const LtcLobe& lobe, double half_angle) {
    const double t = std::tan(std::min(half_angle, 1.5));
    return std::clamp(lobe.peaks_near_mirror() ? t / kHalfMaxScale : cosine_scale_of_half_max(t), 1e-14, 4.0);
}
}  // namespace

Setup make_setup(const LtcLobe& lobe, double n0, int radial, int azimuth) {
    Setup s;
    const LobeShape shape = lobe_shape(lobe, n0);
    s.frame = shape.frame;
    const double m11 = initial_scale(lobe, shape.half_in);
    const double m22 = initial_scale(lobe, shape.half_across);
    s.x0 = {shape.theta, std::log(m11), std::log(m22), 0.0};
    s.step = {0.5 * std::min(m11, 0.5), 0.3, 0.3, 0.3};
    // In the frame about the normal a narrow sheen lobe lies in a band at
    // the horizon end of each ray: half as many radial nodes again resolve
    // it (with the GGX count the fitted sheen coefficients zigzag between
    // neighbouring texels at roughness 0.1 to 0.2 by up to 10 %).
    if (!lobe.peaks_near_mirror()) radial += radial / 2;
    s.grid = make_grid(lobe, n0, s.frame, radial, azimuth);
    s.grid.mass_weight = ltc_mass_weight(lobe);
    return s;
}

double relative_l3(const SphereGrid& g, const Mat3& minv) {
    const double det = std::abs(minv.det()) / kPi;
    double sum = 0.0;
    for (std::size_t i = 0; i < g.size(); ++i) {
        const double e = std::abs(g.p[i] - grid_density(g, i, minv, det));
        sum += g.w[i] * e * e * e;
    }
    return std::cbrt(sum / g.p3);
}

double below_horizon_of(const LtcInverse& minv) {
    const Mat3 m = minv.matrix().inverse();
    const Vec3 n = normalize(Vec3{m.m[2][0], m.m[2][1], m.m[2][2]});
    return 0.5 * (1.0 - n.z);
}

LtcLight square(const char* name, const Vec3& c_in, double sigma_deg) {
    const Vec3 c = normalize(c_in);
    const Vec3 up = std::abs(c.z) < 0.999 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
    const Vec3 e2 = normalize(cross(up, c));
    const Vec3 e1 = cross(e2, c);
    const double t = std::tan(sigma_deg * kPi / 180.0);
    LtcLight l{name, {}};
    const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    for (int i = 0; i < 4; ++i)
        l.vertices[static_cast<std::size_t>(i)] =
            normalize(add(c, add(scale(e1, t * sx[i]), scale(e2, t * sy[i]))));
    return l;
}
Vec3 rotate_y(const Vec3& v, double deg) {  // toward +x for positive angles
    const double a = deg * kPi / 180.0, c = std::cos(a), s = std::sin(a);
    return {c * v.x + s * v.z, v.y, -s * v.x + c * v.z};
}
Vec3 from_angles(double elevation_deg, double phi_deg) {
    const double e = elevation_deg * kPi / 180.0, p = phi_deg * kPi / 180.0;
    return {std::cos(e) * std::cos(p), std::cos(e) * std::sin(p), std::sin(e)};
}

namespace {
// The interval of beta in [0, pi] where e . d(beta) >= 0 for d(beta) =
// cos(beta) a + sin(beta) t: A cos(beta) + B sin(beta) = R cos(beta - b0)
// >= 0 on [b0 - pi/2, b0 + pi/2] (mod 2 pi), which meets [0, pi] in one
// interval.
void clip_interval(double A, double B, double& lo, double& hi) {
    if (A == 0.0 && B == 0.0) return;
    const double b0 = std::atan2(B, A);
    const double half = 0.5 * kPi;
    double l, h;
    if (b0 >= -half) {
        l = std::max(0.0, b0 - half);
        h = std::min(kPi, b0 + half);
    } else {
        l = b0 + 3.0 * half;
        h = kPi;
    }
    lo = std::max(lo, l);
    hi = std::min(hi, h);
}
}  // namespace

double polygon_light(const LtcLobe& lobe, const LobeFrame& f, const LtcLight& light, double abs_tol) {
    const std::size_t n = light.vertices.size();
    std::vector<Vec3> e;  // inward normals of the edge planes, and the horizon
    Vec3 centroid{};
    for (const Vec3& v : light.vertices) centroid = add(centroid, v);
    for (std::size_t i = 0; i < n; ++i) {
        Vec3 c = cross(light.vertices[i], light.vertices[(i + 1) % n]);
        if (dot(c, centroid) < 0.0) c = scale(c, -1.0);
        e.push_back(c);
    }
    e.push_back(Vec3{0, 0, 1});
    const Vec3 t1 = f.t1();
    const Vec3 y{0, 1, 0};
    std::vector<double> breaks;
    auto add_break = [&](const Vec3& v) {
        double phi = f.phi_of_azimuth(std::atan2(dot(v, y), dot(v, t1)));
        if (phi < 0.0) phi += kTwoPi;
        breaks.push_back(phi);
    };
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3& a = light.vertices[i];
        const Vec3& b = light.vertices[(i + 1) % n];
        add_break(a);
        // Where an edge crosses the horizon the ray's interval changes from
        // one bound to another: a kink in phi, made a panel end. (The chord's
        // point at z = 0 projects radially onto the arc.)
        if ((a.z > 0.0) != (b.z > 0.0)) {
            const double t = a.z / (a.z - b.z);
            add_break(add(a, scale(add(b, scale(a, -1.0)), t)));
        }
    }
    // The lobe's point singularities off the frame's axis (where every ray
    // starts): the ray through each is a break of phi, and every ray is cut
    // where it passes closest to each.
    std::vector<Vec3> kinks;
    for (const Vec3& v : lobe.point_kinks())
        if (v.z > 0.0 && dot(v, f.axis) < 1.0 - 1e-12) {
            kinks.push_back(v);
            add_break(v);
        }
    // The lobe is symmetric about the plane of incidence (an isotropic BRDF
    // with wo in the x-z plane; the LTC's form assumes it too), and so is
    // the frame: the ray at -phi is the mirror image of the ray at phi. A
    // polygon that is its own mirror image (a light centred in the plane)
    // then has twice the light of its half phi in [0, pi]. Otherwise the
    // azimuth runs once round from the first break (every polygon has
    // vertices, so there is one). The panels between breaks are adapted as
    // one integral with one error budget.
    bool mirrored = true;
    for (const Vec3& v : light.vertices) {
        bool found = false;
        for (const Vec3& w : light.vertices)
            found = found || (std::abs(w.x - v.x) <= 1e-12 && std::abs(w.y + v.y) <= 1e-12 && std::abs(w.z - v.z) <= 1e-12);
        mirrored = mirrored && found;
    }
    if (mirrored) {
        breaks.erase(std::remove_if(breaks.begin(), breaks.end(), [](double b) { return !(b > 0.0 && b < kPi); }),
                     breaks.end());
        breaks.push_back(0.0);
        breaks.push_back(kPi);
    }
    std::sort(breaks.begin(), breaks.end());
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
    if (!mirrored) breaks.push_back(breaks.front() + kTwoPi);
    const double copies = mirrored ? 2.0 : 1.0;
    AdaptiveOptions outer;
    outer.abs_tol = 0.5 * abs_tol / copies;
    outer.max_intervals = 400;
    AdaptiveOptions inner;
    inner.abs_tol = 0.5 * abs_tol / kTwoPi;
    inner.max_intervals = 100;
    std::vector<double> cuts;
    auto ray = [&](double phi) {
        const Vec3 t = f.tangent(phi);
        const double kk = f.k(phi);
        double lo = 0.0, hi = kPi;
        for (std::size_t i = 0; i + 1 < e.size(); ++i) clip_interval(dot(e[i], f.axis), dot(e[i], t), lo, hi);
        const double hi_in_light = hi;
        clip_interval(dot(e.back(), f.axis), dot(e.back(), t), lo, hi);
        if (!(hi > lo)) return std::array<double, 1>{0.0};
        // Where the horizon ends the ray, the lobe's shadowing often goes
        // as a fractional power of cos(theta_i) there (the Estevez-Kulla
        // Lambda's x^c): the ray is integrated in w with u = u1 - (u1 -
        // u0)(1 - w)^2, which turns (u1 - u)^c into (1 - w)^(2c + 1).
        const bool at_horizon = hi < hi_in_light;
        const double ua = f.u_of_beta(lo, kk), len = f.u_of_beta(hi, kk) - ua;
        auto g = [&](double w) {
            const double r = 1.0 - w;
            const double x = at_horizon ? 1.0 - r * r : w, jac = at_horizon ? 2.0 * r : 1.0;
            const double u = ua + len * x;
            return std::array<double, 1>{lobe(f.direction_at(u, kk, t)) * f.measure(u, kk) * len * jac};
        };
        cuts.assign({0.0, 1.0});
        for (const Vec3& v : kinks) {
            const double at = std::atan2(dot(v, t), dot(v, f.axis));
            if (at > lo && at < hi) {
                const double x = (f.u_of_beta(at, kk) - ua) / len;
                cuts.push_back(at_horizon ? 1.0 - std::sqrt(std::max(0.0, 1.0 - x)) : x);
            }
        }
        std::sort(cuts.begin(), cuts.end());
        // A ray far from a kink (or short) is smooth: one panel that meets
        // the tolerance is kept; otherwise the ray starts again cut at them.
        if (cuts.size() > 2) {
            const detail::Interval<1> whole = detail::kronrod_panel<1>(g, 0.0, 1.0, 1);
            if (whole.error[0] <= inner.abs_tol) return whole.value;
        }
        return integrate_adaptive_breaks<1>(g, cuts.data(), cuts.size(), inner).value;
    };
    return copies * integrate_adaptive_breaks<1>(ray, breaks.data(), breaks.size(), outer).value[0];
}

}  // namespace brdflut::ltc_detail
