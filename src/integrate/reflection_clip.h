// Where the mirror reflection of wo about a half vector stays above the
// horizon. wo is at cos(theta_o) = mu_o, sin(theta_o) = sin_o, phi_o = 0; the
// half vector at t = tan(theta_h) and azimuth phi. The reflected direction has
// mu_i > 0 exactly when cos(phi) > c(t) = -mu_o (1 - t^2) / (2 t sin_o):
//   t <= t_a = mu_o / (1 + sin_o)         every phi    (full circle)
//   t_a < t < t_b = (1 + sin_o) / mu_o    |phi| < acos(c(t))
//   t >= t_b                              none.
// At normal incidence (sin_o = 0) t_a = t_b = 1.
#pragma once

#include <cmath>

#include "brdflut/math.h"

namespace brdflut::detail {

struct ReflectionBand {
    double t_a, t_b;
};

inline ReflectionBand reflection_band(double mu_o, double sin_o) {
    return {mu_o / (1.0 + sin_o), (1.0 + sin_o) / mu_o};
}

// The largest |phi| in [0, pi] at which the reflection stays above the
// horizon, for t inside the band (t_a, t_b); 0 when none does.
// c(t) = cos of that largest |phi| (below -1: every phi; above 1: none).
inline double reflection_cos_phi_max(double t, double mu_o, double sin_o) {
    return -mu_o * (1.0 - t * t) / (2.0 * t * sin_o);
}

inline double reflection_phi_max(double t, double mu_o, double sin_o) {
    const double c = reflection_cos_phi_max(t, mu_o, sin_o);
    if (c >= 1.0) return 0.0;
    if (c <= -1.0) return kPi;
    return std::acos(c);
}

}  // namespace brdflut::detail
