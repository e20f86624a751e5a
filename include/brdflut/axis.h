// Table axes: how the storage position i of a texel along an axis maps to
// the parameter value the model is evaluated at. Every tool that reads or
// writes a table (generate, compare, identify, sample, the shader writers)
// goes through these functions, so one description means the same thing
// everywhere.
//
//   flip       j = count - 1 - i when the axis is stored in reverse, else j = i
//   placement  center     u = (j + 0.5 + shift) / count
//              endpoints  u = (j + shift) / (count - 1)   (count >= 2)
//              zero_then_endpoints  j = 0 holds the parameter 0; j >= 1 the
//                         end points u = (j - 1 + shift) / (count - 2) of
//                         [min, max], 0 < min < max (count >= 2, count 2 holds
//                         0 and min; with the log warp, pbrt-v4's radii 0, r_1,
//                         r_1 q, ..)
//              split_endpoints  two halves, of h = floor(count/2) and
//                         g = count - h texels (count >= 2, no shift): end
//                         points u = j/(h - 1)/2 of [0, 1/2], then u = 1/2 +
//                         (j - h)/(g - 1)/2 of [1/2, 1]; a half of one texel
//                         holds its outer end (Adobe's OpenPBR index axis:
//                         both halves end at u = 1/2, n = 1 with ior_split)
//   shift      0, or the texels by which a generator misplaced its grid
//              (Filament's rows hold r = (j + 1.5)/h: shift 1 with a clamp)
//   warp       value = W(u; min, max), one entry of the warp registry below;
//              min > max is allowed (a decreasing axis)
//   clamp      parameter = clamp(value, clamp_lo, clamp_hi)
//
// The inverse, used to sample a table at a parameter p:
//   u = W^-1(clamp(p)), position = u count - 0.5 - shift (center) or
//   u (count - 1) - shift (endpoints), 1 + u (count - 2) - shift above min and
//   p / min at or below it (zero_then_endpoints), 2u (h - 1) below u = 1/2 and
//   h + (2u - 1)(g - 1) from it (split_endpoints), reversed when flipped; texel i's centre is at position i,
//   and the texture coordinate of a GPU sampler is (position + 0.5) / count.
#pragma once

#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace brdflut {

enum class Placement { center, endpoints, zero_then_endpoints, split_endpoints };
std::string_view to_string(Placement p);
Placement placement_from_string(std::string_view s);  // throws brdflut::Error

// How the normalized coordinate u in [0, 1] maps to a parameter value. Each
// warp is one entry of warps(): to add a mapping, add an enumerator here and
// its entry in src/axis.cpp.
enum class Warp { linear, square, sqrt, log, ior_z, saturating_exp, ior_split };

struct WarpDef {
    Warp warp;
    const char* name;
    const char* formula;  // value as a function of u, min and max
    const char* used_by;  // engines that lay out an axis this way
    double (*value)(double u, double min, double max);
    double (*u_of_value)(double v, double min, double max);  // the inverse
    // Empty when min and max are a valid range for the warp, else why not.
    std::string (*range_problem)(double min, double max);
    // The inverse as one expression valid in GLSL and HLSL alike, of `v`
    // (the clamped parameter, a float), `lo` and `hi`: min and max, or, when
    // shader_bound is set, shader_bound(min) and shader_bound(max) (finite
    // where the range is not: ior_z's z(inf) = 1).
    const char* shader_u;
    double (*shader_bound)(double) = nullptr;
};

const std::vector<WarpDef>& warps();
const WarpDef& warp_def(Warp w);
std::string_view to_string(Warp w);
Warp warp_from_string(std::string_view s);  // throws brdflut::Error listing the warps

struct Axis {
    std::string name;  // from the vocabulary in docs/axes.md: cos_theta, alpha, ...
    double min = 0.0;  // parameter at u = 0
    double max = 1.0;  // parameter at u = 1 (below min for a decreasing axis)
    int count = 1;
    Placement placement = Placement::center;
    Warp warp = Warp::linear;
    bool flip = false;  // stored in reverse: position i holds grid index count - 1 - i
    double shift = 0.0;  // grid offset in texels (a misplaced grid); u may then leave [0, 1]
    double clamp_lo = -std::numeric_limits<double>::infinity();
    double clamp_hi = std::numeric_limits<double>::infinity();

    // Normalized coordinate of storage position i (zero_then_endpoints: the
    // warp's inverse at 0 for grid index 0, -inf for the log warp).
    double u(int i) const;
    double value(int i) const;          // parameter of storage position i (clamped)
    double value_at_u(double u) const;  // the warp alone, exact at u = 0 and 1
    double clamped(double v) const;     // v clamped to [clamp_lo, clamp_hi]
    double u_of_value(double v) const;  // inverse of value_at_u, of the clamped v
    // Continuous storage position of a parameter (texel i's centre is at i),
    // not clamped to the grid.
    double position_of_value(double v) const;
    bool has_clamp() const;
    // The smallest and largest parameter the axis evaluates, over all of
    // [0, 1] and the grid (clamps applied).
    double lowest() const;
    double highest() const;

    // Throws brdflut::Error when the axis is not well formed (count out of
    // range, endpoints with count < 2, an empty or invalid range for the
    // warp, clamps that are reversed, a parameter that is not finite).
    void validate() const;
};

// The largest count accepted on any axis, and in any table as a whole.
inline constexpr int kMaxAxisCount = 16384;
inline constexpr long long kMaxTexels = 1LL << 26;

}  // namespace brdflut
