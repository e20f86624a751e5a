#include "cli/options.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "brdflut/error.h"

namespace brdflut::cli {

void add_table_options(CLI::App& app, TableArgs& a, bool methods) {
    app.add_option("--size", a.size, "Grid size: N (every axis) or NxM (x by y)");
    app.add_option("--range", a.ranges, "Axis range AXIS=MIN:MAX, e.g. alpha=0.01:1 (repeatable)");
    app.add_option("--count", a.counts, "Axis count AXIS=N (repeatable)");
    app.add_option("--placement", a.placements, "Axis placement AXIS=center|endpoints|zero_then_endpoints|split_endpoints (repeatable)");
    std::string warp_names;
    for (const WarpDef& w : warps()) warp_names += (warp_names.empty() ? "" : "|") + std::string(w.name);
    app.add_option("--warp", a.warps, "Axis warp AXIS=" + warp_names + " (repeatable)");
    app.add_option("--order", a.order,
                   "Storage order of the axes, x first, e.g. alpha,cos_theta for a table with rows of cos_theta");
    app.add_option("--flip", a.flips, "Axis stored in reverse order, AXIS (repeatable)");
    app.add_option("--clamp", a.clamps,
                   "Clamp an axis's parameter, AXIS=LO:HI, e.g. cos_theta=1e-4:1 (repeatable; inf allowed)");
    app.add_option("--shift", a.shifts,
                   "Grid of an axis offset by some texels, AXIS=T, e.g. roughness=1 for rows one texel high "
                   "(a misplaced grid; repeatable)");
    app.add_option("--channels", a.channels,
                   "What each stored channel holds, as sums of the table's channels, e.g. R=G,G=R+G");
    if (methods) {
        app.add_option("--method", a.method, "Integration: quadrature (deterministic) or mc (Monte Carlo)")
            ->capture_default_str();
        app.add_option("--quality", a.quality,
                       "Quadrature effort: draft (abs tolerance ~1e-5), default (every stored "
                       "float within 1e-7), reference (~1e-12); recorded in the metadata")
            ->capture_default_str();
        app.add_option("--samples", a.samples, "Samples per texel with --method mc")->capture_default_str();
        app.add_option("--seed", a.seed, "Seed with --method mc")->capture_default_str();
    }
    // Model options of every table, each registered once.
    std::map<std::string, std::string> help;
    for (const TableDefinition& d : catalogue())
        for (const ModelOption& o : d.options) {
            std::string& h = help[o.name];
            if (h.empty()) h = o.help;
            h += (h.find(" [tables:") == std::string::npos ? " [tables: " : ", ") + d.id;
        }
    for (auto& [name, text] : help) app.add_option("--" + name, a.option_values[name], text + "]");
}

void collect_params(const CLI::App& app, TableArgs& a) {
    for (const auto& [name, value] : a.option_values)
        if (app.count("--" + name)) a.params[name] = value;
}

std::vector<int> parse_size(const std::string& s) {
    std::vector<int> out;
    std::size_t start = 0;
    while (true) {
        const std::size_t x = s.find('x', start);
        const std::string part = s.substr(start, x == std::string::npos ? std::string::npos : x - start);
        long long v = -1;
        std::size_t used = 0;
        try {
            v = std::stoll(part, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (part.empty() || used != part.size() || v < 1 || v > kMaxAxisCount)
            throw Error("--size '" + s + "' is not valid; allowed: N or NxM with each count from 1 to " +
                        std::to_string(kMaxAxisCount));
        out.push_back(static_cast<int>(v));
        if (x == std::string::npos) break;
        start = x + 1;
    }
    if (out.size() > 3) throw Error("--size '" + s + "' has more than 3 counts; allowed: N, NxM or NxMxK");
    return out;
}

std::string sci(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2e", v);
    return buf;
}

double parse_limit(const std::string& option, const std::string& s) {
    if (s == "inf" || s == "+inf") return HUGE_VAL;
    if (s == "-inf") return -HUGE_VAL;
    return parse_double(option, s);
}

std::pair<std::string, std::string> split_assignment(const std::string& option, const std::string& s) {
    const std::size_t eq = s.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == s.size())
        throw Error(option + " '" + s + "' is not valid; expected AXIS=VALUE, e.g. " + option +
                    " alpha=" + (option == "--range" ? "0:1" : "64"));
    return {s.substr(0, eq), s.substr(eq + 1)};
}

double parse_double(const std::string& option, const std::string& s) {
    std::size_t used = 0;
    double v = 0;
    try {
        v = std::stod(s, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != s.size() || s.empty() || !std::isfinite(v))
        throw Error(option + " value '" + s + "' is not a finite number");
    return v;
}

TableSettings settings_for(const TableDefinition& def, const TableArgs& a, std::set<std::string>& used) {
    TableSettings s = default_settings(def);
    if (!a.order.empty()) {
        // The storage order, by name, applies to the tables whose axes are
        // exactly those it names.
        std::vector<std::string> names;
        std::stringstream ss(a.order);
        for (std::string name; std::getline(ss, name, ',');) names.push_back(name);
        std::vector<Axis> ordered;
        for (const std::string& name : names) {
            auto it = std::find_if(s.axes.begin(), s.axes.end(), [&](const Axis& ax) { return ax.name == name; });
            if (it != s.axes.end() &&
                std::none_of(ordered.begin(), ordered.end(), [&](const Axis& ax) { return ax.name == name; }))
                ordered.push_back(*it);
        }
        if (ordered.size() == s.axes.size() && names.size() == s.axes.size()) {
            s.axes = ordered;
            used.insert("--order");
        }
    }
    if (!a.size.empty()) {
        // N sets every axis; NxM[xK] sets the axes in storage order, and a
        // table with fewer axes takes the first counts (check_all_used
        // makes sure some requested table takes them all).
        const std::vector<int> n = parse_size(a.size);
        for (std::size_t i = 0; i < s.axes.size(); ++i)
            if (n.size() == 1 || i < n.size()) s.axes[i].count = n.size() == 1 ? n[0] : n[i];
        if (n.size() == 1 || n.size() <= s.axes.size()) used.insert("--size");
    }
    auto axis_named = [&](const std::string& option, const std::string& name) -> Axis* {
        for (auto& ax : s.axes)
            if (ax.name == name) {
                used.insert(option + " " + name);
                return &ax;
            }
        return nullptr;
    };
    for (const auto& r : a.ranges) {
        const auto [name, value] = split_assignment("--range", r);
        const std::size_t colon = value.find(':');
        if (colon == std::string::npos)
            throw Error("--range '" + r + "' is not valid; expected AXIS=MIN:MAX, e.g. --range eta=1:2.5");
        if (Axis* ax = axis_named("--range", name)) {
            ax->min = parse_limit("--range " + name, value.substr(0, colon));
            ax->max = parse_limit("--range " + name, value.substr(colon + 1));
        }
    }
    for (const auto& c : a.counts) {
        const auto [name, value] = split_assignment("--count", c);
        if (Axis* ax = axis_named("--count", name)) {
            const double v = parse_double("--count " + name, value);
            if (v != std::floor(v) || v < 1 || v > kMaxAxisCount)
                throw Error("--count " + name + "=" + value + " is out of range; allowed: 1 to " +
                            std::to_string(kMaxAxisCount));
            ax->count = static_cast<int>(v);
        }
    }
    for (const auto& p : a.placements) {
        const auto [name, value] = split_assignment("--placement", p);
        if (Axis* ax = axis_named("--placement", name)) ax->placement = placement_from_string(value);
    }
    for (const auto& w : a.warps) {
        const auto [name, value] = split_assignment("--warp", w);
        if (Axis* ax = axis_named("--warp", name)) ax->warp = warp_from_string(value);
    }
    for (const auto& c : a.clamps) {
        const auto [name, value] = split_assignment("--clamp", c);
        const std::size_t colon = value.find(':');
        if (colon == std::string::npos)
            throw Error("--clamp '" + c + "' is not valid; expected AXIS=LO:HI, e.g. --clamp cos_theta=1e-4:1");
        if (Axis* ax = axis_named("--clamp", name)) {
            ax->clamp_lo = parse_limit("--clamp " + name, value.substr(0, colon));
            ax->clamp_hi = parse_limit("--clamp " + name, value.substr(colon + 1));
        }
    }
    for (const auto& name : a.flips) {
        if (Axis* ax = axis_named("--flip", name)) ax->flip = true;
    }
    for (const auto& t : a.shifts) {
        const auto [name, value] = split_assignment("--shift", t);
        if (Axis* ax = axis_named("--shift", name)) ax->shift = parse_double("--shift " + name, value);
    }
    if (!a.channels.empty()) {
        // The map applies to the tables that have every channel it names.
        std::vector<std::vector<int>> map = parse_channel_map(a.channels, 4);
        bool fits = true;
        for (const auto& sum : map)
            for (int c : sum) fits = fits && c < static_cast<int>(def.channels.size());
        if (fits) {
            s.channel_map = std::move(map);
            used.insert("--channels");
        }
    }
    for (const auto& [name, value] : a.params) {
        if (s.params.count(name)) {
            s.params[name] = value;
            used.insert("--" + name);
        }
    }
    s.method = method_from_string(a.method);
    s.quality = quality_from_string(a.quality);
    s.samples = a.samples;
    s.seed = a.seed;
    return s;
}

void check_all_used(const TableArgs& a, const std::set<std::string>& used) {
    auto check = [&](const std::string& option, const std::vector<std::string>& values) {
        for (const auto& v : values) {
            const std::string name = v.substr(0, v.find('='));
            if (!used.count(option + " " + name))
                throw Error(option + " '" + v + "': no requested table has an axis named '" + name + "'");
        }
    };
    check("--range", a.ranges);
    check("--count", a.counts);
    check("--placement", a.placements);
    check("--warp", a.warps);
    check("--clamp", a.clamps);
    check("--shift", a.shifts);
    for (const auto& name : a.flips)
        if (!used.count("--flip " + name))
            throw Error("--flip '" + name + "': no requested table has an axis named '" + name + "'");
    if (!a.order.empty() && !used.count("--order"))
        throw Error("--order '" + a.order +
                    "' is not an order of any requested table's axes; allowed: each of the table's axes once, x first");
    if (!a.channels.empty() && !used.count("--channels"))
        throw Error("--channels '" + a.channels + "' names a channel that no requested table has");
    if (!a.size.empty() && !used.count("--size"))
        throw Error("--size '" + a.size + "' has more counts than any requested table has axes");
    for (const auto& [name, value] : a.params)
        if (!used.count("--" + name)) throw Error("--" + name + " does not apply to any requested table");
}

}  // namespace brdflut::cli
