#include "brdflut/catalogue.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "brdflut/error.h"
#include "tables/registry.h"

namespace brdflut {

// Every src/tables/NAME_tables.cpp, as CMakeLists.txt lists them.
#define BRDFLUT_FAMILY(name) void register_##name##_family(FamilyEntries& out);
#include "families.inc"
#undef BRDFLUT_FAMILY

namespace {
// Registers one family and names what it added: its tables' family and its
// description (a family that gives none is listed by its name; a test
// requires every family to describe itself).
void register_family(FamilyEntries& f, const char* name, void (*reg)(FamilyEntries&)) {
    const std::size_t tables = f.tables.size(), described = f.families.size();
    reg(f);
    for (std::size_t i = tables; i < f.tables.size(); ++i) f.tables[i].family = name;
    if (f.families.size() == described) f.families.push_back({name, name, ""});
    f.families.resize(described + 1);
    f.families.back().name = name;
}
}  // namespace

const FamilyEntries& families() {
    static const FamilyEntries all = [] {
        FamilyEntries f;
#define BRDFLUT_FAMILY(name) register_family(f, #name, register_##name##_family);
#include "families.inc"
#undef BRDFLUT_FAMILY
        const auto complete = f.complete;
        for (const auto& step : complete) step(f);
        return f;
    }();
    return all;
}

const std::vector<TableDefinition>& catalogue() { return families().tables; }

const std::vector<TableFamily>& table_families() { return families().families; }

const TableDefinition& find_table(const std::string& id) {
    for (const TableDefinition& d : catalogue())
        if (d.id == id) return d;
    std::string known;
    for (const TableDefinition& d : catalogue()) known += (known.empty() ? "" : ", ") + d.id;
    throw Error("table '" + id + "' is not known; allowed: " + known);
}

const Preset& find_preset(const std::string& name) {
    for (const Preset& p : presets())
        if (p.name == name) return p;
    std::string known;
    for (const Preset& p : presets()) known += (known.empty() ? "" : ", ") + p.name;
    throw Error("preset '" + name + "' is not known; allowed: " + known);
}

std::vector<const TableDefinition*> preset_tables(const std::string& name) {
    find_preset(name);
    std::vector<const TableDefinition*> out;
    for (const TableDefinition& d : catalogue())
        if (d.preset == name) out.push_back(&d);
    return out;
}

TableSettings default_settings(const TableDefinition& def) {
    TableSettings s;
    for (const AxisSpec& a : def.axes) s.axes.push_back(a.axis);
    for (const ModelOption& o : def.options) s.params[o.name] = o.default_value;
    return s;
}

namespace {
std::string format_number(double v) {
    std::ostringstream s;
    s.precision(10);
    s << v;
    return s.str();
}
}  // namespace

std::vector<int> definition_axis_order(const TableDefinition& def, const TableSettings& s) {
    auto names = [](const std::vector<std::string>& v) {
        std::string out;
        for (const auto& n : v) out += (out.empty() ? "" : ", ") + n;
        return out;
    };
    std::vector<std::string> want, got;
    for (const AxisSpec& a : def.axes) want.push_back(a.axis.name);
    for (const Axis& a : s.axes) got.push_back(a.name);
    if (got.size() != want.size())
        throw Error("table '" + def.id + "' has " + std::to_string(want.size()) + " axes (" + names(want) +
                    "); got settings for " + std::to_string(got.size()) + " (" + names(got) + ")");
    std::vector<int> order;
    for (const std::string& name : got) {
        const auto it = std::find(want.begin(), want.end(), name);
        if (it == want.end() ||
            std::find(order.begin(), order.end(), static_cast<int>(it - want.begin())) != order.end())
            throw Error("table '" + def.id + "': the axes " + names(got) + " are not an order of its axes " +
                        names(want));
        order.push_back(static_cast<int>(it - want.begin()));
    }
    return order;
}

void validate_settings(const TableDefinition& def, const TableSettings& s) {
    const std::vector<int> order = definition_axis_order(def, s);
    long long texels = 1;
    for (std::size_t i = 0; i < s.axes.size(); ++i) {
        const Axis& a = s.axes[i];
        const AxisSpec& spec = def.axes[static_cast<std::size_t>(order[i])];
        a.validate();
        // Every parameter the axis evaluates, clamps applied, lies in the domain.
        if (a.lowest() < spec.domain_min || a.highest() > spec.domain_max)
            throw Error("table '" + def.id + "': axis '" + a.name + "' range " + format_number(a.min) + ":" +
                        format_number(a.max) + (a.has_clamp() ? " (clamped to " + format_number(a.clamp_lo) + ":" +
                                                                    format_number(a.clamp_hi) + ")"
                                                              : std::string()) +
                        " is outside the model's domain; allowed: within " + format_number(spec.domain_min) + ":" +
                        format_number(spec.domain_max));
        texels *= a.count;
    }
    for (const auto& sum : s.channel_map)
        for (int c : sum)
            if (c < 0 || c >= static_cast<int>(def.channels.size()))
                throw Error("table '" + def.id + "' has " + std::to_string(def.channels.size()) +
                            " channel(s); the channel map names channel " + std::to_string(c + 1));
    if (s.channel_map.size() > 4)
        throw Error("a channel map of " + std::to_string(s.channel_map.size()) +
                    " channels is too long; allowed: at most 4 (R, G, B, A)");
    if (texels > kMaxTexels)
        throw Error("table '" + def.id + "': " + std::to_string(texels) +
                    " texels is too many; allowed: at most " + std::to_string(kMaxTexels));
    for (const auto& param : s.params) {
        const std::string& name = param.first;
        const std::string& value = param.second;
        auto it = std::find_if(def.options.begin(), def.options.end(),
                               [&](const ModelOption& o) { return o.name == name; });
        if (it == def.options.end())
            throw Error("table '" + def.id + "' has no option '" + name + "'");
        if (!it->allowed.empty() &&
            std::find(it->allowed.begin(), it->allowed.end(), value) == it->allowed.end()) {
            std::string allowed;
            for (const auto& v : it->allowed) allowed += (allowed.empty() ? "" : ", ") + v;
            throw Error("--" + name + " '" + value + "' is not allowed for table '" + def.id +
                        "'; allowed: " + allowed);
        }
    }
    if (s.method == Method::monte_carlo && !def.supports_monte_carlo)
        throw Error("table '" + def.id + "' has no Monte Carlo method; allowed: quadrature");
    if (s.method == Method::monte_carlo && (s.samples < 1 || s.samples > (1LL << 32)))
        throw Error("--samples " + std::to_string(s.samples) + " is out of range; allowed: 1 to " +
                    std::to_string(1LL << 32));
}

namespace tables {

AxisSpec cos_theta_axis(int count) {
    return {Axis{"cos_theta", 0.0, 1.0, count, Placement::center, Warp::linear}, 0.0, 1.0,
            "cos(theta_o): cosine of the angle between the view direction and the normal"};
}

AxisSpec alpha_axis(int count) {
    return {Axis{"alpha", 0.0, 1.0, count, Placement::center, Warp::square}, 0.0, 1.0,
            "GGX alpha; the square warp makes the rows linear in perceptual roughness "
            "sqrt(alpha)",
            "roughness"};
}

ModelOption visibility_option(std::vector<std::string> allowed) {
    return {"visibility",
            "microfacet shadowing-masking term: height_correlated Smith G2 = 1/(1 + Lambda(o) + Lambda(i)) "
            "(Heitz 2014), separable G1(o) G1(i), or schlick_smith G1(mu) = mu/(mu (1 - k) + k) with k = "
            "alpha/2 for GGX (Karis 2013) and alpha sqrt(2/pi) for Beckmann (Schlick 1994), or (GGX "
            "reflection only) smith_joint_approx, Unreal's Vis_SmithJointApprox G2 = 2 mu_o mu_i / (mu_i (mu_o "
            "(1 - a) + a) + mu_o (mu_i (1 - a) + a)) with a = alpha; transmission takes Lambda of |cos(theta_i)|",
            "height_correlated", std::move(allowed)};
}

const std::string& param(const TableSettings& s, const std::string& name) {
    auto it = s.params.find(name);
    if (it == s.params.end()) throw Error("option '" + name + "' is missing");
    return it->second;
}

double parse_number(const std::string& option, const std::string& s) {
    std::size_t used = 0;
    double v = 0.0;
    try {
        v = std::stod(s, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (s.empty() || used != s.size() || !std::isfinite(v))
        throw Error("--" + option + " '" + s + "' is not a finite number");
    return v;
}

nlohmann::json quadrature_method(const std::string& rule, double abs_tol) {
    return {{"name", "quadrature"}, {"rule", rule}, {"abs_tolerance", abs_tol}};
}

nlohmann::json monte_carlo_method(const std::string& sampler, const TableSettings& s) {
    return {{"name", "mc"},
            {"sampler", sampler},
            {"samples", s.samples},
            {"seed", s.seed},
            {"rng", "mt19937_64 seeded per texel with SplitMix64(seed, texel index)"},
            {"error", "4 standard errors of the mean"}};
}

}  // namespace tables
}  // namespace brdflut
