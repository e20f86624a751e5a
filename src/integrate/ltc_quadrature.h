// The quadrature that the LTC fit (src/integrate/ltc_fit.cpp) and its error
// reports (src/integrate/ltc_report.cpp) share: the grid over the sphere in
// coordinates about the lobe, the lobe's peak and widths, a texel's setup
// and initial guess, the relative L3 error and the mass below the horizon
// of an LTC, the exact light of a polygon, and the square lights the two
// light banks are made of. Internal to the library.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "brdflut/ltc.h"
#include "brdflut/ltc_fit.h"
#include "brdflut/math.h"

namespace brdflut::ltc_detail {

inline Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Vec3 normalize(const Vec3& a) {
    const double l = std::sqrt(dot(a, a));
    return {a.x / l, a.y / l, a.z / l};
}
inline Vec3 add(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 scale(const Vec3& a, double s) { return {a.x * s, a.y * s, a.z * s}; }

inline double clamp_mu(double mu) { return std::clamp(mu, kLtcMinMu, 1.0); }

// Quadrature nodes on the sphere with the target's values.
struct SphereGrid {
    std::vector<double> x, y, z, w, p;
    double p3 = 0.0;  // int p^3
    double p2 = 0.0;
    double mass_weight = 0.0;  // of the triangular discrimination in the objective (ltc_mass_weight)

    std::size_t size() const { return x.size(); }
};

// Coordinates about the lobe: the stereographic projection from the
// antipode of `axis` (unit, in the x-z plane, above the horizon), scaled by
// the lobe's widths: (X, Y) = (w1 rho cos(phi), w2 rho sin(phi)) along t1 =
// (axis.z, 0, -axis.x) and y, R^2 = X^2 + Y^2 = tan^2(beta/2) with beta the
// angle from the axis, rho = u / (1 - u), u in [0, 1). Each ray phi is a
// meridian from the axis to its antipode; the measure is
// dw = 4 w1 w2 rho / (1 + R^2)^2 drho dphi.
struct LobeFrame {
    Vec3 axis{0, 0, 1};
    double w1 = 1.0, w2 = 1.0;

    Vec3 t1() const { return {axis.z, 0.0, -axis.x}; }
    // tan(beta/2) = k(phi) rho on the ray phi.
    double k(double phi) const { return std::hypot(w1 * std::cos(phi), w2 * std::sin(phi)); }
    // The ray's direction in the tangent plane (unit), t1 cos(phi') + y sin(phi').
    Vec3 tangent(double phi) const {
        const double c = w1 * std::cos(phi), sn = w2 * std::sin(phi), l = std::hypot(c, sn);
        const Vec3 a = t1();
        return {c / l * a.x, sn / l, c / l * a.z};
    }
    // The stereographic angle phi of a direction's azimuth phi' about the axis.
    double phi_of_azimuth(double phi_p) const { return std::atan2(std::sin(phi_p) / w2, std::cos(phi_p) / w1); }
    Vec3 direction(double beta, const Vec3& t) const {
        const double sb = std::sin(beta), cb = std::cos(beta);
        return {sb * t.x + cb * axis.x, sb * t.y, sb * t.z + cb * axis.z};
    }
    // The direction at u on the ray of tangent t (unit) and k = kk, from
    // s = tan(beta/2) = kk rho without trigonometry: cos(beta) = (1 - s^2) /
    // (1 + s^2), sin(beta) = 2 s / (1 + s^2) (in 1/s beyond s = 1).
    Vec3 direction_at(double u, double kk, const Vec3& t) const {
        const double s = kk * rho_of_u(u);
        double cb, sb;
        if (s <= 1.0) {
            const double s2 = s * s;
            cb = (1.0 - s2) / (1.0 + s2);
            sb = 2.0 * s / (1.0 + s2);
        } else {
            const double r = 1.0 / s, r2 = r * r;
            cb = (r2 - 1.0) / (r2 + 1.0);
            sb = 2.0 * r / (r2 + 1.0);
        }
        return {sb * t.x + cb * axis.x, sb * t.y, sb * t.z + cb * axis.z};
    }
    static double rho_of_u(double u) { return u / (1.0 - u); }
    static double u_of_rho(double rho) { return std::isinf(rho) ? 1.0 : rho / (1.0 + rho); }
    // beta on ray phi (through k) of u, and the measure dw / (du dphi).
    double beta_of_u(double u, double kk) const { return 2.0 * std::atan(kk * rho_of_u(u)); }
    double measure(double u, double kk) const {
        const double rho = rho_of_u(u), R2 = kk * kk * rho * rho;
        return 4.0 * w1 * w2 * rho / ((1.0 + R2) * (1.0 + R2)) / ((1.0 - u) * (1.0 - u));
    }
    double u_of_beta(double beta, double kk) const {
        if (beta >= kPi) return 1.0;
        return u_of_rho(std::tan(0.5 * beta) / kk);
    }
};

// The objective sums its grid in this many interleaved lanes (objective()).
inline constexpr std::size_t kObjectiveLanes = 4;

// Nodes over the whole sphere: on each ray phi (midpoint rule on [0, pi],
// doubled: the lobe is even in y) Gauss-Legendre in u on [0, u_h] above the
// horizon and on [u_h, 1] below it, so that the lobe's cut at the horizon
// is a panel end, not inside a panel.
SphereGrid make_grid(const LtcLobe& lobe, double n0, const LobeFrame& f, int radial, int azimuth);

// The quadrature of one texel and its initial guess.
struct Setup {
    SphereGrid grid;
    LobeFrame frame;
    // The light term of the objective (fit_objective): its weight, the fit
    // bank and the lobe's mass in each of its lights (exact light / n0).
    double light_weight = 0.0;
    std::vector<LtcLight> lights;
    std::vector<double> light_mass;
    std::array<double, 4> x0{};  // initial parameters
    std::array<double, 4> step{};  // initial simplex steps
};

// The lobe's peak and widths. An isotropic lobe peaks in the plane of
// incidence: p is scanned there at offsets from the mirror direction
// spaced evenly in log(offset) from 1e-12 to 1 radian on both sides, and
// the best bracket refined by golden section. (The peak, not the average
// direction: at grazing view a narrow lobe has a long tail toward the
// normal that moves its average far from its peak.) The widths are the
// angles from the peak at which p falls to half its peak, in the plane of
// incidence (the mean of both sides) and across it, found by bisection in
// log(angle).
struct LobeShape {
    LobeFrame frame;
    double theta = 0.0;       // the peak's signed angle from the normal (+x positive)
    double half_in = 1.0;     // half-maximum angle in the plane of incidence
    double half_across = 1.0; // ... across it
};
LobeShape lobe_shape(const LtcLobe& lobe, double n0);

// The grid, frame and initial guess of a texel: what the fit and the error
// figures share (make_fit_setup adds the fit's light term).
Setup make_setup(const LtcLobe& lobe, double n0, int radial, int azimuth);

// D of the LTC at grid node i (minv with middle element 1).
inline double grid_density(const SphereGrid& g, std::size_t i, const Mat3& minv, double det_over_pi) {
    const auto& m = minv.m;
    const double x = g.x[i], y = g.y[i], z = g.z[i];
    const double px = m[0][0] * x + m[0][2] * z;
    const double pz = m[2][0] * x + m[2][2] * z;
    const double l2 = px * px + y * y + pz * pz;
    return pz > 0.0 ? pz * det_over_pi / (l2 * l2) : 0.0;
}

// (int |p - D|^3 dw / int p^3 dw)^(1/3).
double relative_l3(const SphereGrid& g, const Mat3& minv);

// The LTC's mass below the horizon: the hemisphere z > 0 maps under M^-1 to
// the half space whose normal is row 2 of M, and the clamped cosine's
// integral over a hemisphere whose axis has cosine c with the normal is
// (1 + c) / 2.
double below_horizon_of(const LtcInverse& minv);

// The exact light of one convex polygon: in the lobe's polar coordinates,
// each ray phi crosses the polygon's cone (and the upper hemisphere) in
// one interval of beta, integrated in u by adaptive Gauss-Kronrod; phi by
// adaptive Gauss-Kronrod over one turn (half a turn, doubled, for a polygon
// that is its own mirror image in the plane of incidence), from panels
// between the vertices' azimuths and those of the lobe's point kinks
// (LtcLobe::point_kinks). A
// ray that one panel does not resolve is cut where it passes closest to a
// point kink, and a ray that the horizon ends is integrated in
// w, u = u1 - (u1 - u0)(1 - w)^2, flat at the horizon, where a shadowing
// term that goes as a power of cos(theta_i) is not smooth.
double polygon_light(const LtcLobe& lobe, const LobeFrame& f, const LtcLight& light, double abs_tol);

// ---- The lights of the banks (ltc_fit_light_bank, ltc_light_bank) ----

// A square light of angular half-size sigma centred on direction c, its
// edges along e1, e2 (c, e1, e2 orthonormal), counter-clockwise seen from
// the origin.
LtcLight square(const char* name, const Vec3& c_in, double sigma_deg);
Vec3 rotate_y(const Vec3& v, double deg);  // toward +x for positive angles
Vec3 from_angles(double elevation_deg, double phi_deg);

}  // namespace brdflut::ltc_detail
