#include "brdflut/axis.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "brdflut/error.h"

namespace brdflut {
namespace {

std::string number(double v) {
    std::ostringstream s;
    s.precision(10);
    s << v;
    return s.str();
}

std::string finite_range(double min, double max) {
    if (!std::isfinite(min) || !std::isfinite(max)) return "range must be finite";
    if (min == max) return "range " + number(min) + ":" + number(max) + " is empty; min and max must differ";
    return {};
}

// Cycles' IOR coordinate z = sqrt((n - 1)/(n + 1)); z(inf) = 1.
double ior_z(double n) { return std::isinf(n) ? 1.0 : std::sqrt(std::max(0.0, (n - 1.0) / (n + 1.0))); }
double ior_of_z(double z) { return z >= 1.0 ? HUGE_VAL : (1.0 + z * z) / (1.0 - z * z); }

const std::vector<WarpDef> kWarps = {
    {Warp::linear, "linear", "min + (max - min) u", "most axes (Filament, glTF, Godot: mu and r)",
     [](double u, double lo, double hi) { return lo + (hi - lo) * u; },
     [](double v, double lo, double hi) { return (v - lo) / (hi - lo); }, finite_range,
     "(v - lo) / (hi - lo)"},
    {Warp::square, "square", "min + (max - min) u^2",
     "u = sqrt(alpha) (Cycles), u = sqrt(mu) (HDRP FGD); with range 1:0, u = sqrt(1 - mu) "
     "(EEVEE split sum, Heitz LTC, HDRP LTC)",
     [](double u, double lo, double hi) { return lo + (hi - lo) * u * u; },
     [](double v, double lo, double hi) { return std::sqrt(std::max(0.0, (v - lo) / (hi - lo))); }, finite_range,
     "sqrt(max((v - lo) / (hi - lo), 0.0))"},
    {Warp::sqrt, "sqrt", "min + (max - min) sqrt(u)", "",
     [](double u, double lo, double hi) { return lo + (hi - lo) * std::sqrt(u); },
     [](double v, double lo, double hi) {
         const double s = std::max(0.0, (v - lo) / (hi - lo));
         return s * s;
     },
     finite_range, "max((v - lo) / (hi - lo), 0.0) * max((v - lo) / (hi - lo), 0.0)"},
    {Warp::log, "log", "min (max / min)^u", "distances (dipole radius)",
     [](double u, double lo, double hi) { return lo * std::pow(hi / lo, u); },
     [](double v, double lo, double hi) { return std::log(v / lo) / std::log(hi / lo); },
     [](double lo, double hi) -> std::string {
         if (std::string why = finite_range(lo, hi); !why.empty()) return why;
         if (!(lo > 0.0) || !(hi > 0.0))
             return "warp 'log' needs min > 0 and max > 0 (got " + number(lo) + ":" + number(hi) + ")";
         return {};
     },
     "log(v / lo) / log(hi / lo)"},
    {Warp::ior_z, "ior_z",
     "n(z) = (1 + z^2)/(1 - z^2), z = z(min) + (z(max) - z(min)) u, z(n) = sqrt((n - 1)/(n + 1))",
     "index of refraction (Cycles glass tables, z in [0, 1] for n in [1, inf])",
     [](double u, double lo, double hi) { return ior_of_z(ior_z(lo) + (ior_z(hi) - ior_z(lo)) * u); },
     [](double v, double lo, double hi) { return (ior_z(v) - ior_z(lo)) / (ior_z(hi) - ior_z(lo)); },
     [](double lo, double hi) -> std::string {
         if (std::isnan(lo) || std::isnan(hi) || std::isinf(lo) || hi == -HUGE_VAL) return "range must be finite";
         if (!(lo >= 1.0) || !(hi >= 1.0))
             return "warp 'ior_z' needs min >= 1 and max >= 1 (got " + number(lo) + ":" + number(hi) + ")";
         if (lo == hi) return "range " + number(lo) + ":" + number(hi) + " is empty; min and max must differ";
         return {};
     },
     "(sqrt(max((v - 1.0) / (v + 1.0), 0.0)) - lo) / (hi - lo)", ior_z},
    {Warp::saturating_exp, "saturating_exp", "min + (max - min) (1 - e^(-8 u)) / (1 - e^(-8))",
     "single-scattering albedos of pbrt-v4's BSSRDFTable (100 end points from 0 to 1, dense near 1)",
     [](double u, double lo, double hi) { return lo + (hi - lo) * (std::expm1(-8.0 * u) / std::expm1(-8.0)); },
     [](double v, double lo, double hi) { return -std::log1p((v - lo) / (hi - lo) * std::expm1(-8.0)) / 8.0; },
     [](double lo, double hi) -> std::string {
         if (std::string why = finite_range(lo, hi); !why.empty()) return why;
         return {};
     },
     "-log(max(1.0 - (v - lo) / (hi - lo) * 0.9996645373720975, 1e-30)) / 8.0"},
    {Warp::ior_split, "ior_split",
     "u < 1/2: 1/(1 + (1 - 2u)(1/min - 1)), else 1 + (2u - 1)(max - 1) (1/n linear below n = 1, n above)",
     "index of refraction from both sides of the interface: n < 1 is light leaving the denser medium "
     "(Adobe's OpenPBR energy tables, with placement split_endpoints)",
     [](double u, double lo, double hi) {
         return u < 0.5 ? 1.0 / (1.0 + (1.0 - 2.0 * u) * (1.0 / lo - 1.0)) : 1.0 + (2.0 * u - 1.0) * (hi - 1.0);
     },
     [](double v, double lo, double hi) {
         return v < 1.0 ? 0.5 - 0.5 * (1.0 / v - 1.0) / (1.0 / lo - 1.0) : 0.5 + 0.5 * (v - 1.0) / (hi - 1.0);
     },
     [](double lo, double hi) -> std::string {
         if (std::string why = finite_range(lo, hi); !why.empty()) return why;
         if (!(lo > 0.0) || !(lo < 1.0) || !(hi > 1.0))
             return "warp 'ior_split' needs 0 < min < 1 < max (got " + number(lo) + ":" + number(hi) + ")";
         return {};
     },
     "(v < 1.0 ? 0.5 - 0.5 * (1.0 / v - 1.0) / (1.0 / lo - 1.0) : 0.5 + 0.5 * (v - 1.0) / (hi - 1.0))"},
};

}  // namespace

std::string_view to_string(Placement p) {
    switch (p) {
        case Placement::center: return "center";
        case Placement::endpoints: return "endpoints";
        case Placement::zero_then_endpoints: return "zero_then_endpoints";
        case Placement::split_endpoints: return "split_endpoints";
    }
    return "center";
}

Placement placement_from_string(std::string_view s) {
    if (s == "center") return Placement::center;
    if (s == "endpoints") return Placement::endpoints;
    if (s == "zero_then_endpoints") return Placement::zero_then_endpoints;
    if (s == "split_endpoints") return Placement::split_endpoints;
    throw Error("placement '" + std::string(s) +
                "' is not known; allowed: center, endpoints, zero_then_endpoints, split_endpoints");
}

const std::vector<WarpDef>& warps() { return kWarps; }

const WarpDef& warp_def(Warp w) {
    for (const WarpDef& d : kWarps)
        if (d.warp == w) return d;
    return kWarps.front();
}

std::string_view to_string(Warp w) { return warp_def(w).name; }

Warp warp_from_string(std::string_view s) {
    std::string known;
    for (const WarpDef& d : kWarps) {
        if (s == d.name) return d.warp;
        known += (known.empty() ? "" : ", ") + std::string(d.name);
    }
    throw Error("warp '" + std::string(s) + "' is not known; allowed: " + known);
}

double Axis::u(int i) const {
    const int j = flip ? count - 1 - i : i;
    if (placement == Placement::center) return (j + 0.5 + shift) / count;
    if (placement == Placement::zero_then_endpoints) {
        if (j == 0) return warp_def(warp).u_of_value(0.0, min, max);
        return count > 2 ? (j - 1 + shift) / (count - 2) : 0.0;  // count 2: 0 and min
    }
    if (placement == Placement::split_endpoints) {  // validate(): count >= 2, no shift
        const int lo = count / 2, hi = count - lo;    // a half of one texel holds its outer end
        if (j < lo) return lo > 1 ? 0.5 * j / (lo - 1) : 0.0;
        return hi > 1 ? 0.5 + 0.5 * (j - lo) / (hi - 1) : 1.0;
    }
    return count > 1 ? (j + shift) / (count - 1) : 0.0;
}

double Axis::value_at_u(double t) const {
    // The end points are exact, whatever the rounding of the warp.
    if (t == 0.0) return min;
    if (t == 1.0) return max;
    return warp_def(warp).value(t, min, max);
}

double Axis::clamped(double v) const { return std::min(std::max(v, clamp_lo), clamp_hi); }

double Axis::value(int i) const {
    if (placement == Placement::zero_then_endpoints && (flip ? count - 1 - i : i) == 0) return clamped(0.0);
    return clamped(value_at_u(u(i)));
}

double Axis::u_of_value(double v) const { return warp_def(warp).u_of_value(clamped(v), min, max); }

double Axis::position_of_value(double v) const {
    double p = 0.0;
    if (placement == Placement::zero_then_endpoints && clamped(v) <= min) {
        p = clamped(v) / min;  // linear between the parameter 0 (texel 0) and min (texel 1)
    } else {
        const double t = u_of_value(v);
        const int lo = count / 2, hi = count - lo;
        p = placement == Placement::center            ? t * count - 0.5 - shift
            : placement == Placement::endpoints       ? t * (count - 1) - shift
            : placement == Placement::split_endpoints ? (t < 0.5 ? 2.0 * t * (lo - 1) : lo + (2.0 * t - 1.0) * (hi - 1))
                                                      : 1.0 + t * (count - 2) - shift;
    }
    return flip ? count - 1 - p : p;
}

bool Axis::has_clamp() const { return clamp_lo != -HUGE_VAL || clamp_hi != HUGE_VAL; }

double Axis::lowest() const {
    return std::min({clamped(std::min(min, max)), value(0), value(count - 1)});
}
double Axis::highest() const {
    return std::max({clamped(std::max(min, max)), value(0), value(count - 1)});
}

void Axis::validate() const {
    auto fail = [&](const std::string& what) { throw Error("axis '" + name + "': " + what); };
    if (count < 1 || count > kMaxAxisCount) {
        fail("count " + std::to_string(count) + " is out of range; allowed: 1 to " + std::to_string(kMaxAxisCount));
    }
    if (placement == Placement::endpoints && count < 2)
        fail("placement 'endpoints' needs a count of at least 2 (got " + std::to_string(count) + ")");
    if (placement == Placement::zero_then_endpoints) {
        if (count < 2)
            fail("placement 'zero_then_endpoints' needs a count of at least 2 (got " + std::to_string(count) + ")");
        if (!(min > 0.0) || !(max > min))
            fail("placement 'zero_then_endpoints' needs 0 < min < max (got " + number(min) + ":" + number(max) + ")");
    }
    if (placement == Placement::split_endpoints) {
        if (count < 2)
            fail("placement 'split_endpoints' needs a count of at least 2 (got " + std::to_string(count) + ")");
        if (shift != 0.0) fail("placement 'split_endpoints' takes no shift (got " + number(shift) + ")");
    }
    if (const std::string why = warp_def(warp).range_problem(min, max); !why.empty()) fail(why);
    if (std::isnan(clamp_lo) || std::isnan(clamp_hi) || !(clamp_lo <= clamp_hi))
        fail("clamp " + number(clamp_lo) + ":" + number(clamp_hi) + " is not valid; allowed: LO:HI with LO <= HI");
    if (!std::isfinite(shift) || std::abs(shift) > 2)
        fail("shift " + number(shift) + " is out of range; allowed: -2 to 2 texels");
    if (std::isnan(value(0)) || std::isnan(value(count - 1)))
        fail("shift " + number(shift) + " moves the grid outside the domain of warp '" + warp_def(warp).name + "'");
    if (!std::isfinite(lowest()) || !std::isfinite(highest()))
        fail("range " + number(min) + ":" + number(max) +
             " reaches an infinite parameter; clamp it to a finite one with --clamp " + name + "=LO:HI");
}

}  // namespace brdflut
