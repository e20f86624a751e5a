// Table axes: how texel index i maps to a parameter value.
//
//   placement  center     u = (i + 0.5) / count
//              endpoints  u = i / (count - 1)        (count >= 2)
//   warp       linear     value = min + (max - min) u
//              square     value = min + (max - min) u^2
//              sqrt       value = min + (max - min) sqrt(u)
//              log        value = min (max / min)^u  (0 < min < max)
#pragma once

#include <string>
#include <string_view>

namespace brdflut {

enum class Placement { center, endpoints };
enum class Warp { linear, square, sqrt, log };

std::string_view to_string(Placement p);
std::string_view to_string(Warp w);
Placement placement_from_string(std::string_view s);  // throws brdflut::Error
Warp warp_from_string(std::string_view s);            // throws brdflut::Error

struct Axis {
    std::string name;  // from the vocabulary in README.md: cos_theta, alpha, ...
    double min = 0.0;
    double max = 1.0;
    int count = 1;
    Placement placement = Placement::center;
    Warp warp = Warp::linear;

    double u(int i) const;       // normalized coordinate of index i
    double value(int i) const;   // parameter value of index i
    double value_at_u(double u) const;
    double u_of_value(double v) const;  // inverse of value_at_u

    // Throws brdflut::Error when the axis is not well formed (count < 1,
    // endpoints with count < 2, min >= max, log with min <= 0, non-finite).
    void validate() const;
};

// The largest count accepted on any axis, and in any table as a whole.
inline constexpr int kMaxAxisCount = 16384;
inline constexpr long long kMaxTexels = 1LL << 26;

}  // namespace brdflut
