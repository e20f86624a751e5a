// Linearly transformed cosines: the distribution, the polygon integral of
// the clamped cosine, and the horizon-clipped sphere form factor.
//
// Heitz, Dupuy, Hill and Neubelt 2016, "Real-Time Polygonal-Light Shading
//   with Linearly Transformed Cosines"
// Snyder 1996, "Area Light Sources for Real-Time Graphics"
#include "brdflut/ltc.h"

#include <cmath>

namespace brdflut {

namespace {
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double length(const Vec3& a) { return std::sqrt(dot(a, a)); }
}  // namespace

Mat3 Mat3::operator*(const Mat3& o) const {
    Mat3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            r.m[i][j] = m[i][0] * o.m[0][j] + m[i][1] * o.m[1][j] + m[i][2] * o.m[2][j];
    return r;
}

double Mat3::det() const {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

Mat3 Mat3::inverse() const {
    const double id = 1.0 / det();
    Mat3 r;
    r.m[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) * id;
    r.m[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * id;
    r.m[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * id;
    r.m[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) * id;
    r.m[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * id;
    r.m[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * id;
    r.m[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) * id;
    r.m[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * id;
    r.m[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * id;
    return r;
}

LtcInverse LtcInverse::from_matrix(const Mat3& inv) {
    const double e = inv.m[1][1];
    return {inv.m[0][0] / e, inv.m[0][2] / e, inv.m[2][0] / e, inv.m[2][2] / e};
}

// D(w) = max(0, w'.z / |w'|) / pi * |det M^-1| / |w'|^3 with w' = M^-1 w,
// for unit w; for any w the density at w/|w| is the same expression times
// |w|^3 / |w| ... written below for the unit direction w / |w|.
double ltc_density(const Mat3& minv, const Vec3& w) {
    const double len = length(w);
    if (!(len > 0.0)) return 0.0;
    const Vec3 u{w.x / len, w.y / len, w.z / len};
    const Vec3 p = minv * u;
    if (p.z <= 0.0) return 0.0;
    const double l2 = dot(p, p);
    return p.z * std::abs(minv.det()) / (kPi * l2 * l2);
}

std::vector<Vec3> clip_to_horizon(const Vec3* v, std::size_t n) {
    std::vector<Vec3> out;
    out.reserve(n + 1);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3& p = v[i];
        const Vec3& q = v[(i + 1) % n];
        if (p.z >= 0.0) out.push_back(p);
        if ((p.z >= 0.0) != (q.z >= 0.0)) {
            // The edge crosses z = 0 at p + t (q - p), t = p.z / (p.z - q.z).
            const double t = p.z / (p.z - q.z);
            out.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y), 0.0});
        }
    }
    return out;
}

// Lambert's edge formula: the irradiance of a uniform spherical polygon is
// (1/2pi) sum_i theta_i (n_i . z), theta_i the arc of edge i and n_i the unit
// normal of the plane through it. atan2(|u x v|, u.v) keeps small arcs exact.
double polygon_clamped_cosine(const Vec3* v, std::size_t n) {
    const std::vector<Vec3> c = clip_to_horizon(v, n);
    if (c.size() < 3) return 0.0;
    double sum = 0.0;
    for (std::size_t i = 0; i < c.size(); ++i) {
        const Vec3& p = c[i];
        const Vec3& q = c[(i + 1) % c.size()];
        const Vec3 x = cross(p, q);
        const double s = length(x);
        if (!(s > 0.0)) continue;  // a repeated vertex: no arc
        sum += std::atan2(s, dot(p, q)) * x.z / s;
    }
    return std::abs(sum) / kTwoPi;
}

double ltc_polygon_integral(const Mat3& minv, const Vec3* v, std::size_t n) {
    std::vector<Vec3> t(n);
    for (std::size_t i = 0; i < n; ++i) t[i] = minv * v[i];
    return polygon_clamped_cosine(t.data(), n);
}

// A cap of radius s centred at polar angle w. Fully above the horizon
// (w <= pi/2 - s) its projected solid angle is pi cos(w) sin^2(s); fully
// below (w >= pi/2 + s) it is 0. Across the horizon Snyder's closed form
// applies, with g = asin(cos(s) / sin(w)):
//   G = pi/2 - g + sin(g) cos(g) - 2 sin(w) cos(s) cos(g)
//   H = cos(w) (cos(g) sqrt(sin^2(s) - cos^2(g)) + sin^2(s) asin(cos(g) / sin(s)))
//   I = pi cos(w) sin^2(s) + G - H  (w < pi/2),   G + H  (w >= pi/2).
double sphere_horizon_form_factor(double z, double len) {
    z = std::clamp(z, -1.0, 1.0);
    len = std::clamp(len, 0.0, 1.0);
    if (len <= 0.0) return std::max(z, 0.0);
    const double sin2_s = len;
    const double sin_s = std::sqrt(sin2_s);
    const double cos_s = std::sqrt(1.0 - sin2_s);
    const double w = std::acos(z);
    const double s = std::asin(sin_s);
    const double half_pi = 0.5 * kPi;
    double I;
    if (w <= half_pi - s) {
        I = kPi * z * sin2_s;
    } else if (w >= half_pi + s) {
        I = 0.0;
    } else {
        const double sin_w = std::sin(w);
        const double g = std::asin(std::clamp(cos_s / sin_w, -1.0, 1.0));
        const double cos_g = std::cos(g), sin_g = std::sin(g);
        const double G = half_pi - g + sin_g * cos_g - 2.0 * sin_w * cos_s * cos_g;
        const double H = z * (cos_g * safe_sqrt(sin2_s - cos_g * cos_g) +
                              sin2_s * std::asin(std::clamp(cos_g / sin_s, -1.0, 1.0)));
        I = w < half_pi ? kPi * z * sin2_s + G - H : G + H;
    }
    return std::max(I, 0.0) / (kPi * len);
}

}  // namespace brdflut
