#include "brdflut/axis.h"

#include <cmath>
#include <sstream>

#include "brdflut/error.h"

namespace brdflut {

std::string_view to_string(Placement p) { return p == Placement::center ? "center" : "endpoints"; }

std::string_view to_string(Warp w) {
    switch (w) {
        case Warp::linear: return "linear";
        case Warp::square: return "square";
        case Warp::sqrt: return "sqrt";
        case Warp::log: return "log";
    }
    return "linear";
}

Placement placement_from_string(std::string_view s) {
    if (s == "center") return Placement::center;
    if (s == "endpoints") return Placement::endpoints;
    throw Error("placement '" + std::string(s) + "' is not known; allowed: center, endpoints");
}

Warp warp_from_string(std::string_view s) {
    if (s == "linear") return Warp::linear;
    if (s == "square") return Warp::square;
    if (s == "sqrt") return Warp::sqrt;
    if (s == "log") return Warp::log;
    throw Error("warp '" + std::string(s) + "' is not known; allowed: linear, square, sqrt, log");
}

double Axis::u(int i) const {
    if (placement == Placement::center) return (i + 0.5) / count;
    return count > 1 ? static_cast<double>(i) / (count - 1) : 0.0;
}

double Axis::value_at_u(double t) const {
    double v = min;
    switch (warp) {
        case Warp::linear: v = min + (max - min) * t; break;
        case Warp::square: v = min + (max - min) * t * t; break;
        case Warp::sqrt: v = min + (max - min) * std::sqrt(t); break;
        case Warp::log: v = min * std::pow(max / min, t); break;
    }
    // The end points are exact, whatever the rounding of the warp.
    if (t == 0.0) v = min;
    if (t == 1.0) v = max;
    return v;
}

double Axis::value(int i) const { return value_at_u(u(i)); }

double Axis::u_of_value(double v) const {
    const double s = (v - min) / (max - min);
    switch (warp) {
        case Warp::linear: return s;
        case Warp::square: return std::sqrt(std::max(0.0, s));
        case Warp::sqrt: return s * s;
        case Warp::log: return std::log(v / min) / std::log(max / min);
    }
    return s;
}

void Axis::validate() const {
    auto fail = [&](const std::string& what) {
        throw Error("axis '" + name + "': " + what);
    };
    if (count < 1 || count > kMaxAxisCount) {
        fail("count " + std::to_string(count) + " is out of range; allowed: 1 to " +
             std::to_string(kMaxAxisCount));
    }
    if (placement == Placement::endpoints && count < 2)
        fail("placement 'endpoints' needs a count of at least 2 (got " + std::to_string(count) + ")");
    if (!std::isfinite(min) || !std::isfinite(max)) fail("range must be finite");
    if (!(min < max)) {
        std::ostringstream s;
        s << "range " << min << ":" << max << " is empty; min must be below max";
        fail(s.str());
    }
    if (warp == Warp::log && !(min > 0.0)) {
        std::ostringstream s;
        s << "warp 'log' needs min > 0 (got " << min << ")";
        fail(s.str());
    }
}

}  // namespace brdflut
