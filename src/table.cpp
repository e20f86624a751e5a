#include "brdflut/table.h"

#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

#include "brdflut/error.h"
#include "brdflut/version.h"

namespace brdflut {

namespace {
constexpr const char* kLetters = "RGBA";

int letter_index(char c) {
    const char* p = std::strchr(kLetters, c);
    return (p && c) ? static_cast<int>(p - kLetters) : -1;
}
}  // namespace

nlohmann::json number_to_json(double v) {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    return v;
}

double number_from_json(const nlohmann::json& j) {
    if (j.is_string()) {
        const std::string s = j.get<std::string>();
        if (s == "inf") return HUGE_VAL;
        if (s == "-inf") return -HUGE_VAL;
        throw RuntimeError("'" + s + "' is not a number (allowed: a number, \"inf\" or \"-inf\")");
    }
    return j.get<double>();
}

std::string channel_map_to_string(const std::vector<std::vector<int>>& map) {
    std::string out;
    for (std::size_t c = 0; c < map.size(); ++c) {
        if (c) out.push_back(',');
        out.push_back(kLetters[c]);
        out.push_back('=');
        for (std::size_t i = 0; i < map[c].size(); ++i) {
            if (i) out.push_back('+');
            out.push_back(kLetters[map[c][i]]);
        }
    }
    return out;
}

std::vector<std::vector<int>> parse_channel_map(const std::string& spec, int table_channels) {
    std::vector<std::vector<int>> map;
    std::stringstream ss(spec);
    std::string item;
    const std::string allowed = std::string(kLetters).substr(0, static_cast<std::size_t>(table_channels));
    while (std::getline(ss, item, ',')) {
        const std::size_t eq = item.find('=');
        auto bad = [&](const std::string& why) {
            return Error("--channels item '" + item + "' " + why + "; expected FILE=TABLE[+TABLE], e.g. R=G,G=R+G, "
                         "with table channels from " + allowed);
        };
        if (eq != 1 || letter_index(item[0]) < 0) throw bad("must start with a file channel R, G, B or A");
        const std::size_t file_c = static_cast<std::size_t>(letter_index(item[0]));
        if (file_c != map.size()) throw bad("is out of order: list the file channels from R");
        std::vector<int> sum;
        for (std::size_t i = 2; i < item.size(); ++i) {
            if (item[i] == '+') continue;
            const int t = letter_index(item[i]);
            if (t < 0 || t >= table_channels) throw bad("names a table channel that does not exist");
            sum.push_back(t);
        }
        if (sum.empty()) throw bad("names no table channel");
        map.push_back(sum);
    }
    if (map.empty()) throw Error("--channels '" + spec + "' is empty");
    return map;
}

std::string_view to_string(Method m) { return m == Method::quadrature ? "quadrature" : "mc"; }

Method method_from_string(std::string_view s) {
    if (s == "quadrature") return Method::quadrature;
    if (s == "mc") return Method::monte_carlo;
    throw Error("method '" + std::string(s) + "' is not known; allowed: quadrature, mc");
}

std::string_view to_string(Quality q) {
    switch (q) {
        case Quality::draft: return "draft";
        case Quality::standard: return "default";
        case Quality::reference: return "reference";
    }
    return "default";
}

Quality quality_from_string(std::string_view s) {
    if (s == "draft") return Quality::draft;
    if (s == "default") return Quality::standard;
    if (s == "reference") return Quality::reference;
    throw Error("--quality '" + std::string(s) + "' is not known; allowed: draft, default, reference");
}

std::string_view to_string(PixelType p) { return p == PixelType::half ? "half" : "float"; }

PixelType pixel_type_from_string(std::string_view s) {
    if (s == "half") return PixelType::half;
    if (s == "float") return PixelType::float32;
    throw Error("pixel type '" + std::string(s) + "' is not known; allowed: half, float");
}

int Table::height() const {
    int h = axes.size() > 1 ? axes[1].count : 1;
    if (axes.size() > 2) h *= axes[2].count;
    return h;
}

std::size_t Table::texel_count() const {
    std::size_t n = 1;
    for (const Axis& a : axes) n *= static_cast<std::size_t>(a.count);
    return n;
}

double error_bound(const Table& t, PixelType p) { return error_bound(t, storage_of(p)); }

double error_bound(const Table& t, Storage s) {
    double bound = 0.0;
    const std::size_t nc = t.channels.empty() ? 1 : t.channels.size();
    const int n = static_cast<int>(std::min<std::size_t>(nc, 4));
    double rounded[4];
    for (std::size_t i = 0; i < t.values.size(); i += nc) {
        if (i + nc > t.values.size() || nc > 4) break;
        round_texel(s, &t.values[i], n, rounded);
        for (std::size_t c = 0; c < nc; ++c) {
            const double rounding = std::abs(rounded[c] - t.values[i + c]);
            bound = std::max(bound, (i + c < t.errors.size() ? t.errors[i + c] : 0.0) + rounding);
        }
    }
    return bound;
}

nlohmann::json metadata_json(const Table& t, PixelType p) { return metadata_json(t, storage_of(p)); }

nlohmann::json metadata_json(const Table& t, Storage s) {
    nlohmann::json j;
    j["table"] = t.id;
    j["generator"] = {{"name", kName}, {"version", kVersion}};
    j["model"] = t.model;
    j["options"] = t.options;
    nlohmann::json axes = nlohmann::json::array();
    for (const Axis& a : t.axes) {
        nlohmann::json ax = {{"name", a.name},
                             {"min", number_to_json(a.min)},
                             {"max", number_to_json(a.max)},
                             {"count", a.count},
                             {"placement", to_string(a.placement)},
                             {"warp", to_string(a.warp)}};
        if (a.flip) ax["flip"] = true;
        if (a.shift != 0.0) ax["shift"] = a.shift;
        if (a.has_clamp()) ax["clamp"] = {number_to_json(a.clamp_lo), number_to_json(a.clamp_hi)};
        axes.push_back(ax);
    }
    j["axes"] = axes;
    if (!t.channel_map.empty()) j["channel_map"] = channel_map_to_string(t.channel_map);
    j["layout"] = t.axes.size() > 2
                      ? "x: axis 0 along the row; rows: axis 1; axis 2 slices stacked "
                        "vertically (row = z * count_y + y)"
                      : (t.axes.size() == 2 ? "x: axis 0 along the row; rows: axis 1"
                                            : "x: axis 0 along the single row");
    j["channels"] = t.channels;
    j["method"] = t.method;
    j["pixel"] = to_string(s);
    if (is_integer(s)) j["decode"] = decode_rule(s);
    j["error_bound"] = error_bound(t, s);
    return j;
}

std::vector<Axis> axes_from_json(const nlohmann::json& axes) {
    if (!axes.is_array() || axes.empty() || axes.size() > 3)
        throw RuntimeError("metadata 'axes' must be a list of 1 to 3 axes");
    std::vector<Axis> out;
    for (const auto& a : axes) {
        try {
            Axis ax;
            ax.name = a.at("name").get<std::string>();
            ax.min = number_from_json(a.at("min"));
            ax.max = number_from_json(a.at("max"));
            ax.count = a.at("count").get<int>();
            ax.placement = placement_from_string(a.at("placement").get<std::string>());
            ax.warp = warp_from_string(a.at("warp").get<std::string>());
            if (a.contains("flip")) ax.flip = a.at("flip").get<bool>();
            if (a.contains("shift")) ax.shift = a.at("shift").get<double>();
            if (a.contains("clamp")) {
                const auto& c = a.at("clamp");
                if (!c.is_array() || c.size() != 2) throw RuntimeError("'clamp' must be [lo, hi]");
                ax.clamp_lo = number_from_json(c.at(0));
                ax.clamp_hi = number_from_json(c.at(1));
            }
            ax.validate();
            out.push_back(ax);
        } catch (const nlohmann::json::exception& e) {
            throw RuntimeError(std::string("metadata axis is malformed: ") + e.what());
        } catch (const Error& e) {
            throw RuntimeError(std::string("metadata axis is malformed: ") + e.what());
        } catch (const RuntimeError& e) {
            throw RuntimeError(std::string("metadata axis is malformed: ") + e.what());
        }
    }
    return out;
}

}  // namespace brdflut
