// Linearly transformed cosines (LTC) for polygonal area lights.
//
// Heitz, Dupuy, Hill and Neubelt 2016, "Real-Time Polygonal-Light Shading
//   with Linearly Transformed Cosines"
// Snyder 1996, "Area Light Sources for Real-Time Graphics" (the projected
//   solid angle of a spherical cap clipped by the horizon)
//
// Conventions: the shading frame has the normal along +z and the view
// direction in the x-z plane at +x, wo = (sin theta_o, 0, cos theta_o), so
// the mirror direction is at -x. Matrices act on column vectors and are
// written by rows: m[row][col].
//
// An LTC is the clamped cosine D_o(w) = max(0, w.z) / pi carried by a 3x3
// matrix M to the distribution
//
//   D(w) = D_o(w_o) |det M^-1| / |M^-1 w|^3,   w_o = M^-1 w / |M^-1 w|,
//
// a density per steradian over the whole sphere (it integrates to 1; the
// part below the horizon z < 0 is mass the BRDF does not have). The
// integral of D over a polygon P is the clamped cosine's integral over
// M^-1 P, which has a closed form (polygon_clamped_cosine).
//
// The fitter (brdflut/ltc_fit.h, src/integrate/ltc_fit.cpp) takes any lobe
// LtcLobe describes: GGX, the Charlie sheen and the EON rough diffuse lobe;
// the error figures of an LTC against its lobe are in brdflut/ltc_report.h.
//
// An isotropic BRDF lobe in this frame is symmetric in y, so M^-1 has the
// form [[a, 0, b], [0, e, 0], [c, 0, d]] and D does not change when M^-1 is
// scaled: engines store it divided by one of its elements (LtcInverse).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "brdflut/math.h"

namespace brdflut {

// A 3x3 matrix by rows.
struct Mat3 {
    std::array<std::array<double, 3>, 3> m{};

    static Mat3 identity() { return Mat3{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}}; }
    Vec3 operator*(const Vec3& v) const {
        return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
                m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
    }
    Mat3 operator*(const Mat3& o) const;
    double det() const;
    Mat3 inverse() const;  // undefined for a singular matrix
};

// The inverse matrix of an isotropic LTC normalized by its middle element:
// M^-1 = [[a, 0, b], [0, 1, 0], [c, 0, d]] (by rows). In glm's m[col][row],
// which Heitz's tables and three.js use, (a, c, b, d) = (m[0][0], m[0][2],
// m[2][0], m[2][2]).
struct LtcInverse {
    double a = 1.0, b = 0.0, c = 0.0, d = 1.0;

    Mat3 matrix() const { return Mat3{{{{a, 0, b}, {0, 1, 0}, {c, 0, d}}}}; }
    // From any y-symmetric M^-1 (divided by its middle element).
    static LtcInverse from_matrix(const Mat3& inv);
};

// D(w) of the LTC with inverse matrix minv, for any direction w (not
// necessarily unit): per steradian, integrating to 1 over the sphere.
double ltc_density(const Mat3& minv, const Vec3& w);

// (1/pi) * integral over the spherical polygon P of max(0, w.z) dw: the
// form factor of a polygon (vertices are directions from the shading point,
// any length, convex or not, either winding), clipped to the horizon z >= 0
// by the edge formula (1/2pi) sum_i angle(v_i, v_i+1) n_i.z. n >= 3.
double polygon_clamped_cosine(const Vec3* v, std::size_t n);

// The integral of the LTC's D over the polygon P: polygon_clamped_cosine of
// M^-1 P, as a shader computes it (the light is clipped in the cosine's
// frame, so LTC mass below the surface horizon does receive light).
double ltc_polygon_integral(const Mat3& minv, const Vec3* v, std::size_t n);

// Clips a polygon (directions from the origin) to the half space z >= 0.
std::vector<Vec3> clip_to_horizon(const Vec3* v, std::size_t n);

// The projected solid angle of a spherical cap of angular radius sigma whose
// centre is at cos(elevation from the normal) z, clipped to the horizon,
// divided by pi sin^2(sigma): the fourth channel of Heitz's ltc_2, with
// len = sin^2(sigma) (the length of the average vector of a sphere light).
// z in [-1, 1], len in [0, 1]; at len = 0 it is max(z, 0).
double sphere_horizon_form_factor(double z, double len);

}  // namespace brdflut
