#include "io/table_checks.h"

#include <charconv>
#include <cmath>
#include <sstream>
#include <string_view>

#include "brdflut/error.h"

namespace brdflut {
namespace {
constexpr const char* kChannelNames[4] = {"R", "G", "B", "A"};

// Shortest text that reads back as the same double.
std::string shortest(double v) {
    char buf[32];
    const auto end = std::to_chars(buf, buf + sizeof buf, v).ptr;
    return std::string(buf, static_cast<std::size_t>(end - buf));
}
}  // namespace

std::string describe_value(const Table& t, std::size_t value_index) {
    const std::size_t nc = t.channels.empty() ? 1 : t.channels.size();
    std::ostringstream s;
    s << "texel (";
    std::size_t rest = value_index / nc;
    for (std::size_t a = 0; a < t.axes.size(); ++a) {
        const std::size_t n = static_cast<std::size_t>(t.axes[a].count);
        s << (a ? ", " : "") << t.axes[a].name << " index " << rest % n << " = "
          << t.axes[a].value(static_cast<int>(rest % n));
        rest /= n;
    }
    s << "), channel " << kChannelNames[value_index % nc % 4];
    return s.str();
}

void check_shape(const Table& t) {
    const int nc = t.channel_count();
    if (nc < 1 || nc > 4)
        throw Error("table '" + t.id + "' has " + std::to_string(nc) + " channels; allowed: 1 to 4");
    if (t.values.size() != t.texel_count() * static_cast<std::size_t>(nc))
        throw Error("table '" + t.id + "' has " + std::to_string(t.values.size()) + " values; its axes and " +
                    std::to_string(nc) + " channel(s) need " +
                    std::to_string(t.texel_count() * static_cast<std::size_t>(nc)));
}

void check_storable(const Table& t, Storage s) {
    constexpr double kEndRounding = 1e-12;
    if (t.channel_count() > max_channels(s))
        throw Error("table '" + t.id + "' has " + std::to_string(t.channel_count()) + " channels; the encoding " +
                    std::string(to_string(s)) + " holds 1 to " + std::to_string(max_channels(s)) +
                    " (A is taken); nothing was written");
    for (std::size_t i = 0; i < t.values.size(); ++i) {
        const double v = t.values[i];
        if (!std::isfinite(v))
            throw RuntimeError("table '" + t.id + "': value " + shortest(v) + " at " + describe_value(t, i) +
                               " is not finite; nothing was written");
        if (is_integer(s)) {
            // A value within kEndRounding of an end is that end, rounded
            // (1 - (E_R + E_T) = -2.2e-16 where E_R + E_T rounds to 1 + 2^-52):
            // it is stored as the end's code, which is what clamping would give.
            if (v >= storage_min(s) - kEndRounding && v <= storage_max(s) * (1.0 + kEndRounding)) continue;
            throw Error("table '" + t.id + "': value " + shortest(v) + " at " + describe_value(t, i) +
                        " is outside [0, " + shortest(storage_max(s)) + "]; the encoding " +
                        std::string(to_string(s)) + " holds values in [0, " + shortest(storage_max(s)) +
                        "] only (values are refused, not clamped), use half or float storage for this table; "
                        "nothing was written");
        }
        if (!std::isfinite(round_to_storage(v, s)))
            throw RuntimeError("table '" + t.id + "': value " + shortest(v) + " at " + describe_value(t, i) +
                               " does not fit in " + std::string(to_string(s)) +
                               (s == Storage::half ? " (largest 65504); use float pixels" : "") +
                               "; nothing was written");
    }
}

}  // namespace brdflut
