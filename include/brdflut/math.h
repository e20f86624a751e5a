// Small numeric helpers shared by every model. All computation is in double.
#pragma once

#include <algorithm>
#include <cmath>

namespace brdflut {

inline constexpr double kPi = 3.14159265358979323846264338327950288;
inline constexpr double kInvPi = 1.0 / kPi;
inline constexpr double kTwoPi = 2.0 * kPi;

constexpr double sqr(double x) { return x * x; }

// sqrt that treats tiny negative arguments (rounding noise) as zero.
inline double safe_sqrt(double x) { return std::sqrt(std::max(0.0, x)); }

inline double clamp01(double x) { return std::clamp(x, 0.0, 1.0); }

// (1 - x)^5, the Schlick weight, computed without pow().
constexpr double schlick_weight(double cos_theta) {
    const double m = 1.0 - cos_theta;
    const double m2 = m * m;
    return m2 * m2 * m;
}

// Shading frame: the surface normal is +z; mu = cos(theta) = z.
struct Vec3 {
    double x = 0, y = 0, z = 0;
};
constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// Direction in the x-z plane at cos(theta) = mu (phi = 0), the convention
// used for the outgoing direction of every isotropic table.
inline Vec3 direction_from_mu(double mu) { return {safe_sqrt(1.0 - mu * mu), 0.0, mu}; }

// The exact sRGB EOTF (IEC 61966-2-1), the decoding a GPU applies to an
// *_SRGB texture, and its inverse, for v in [0, 1] (extended as odd
// functions beyond).
inline double srgb_eotf(double encoded) {
    const double a = std::abs(encoded);
    const double v = a <= 0.04045 ? a / 12.92 : std::pow((a + 0.055) / 1.055, 2.4);
    return std::copysign(v, encoded);
}
inline double srgb_inverse_eotf(double linear) {
    const double a = std::abs(linear);
    const double v = a <= 0.0031308 ? 12.92 * a : 1.055 * std::pow(a, 1.0 / 2.4) - 0.055;
    return std::copysign(v, linear);
}

}  // namespace brdflut
