#include "tables/recipe.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "brdflut/error.h"
#include "brdflut/microfacet.h"

namespace brdflut::tables {
namespace {

std::string list(const std::vector<std::string>& v) {
    std::string out;
    for (const std::string& s : v) out += (out.empty() ? "" : ", ") + s;
    return out;
}

// The recipe axis that feeds the core axis `name`: one of that name first,
// else one whose square or square root it is.
RecipePlan::Feed feed_of(const RecipeTable& e, const TableDefinition& core, const std::string& name) {
    for (std::size_t i = 0; i < e.axes.size(); ++i)
        if (e.axes[i].axis.name == name) return {static_cast<int>(i), AxisConversion::same};
    for (std::size_t i = 0; i < e.axes.size(); ++i) {
        if (e.axes[i].square_name == name) return {static_cast<int>(i), AxisConversion::square};
        if (e.axes[i].root_name == name) return {static_cast<int>(i), AxisConversion::root};
    }
    for (std::size_t i = 0; i < e.pins.size(); ++i)
        if (e.pins[i].axis == name) return {-1, AxisConversion::same, static_cast<int>(i)};
    std::vector<std::string> names;
    for (const AxisSpec& a : e.axes) names.push_back(a.axis.name);
    throw Error("recipe table '" + e.id + "': no axis feeds axis '" + name + "' of core table '" + core.id +
                "'; its axes (" + list(names) +
                ") feed a core axis of their own name, of their square_name or of their root_name, "
                "and a pin (RecipeTable::pins) holds the axis of its name");
}

double convert(AxisConversion c, double v) {
    switch (c) {
        case AxisConversion::same: return v;
        case AxisConversion::square: return alpha_from_perceptual(v);
        case AxisConversion::root: return std::sqrt(v);
    }
    return v;
}

class RecipeEvaluator final : public TexelEvaluator {
public:
    struct Core {
        std::unique_ptr<TexelEvaluator> evaluator;
        std::vector<RecipePlan::Feed> feeds;
    };

    RecipeEvaluator(std::vector<Core> cores, std::vector<RecipePlan::Channel> channels, std::vector<double> pins)
        : cores_(std::move(cores)), channels_(std::move(channels)), pins_(std::move(pins)) {}

    // Each core table at the texel's coordinates converted to its axes, with
    // the recipe's texel index (its Monte Carlo seed); then per channel the
    // terms in order, the offset last, so that a single term with coef 1
    // and no offset stores the core value to the bit.
    TexelValue evaluate(const double* c, std::uint64_t texel) const override {
        std::array<TexelValue, kMaxRecipeCores> in;
        TexelValue out;
        for (std::size_t i = 0; i < cores_.size(); ++i) {
            double x[3] = {0.0, 0.0, 0.0};
            const std::vector<RecipePlan::Feed>& feeds = cores_[i].feeds;
            for (std::size_t k = 0; k < feeds.size(); ++k)
                x[k] = feeds[k].axis < 0 ? pins_[static_cast<std::size_t>(feeds[k].pin)]
                                         : convert(feeds[k].conversion, c[feeds[k].axis]);
            in[i] = cores_[i].evaluator->evaluate(x, texel);
            out.evaluations += in[i].evaluations;
        }
        for (std::size_t ch = 0; ch < channels_.size(); ++ch) {
            const RecipePlan::Channel& r = channels_[ch];
            auto [value, error] = sum(in, r.terms, r.offset);
            if (r.ratio()) {
                const auto [den, den_error] = sum(in, r.den_terms, r.den_offset);
                const double q = value / den;
                error = (error + std::abs(q) * den_error) / std::abs(den);
                value = q;
            }
            out.value[ch] = value;
            out.error[ch] = error;
        }
        return out;
    }

private:
    // The terms in order, the offset last, so that a single term with coef
    // 1 and no offset gives the core value to the bit: {value, error}.
    static std::array<double, 2> sum(const std::array<TexelValue, kMaxRecipeCores>& in,
                                     const std::vector<RecipePlan::Term>& terms, double offset) {
        double value = offset, error = 0.0;
        for (std::size_t t = 0; t < terms.size(); ++t) {
            const RecipePlan::Term& term = terms[t];
            const auto k = static_cast<std::size_t>(term.channel);
            const TexelValue& v = in[static_cast<std::size_t>(term.core)];
            const double x = term.coef * v.value[k], e = std::abs(term.coef) * v.error[k];
            value = t == 0 ? x : value + x;
            error = t == 0 ? e : error + e;
        }
        if (!terms.empty() && offset != 0.0) value += offset;
        return {value, error};
    }

    std::vector<Core> cores_;
    std::vector<RecipePlan::Channel> channels_;
    std::vector<double> pins_;
};

const TableDefinition* catalogue_table(const std::string& id) {
    for (const TableDefinition& d : catalogue())
        if (d.id == id) return &d;
    return nullptr;
}

}  // namespace

RecipePlan plan_recipe(const RecipeTable& e, const std::function<const TableDefinition*(const std::string&)>& lookup) {
    const std::string what = "recipe table '" + e.id + "'";
    if (e.channels.empty() || e.channels.size() > 4)
        throw Error(what + " has " + std::to_string(e.channels.size()) + " channels; allowed 1 to 4");
    RecipePlan plan;
    auto core_index = [&](const std::string& id) {
        for (std::size_t i = 0; i < plan.cores.size(); ++i)
            if (plan.cores[i].def->id == id) return static_cast<int>(i);
        const TableDefinition* def = lookup(id);
        if (!def) throw Error(what + ": core table '" + id + "' is not in the catalogue");
        if (!def->preset.empty())
            throw Error(what + ": table '" + id + "' belongs to preset '" + def->preset +
                        "'; a recipe reads core tables (no preset) only");
        if (def->axes.size() > 3)
            throw Error(what + ": core table '" + id + "' has " + std::to_string(def->axes.size()) +
                        " axes; allowed 1 to 3");
        if (plan.cores.size() == static_cast<std::size_t>(kMaxRecipeCores))
            throw Error(what + " reads more than " + std::to_string(kMaxRecipeCores) + " core tables ('" + id +
                        "' would be one more)");
        RecipePlan::Core core{def, {}};
        for (const AxisSpec& a : def->axes) core.feeds.push_back(feed_of(e, *def, a.axis.name));
        plan.cores.push_back(core);
        return static_cast<int>(plan.cores.size() - 1);
    };
    for (std::size_t ch = 0; ch < e.channels.size(); ++ch) {
        const ChannelRecipe& r = e.channels[ch];
        if (!std::isfinite(r.offset))
            throw Error(what + " channel " + std::to_string(ch) + ": offset " + std::to_string(r.offset) +
                        " is not finite");
        if (!std::isfinite(r.den_offset))
            throw Error(what + " channel " + std::to_string(ch) + ": denominator offset " +
                        std::to_string(r.den_offset) + " is not finite");
        if (r.den_terms.empty() && r.den_offset == 0.0)
            throw Error(what + " channel " + std::to_string(ch) + ": the denominator is the constant 0");
        auto plan_terms = [&](const std::vector<RecipeTerm>& terms) {
            std::vector<RecipePlan::Term> planned;
            for (const RecipeTerm& t : terms) {
                const int core = core_index(t.table);
                const int count =
                    static_cast<int>(plan.cores[static_cast<std::size_t>(core)].def->channels.size());
                if (t.channel < 0 || t.channel >= count)
                    throw Error(what + " channel " + std::to_string(ch) + ": channel " + std::to_string(t.channel) +
                                " of core table '" + t.table + "' does not exist; allowed 0 to " +
                                std::to_string(count - 1));
                if (!std::isfinite(t.coef))
                    throw Error(what + " channel " + std::to_string(ch) + ": coefficient " +
                                std::to_string(t.coef) + " of '" + t.table + "' is not finite");
                planned.push_back({core, t.channel, t.coef});
            }
            return planned;
        };
        RecipePlan::Channel out{plan_terms(r.terms), r.offset, plan_terms(r.den_terms), r.den_offset};
        plan.channels.push_back(out);
    }
    for (std::size_t i = 0; i < e.pins.size(); ++i) {
        const std::string& name = e.pins[i].axis;
        for (const AxisSpec& a : e.axes)
            if (a.axis.name == name)
                throw Error(what + ": pin '" + name + "' names one of its own axes; a pin holds a core axis "
                                   "that no recipe axis feeds");
        bool feeds = false;
        for (const RecipePlan::Core& core : plan.cores)
            for (const RecipePlan::Feed& f : core.feeds) feeds = feeds || f.pin == static_cast<int>(i);
        if (!feeds) throw Error(what + ": pin '" + name + "' holds no axis of its core tables");
    }
    for (const auto& [name, value] : e.options) {
        std::vector<std::string> known;
        bool taken = false;
        for (const RecipePlan::Core& core : plan.cores)
            for (const ModelOption& o : core.def->options) {
                known.push_back(core.def->id + " --" + o.name);
                if (o.name != name) continue;
                taken = true;
                if (!o.allowed.empty() && std::find(o.allowed.begin(), o.allowed.end(), value) == o.allowed.end())
                    throw Error(what + ": option " + name + " = '" + value + "' is not allowed by core table '" +
                                core.def->id + "'; allowed: " + list(o.allowed));
            }
        if (!taken)
            throw Error(what + ": option '" + name + "' is taken by none of its core tables; their options: " +
                        (known.empty() ? std::string("none") : list(known)));
    }
    return plan;
}

namespace {
// A number as the shortest decimal that reads back to it.
std::string number(double v) {
    char buf[32];
    for (int p = 1; p <= 17; ++p) {
        std::snprintf(buf, sizeof buf, "%.*g", p, v);
        if (std::strtod(buf, nullptr) == v) break;
    }
    return buf;
}

std::string sum_expression(const std::vector<RecipeTerm>& terms, double offset) {
    std::string out;
    for (const RecipeTerm& t : terms) {
        const std::string name = t.table + "." + std::to_string(t.channel);
        const double c = t.coef;
        const std::string mag = std::abs(c) == 1.0 ? name : number(std::abs(c)) + " * " + name;
        if (out.empty())
            out = (c < 0 ? "-" : "") + mag;
        else
            out += (c < 0 ? " - " : " + ") + mag;
    }
    if (out.empty()) return number(offset);
    if (offset == 0.0) return out;
    // A leading negated term with an offset reads as "offset - term".
    if (terms.size() == 1 && terms[0].coef < 0) return number(offset) + " " + out.replace(0, 1, "- ");
    return out + (offset < 0 ? " - " : " + ") + number(std::abs(offset));
}
}  // namespace

std::string channel_expression(const ChannelRecipe& c) {
    const std::string n = sum_expression(c.terms, c.offset);
    if (c.den_terms.empty() && c.den_offset == 1.0) return n;
    return "(" + n + ") / (" + sum_expression(c.den_terms, c.den_offset) + ")";
}

TableDefinition recipe_table(const RecipeTable& entry, const std::string& preset, const RecipeMethod& method) {
    TableDefinition d;
    d.id = entry.id;
    d.description = entry.description;
    d.axes = entry.axes;
    for (const ChannelRecipe& c : entry.channels) d.channels.push_back(c.meaning);
    d.preset = preset;
    d.engine_source = entry.engine_source;
    d.engine_storage = entry.engine_storage;
    for (const ChannelRecipe& c : entry.channels) d.channel_recipes.push_back(channel_expression(c));
    for (const AxisPin& pin : entry.pins) d.options.push_back({pin.axis, pin.help, pin.default_value, {}});
    d.checks = entry.checks;
    // Until resolve_recipe_tables has read the core tables.
    d.supports_monte_carlo = true;
    nlohmann::json model = entry.model;
    model["preset"] = preset;
    model["engine_source"] = entry.engine_source;
    model["recipe"] = d.channel_recipes;
    RecipeTable e = entry;
    e.checks.clear();
    d.prepare = [e, model, method](const TableSettings& s) {
        const RecipePlan plan = plan_recipe(e, catalogue_table);
        // Each pin's value, in the domain of every core axis it holds.
        std::vector<double> pins;
        nlohmann::json out_model = model;
        for (std::size_t i = 0; i < e.pins.size(); ++i) {
            const std::string& name = e.pins[i].axis;
            const double v = parse_number(name, param(s, name));
            for (const RecipePlan::Core& core : plan.cores)
                for (std::size_t k = 0; k < core.feeds.size(); ++k) {
                    if (core.feeds[k].pin != static_cast<int>(i)) continue;
                    const AxisSpec& spec = core.def->axes[k];
                    if (v < spec.domain_min || v > spec.domain_max)
                        throw Error("--" + name + " " + number(v) + " is outside the domain of axis '" + name +
                                    "' of core table '" + core.def->id + "' (table '" + e.id + "'); allowed: " +
                                    number(spec.domain_min) + " to " + number(spec.domain_max));
                }
            pins.push_back(v);
            out_model["pinned"][name] = v;
        }
        std::vector<RecipeEvaluator::Core> cores;
        double tolerance = 0.0;
        for (const RecipePlan::Core& core : plan.cores) {
            TableSettings cs = default_settings(*core.def);
            cs.method = s.method;
            cs.quality = s.quality;
            cs.samples = s.samples;
            cs.seed = s.seed;
            for (const auto* params : {&s.params, &e.options})
                for (const auto& [name, value] : *params)
                    if (cs.params.count(name)) cs.params[name] = value;
            validate_settings(*core.def, cs);
            PreparedTable p = core.def->prepare(cs);
            if (p.finish)
                throw Error("recipe table '" + e.id + "': core table '" + core.def->id +
                            "' gathers table-wide figures after its texels, so it cannot feed a recipe");
            if (p.method.contains("abs_tolerance"))
                tolerance = std::max(tolerance, p.method["abs_tolerance"].get<double>());
            cores.push_back({std::move(p.evaluator), core.feeds});
        }
        PreparedTable out;
        out.evaluator = std::make_unique<RecipeEvaluator>(std::move(cores), plan.channels, std::move(pins));
        out.model = out_model;
        out.method = s.method == Method::monte_carlo ? monte_carlo_method(method.mc_sampler, s)
                                                     : quadrature_method(method.quadrature_rule, tolerance);
        return out;
    };
    return d;
}

void resolve_recipe_tables(const std::vector<RecipeTable>& entries, FamilyEntries& family) {
    auto lookup = [&family](const std::string& id) -> const TableDefinition* {
        for (const TableDefinition& d : family.tables)
            if (d.id == id) return &d;
        return nullptr;
    };
    for (const RecipeTable& e : entries) {
        const RecipePlan plan = plan_recipe(e, lookup);
        bool mc = true, identify = true;
        for (const RecipePlan::Core& core : plan.cores) {
            mc = mc && core.def->supports_monte_carlo;
            identify = identify && core.def->searched_by_identify;
        }
        for (TableDefinition& d : family.tables)
            if (d.id == e.id) {
                d.supports_monte_carlo = mc;
                d.searched_by_identify = identify;
            }
    }
}

}  // namespace brdflut::tables
