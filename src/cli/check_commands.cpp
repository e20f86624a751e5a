// verify, compare, inspect and sample: the checking side of the tool.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <cstdio>
#include <optional>
#include <iostream>
#include <sstream>

#include "brdflut/error.h"
#include "brdflut/exr.h"
#include "brdflut/formats.h"
#include "brdflut/lut.h"
#include "brdflut/ltc_compare.h"
#include "brdflut/plot.h"
#include "brdflut/verify.h"
#include "cli/commands.h"

namespace brdflut::cli {
namespace {

std::string axis_line(const Axis& a) {
    std::ostringstream s;
    s << a.name << " [" << a.min << ", " << a.max << "] " << a.count << " " << to_string(a.placement) << " "
      << to_string(a.warp);
    if (a.flip) s << " flipped";
    if (a.has_clamp()) s << " clamped to [" << a.clamp_lo << ", " << a.clamp_hi << "]";
    return s.str();
}

std::string tolerance_text(const Tolerance& t) {
    std::string out;
    if (t.abs > 0 || (t.rel == 0 && t.steps == 0)) out += sci(t.abs);
    if (t.rel > 0) out += (out.empty() ? "" : " + ") + sci(t.rel) + " |exact|";
    if (t.steps > 0) out += (out.empty() ? "" : " + ") + std::string(t.steps == 1 ? "one storage step" : sci(t.steps) + " storage steps");
    return out + " (" + t.source + "), plus the exact values' own error";
}

std::string verdict_line(const CompareReport& rep) {
    const std::size_t values = rep.max_error_map.size() * rep.channels.size();
    if (rep.pass())
        return "PASS: every one of the " + std::to_string(values) + " values is within " + tolerance_text(rep.tolerance);
    std::string line = "FAIL: " + std::to_string(rep.failed_values) + " of the " + std::to_string(values) +
                       " values exceed " + tolerance_text(rep.tolerance);
    return line;
}

struct Described {
    ExrImage image;
    LutDescription lut;
    bool from_metadata = false;
};

Described describe(const DescribeArgs& a) {
    Described d;
    d.image = read_table_image(a.file, read_options(a.read));
    if (a.as.empty()) {
        if (a.table.layout_given())
            throw Error("axis, layout and model options describe a foreign file and need --as <table id>");
        d.lut = describe_from_metadata(d.image, a.file);
        d.from_metadata = true;
    } else {
        const TableDefinition& def = find_table(a.as);
        TableArgs t = a.table;
        // A flat array (a source array of one dimension, given no --shape)
        // takes its shape from the table's layout.
        const bool flat = def.axes.size() >= 2 && is_flat(d.image) && a.read.shape.empty();
        if (t.size.empty() && !flat) {
            // Default grid: the image's own size.
            if (def.axes.size() == 1) {
                if (d.image.height != 1)
                    throw RuntimeError("'" + a.file + "' has " + std::to_string(d.image.height) +
                                       " rows but table '" + def.id + "' is 1-D");
                t.size = std::to_string(d.image.width);
            } else if (def.axes.size() == 2) {
                t.size = std::to_string(d.image.width) + "x" + std::to_string(d.image.height);
            }
        }
        std::set<std::string> used;
        d.lut.def = &def;
        d.lut.settings = settings_for(def, t, used);
        check_all_used(t, used);
        if (flat) reshape_flat(d.image, d.lut.settings.axes, static_cast<int>(def.channels.size()), a.file);
        // Without --channels, the file's first channels hold the table's.
        if (d.lut.settings.channel_map.empty() && d.image.channel_names.size() < def.channels.size())
            for (std::size_t c = 0; c < d.image.channel_names.size(); ++c)
                d.lut.settings.channel_map.push_back({static_cast<int>(c)});
        validate_settings(def, d.lut.settings);
    }
    check_fits(d.image, d.lut, a.file);
    return d;
}

}  // namespace

int run_verify(const VerifyArgs& a) {
    std::vector<const TableDefinition*> defs;
    if (a.ids.empty())
        for (const auto& d : catalogue()) defs.push_back(&d);
    for (const auto& id : a.ids) defs.push_back(&find_table(id));
    if (a.samples < 100 || a.samples > 100000000)
        throw Error("--samples " + std::to_string(a.samples) + " is out of range; allowed: 100 to 100000000");
    VerifyOptions opt;
    opt.mc_samples = a.samples;
    std::vector<CheckRow> rows;
    bool ok = true;
    if (!a.json)
        std::printf("%-28s %-72s %-10s %-10s %s\n", "table", "check", "max error", "tolerance", "result");
    for (const auto* d : defs) {
        std::vector<CheckRow> r = verify_table(*d, opt);
        if (r.empty()) r.push_back({d->id, "no independent check available", 0.0, 0.0, true, ""});
        for (const CheckRow& row : r) {
            ok = ok && row.pass;
            if (!a.json) {
                std::printf("%-28s %-72s %-10s %-10s %s%s\n", row.table.c_str(), row.check.c_str(),
                            sci(row.max_error).c_str(), sci(row.tolerance).c_str(), row.pass ? "pass" : "FAIL",
                            row.where.empty() ? "" : ("  (" + row.where + ")").c_str());
                std::fflush(stdout);
            }
            rows.push_back(row);
        }
    }
    if (a.json) {
        nlohmann::json j = nlohmann::json::array();
        for (const CheckRow& r : rows)
            j.push_back({{"table", r.table}, {"check", r.check}, {"max_error", r.max_error},
                         {"tolerance", r.tolerance}, {"pass", r.pass}, {"where", r.where}});
        std::cout << nlohmann::json{{"pass", ok}, {"checks", j}}.dump(2) << "\n";
    } else {
        std::size_t failed = 0;
        for (const CheckRow& r : rows) failed += r.pass ? 0 : 1;
        std::printf("%zu checks: %zu passed, %zu failed\n", rows.size(), rows.size() - failed, failed);
    }
    return ok ? 0 : kExitFailure;
}

int run_compare(const CompareArgs& a) {
    if (a.worst < 0 || a.worst > 100000)
        throw Error("--worst " + std::to_string(a.worst) + " is out of range; allowed: 0 to 100000");
    const Tolerance given = a.tolerance.empty() ? Tolerance{} : parse_tolerance(a.tolerance);
    Described d = describe(a.describe);
    if (!a.transform.empty()) d.lut.values = value_transform_from_string(a.transform);
    const Tolerance tol = a.tolerance.empty() ? default_tolerance(d.image) : given;
    const CompareReport rep = compare_lut(d.image, d.lut, a.threads, static_cast<std::size_t>(a.worst), tol);
    const auto& axes = d.lut.settings.axes;
    // An LTC matrix is judged by the light it gives, not by its coefficients.
    std::optional<LtcComparison> ltc;
    if (is_ltc_matrix_table(d.lut.def->id)) ltc = compare_ltc_light(d.image, d.lut, a.threads);
    if (!a.plot.empty()) {
        if (axes.size() > 2) throw Error("--plot: 3-D tables cannot be drawn as one heatmap");
        Heatmap h;
        h.title = "compare " + std::filesystem::path(a.describe.file).filename().string() + " with exact " + d.lut.def->id;
        h.x = {axes[0].name, axes[0]};
        h.y = axes.size() > 1 ? HeatmapAxis{axes[1].name, axes[1]}
                              : HeatmapAxis{"(1-D table)", Axis{"none", 0.0, 1.0, 1, Placement::center, Warp::linear}};
        // log10 of the largest error over the channels; exact zeros at the floor.
        for (double e : rep.max_error_map) h.values.push_back(std::log10(std::max(e, 1e-12)));
        h.colorbar_label = "log10 |stored - exact| (max over channels)";
        write_heatmap_png(a.plot, h);
    }
    if (a.json) {
        nlohmann::json j;
        j["file"] = a.describe.file;
        j["table"] = d.lut.def->id;
        j["described_by"] = d.from_metadata ? "metadata" : "command line";
        j["transform"] = std::string(to_string(d.lut.values));
        nlohmann::json ch = nlohmann::json::array();
        for (const auto& c : rep.channels) {
            ch.push_back({{"channel", c.channel}, {"max_abs_error", c.max_abs}, {"rms_error", c.rms}});
            if (a.relative) ch.back()["max_rel_error"] = c.max_rel;
        }
        j["channels"] = ch;
        nlohmann::json w = nlohmann::json::array();
        for (const auto& t : rep.worst) {
            nlohmann::json p;
            for (std::size_t i = 0; i < axes.size(); ++i) p[axes[i].name] = t.params[i];
            w.push_back({{"params", p}, {"channel", t.channel}, {"stored", t.stored}, {"exact", t.exact}, {"error", t.error}});
        }
        j["worst"] = w;
        j["exact_error_bound"] = rep.exact_error_bound;
        if (ltc)
            j["ltc_light_error"] = {{"stored_max", ltc->stored_light_max}, {"stored_median", ltc->stored_light_median},
                                    {"refit_max", ltc->refit_light_max}, {"refit_median", ltc->refit_light_median},
                                    {"refit_better_texels", ltc->refit_better}, {"texels", ltc->texels},
                                    {"stored_below_horizon_max", ltc->stored_below_horizon_max},
                                    {"stored_per_texel", ltc->stored_light}, {"refit_per_texel", ltc->refit_light}};
        j["verdict"] = {{"pass", rep.pass()},
                        {"tolerance", {{"abs", tol.abs}, {"rel", tol.rel}, {"storage_steps", tol.steps},
                                       {"source", tol.source}}},
                        {"failed_values", rep.failed_values},
                        {"values", rep.max_error_map.size() * rep.channels.size()}};
        std::cout << j.dump(2) << "\n";
        return rep.pass() ? 0 : kExitFailure;
    }
    std::printf("file:  %s\ntable: %s (described by %s)\n", a.describe.file.c_str(), d.lut.def->id.c_str(),
                d.from_metadata ? "its metadata" : "the command line");
    if (d.lut.values == ValueTransform::srgb) std::printf("values: the sRGB EOTF of the table's values\n");
    for (const Axis& ax : axes) std::printf("axis:  %s\n", axis_line(ax).c_str());
    std::printf("\n%-8s %-14s %-14s\n", "channel", "max |error|", "rms error");
    for (const auto& c : rep.channels) std::printf("%-8s %-14s %-14s\n", c.channel.c_str(), sci(c.max_abs).c_str(), sci(c.rms).c_str());
    if (a.relative) {
        std::printf("\n%-8s %-22s %s\n", "channel", "max |error|/|exact|", "at");
        for (const auto& c : rep.channels) {
            std::string where;
            for (std::size_t i = 0; i < axes.size() && i < c.max_rel_params.size(); ++i) {
                char buf[96];
                std::snprintf(buf, sizeof buf, "%s%s = %.6g", i ? ", " : "", axes[i].name.c_str(), c.max_rel_params[i]);
                where += buf;
            }
            std::printf("%-8s %-22s %s\n", c.channel.c_str(), sci(c.max_rel).c_str(), where.c_str());
        }
    }
    if (!rep.worst.empty()) std::printf("\nworst texels:\n");
    for (const auto& t : rep.worst) {
        std::string where;
        for (std::size_t i = 0; i < axes.size(); ++i) {
            char buf[96];
            std::snprintf(buf, sizeof buf, "%s%s = %.6g", i ? ", " : "", axes[i].name.c_str(), t.params[i]);
            where += buf;
        }
        std::printf("  %s, channel %s: stored %.9g, exact %.9g, error %+.3e\n", where.c_str(), t.channel.c_str(), t.stored,
                    t.exact, t.error);
    }
    std::printf("\n(the exact values themselves are within %s)\n", sci(rep.exact_error_bound).c_str());
    if (ltc)
        std::printf("\nintegrated-light error over the light bank (fraction of n0, exact n0):\n"
                    "  stored: max %s, median %s (LTC mass below the horizon up to %s)\n"
                    "  refit:  max %s, median %s; lower at %zu of %zu texels\n",
                    sci(ltc->stored_light_max).c_str(), sci(ltc->stored_light_median).c_str(),
                    sci(ltc->stored_below_horizon_max).c_str(), sci(ltc->refit_light_max).c_str(),
                    sci(ltc->refit_light_median).c_str(), ltc->refit_better, ltc->texels);
    std::printf("\n%s\n", verdict_line(rep).c_str());
    return rep.pass() ? 0 : kExitFailure;
}

ReadOptions read_options(const ReadArgs& a) {
    ReadOptions o;
    o.array = a.array;
    if (!a.shape.empty()) o.shape = parse_array_shape(a.shape);
    if (!a.decode.empty()) o.decode = decode_from_string(a.decode);
    return o;
}

namespace {
// JSON indented by two spaces, with each array of numbers or strings on
// one line (per-channel figures read as a row).
void dump_with_flat_arrays(const nlohmann::json& j, int indent, std::string& out) {
    const bool container = j.is_object() || j.is_array();
    const bool flat = j.is_array() && std::all_of(j.begin(), j.end(), [](const nlohmann::json& e) { return e.is_primitive(); });
    if (!container || j.empty() || flat) {
        out += j.dump();
        return;
    }
    const std::string pad(static_cast<std::size_t>(indent), ' ');
    out += j.is_object() ? "{\n" : "[\n";
    bool first = true;
    for (auto it = j.begin(); it != j.end(); ++it) {
        out += (first ? "" : ",\n") + pad + "  ";
        first = false;
        if (j.is_object()) out += nlohmann::json(it.key()).dump() + ": ";
        dump_with_flat_arrays(*it, indent + 2, out);
    }
    out += "\n" + pad + (j.is_object() ? "}" : "]");
}
}  // namespace

int run_inspect(const std::string& file, const ReadArgs& read, bool json, const std::string& member) {
    const ExrImage img = read_table_image(file, read_options(read));
    if (!member.empty()) {
        if (!img.has_metadata) throw Error("--metadata " + member + ": " + file + " has no brdflut metadata");
        nlohmann::json::json_pointer ptr;
        try {
            ptr = nlohmann::json::json_pointer(member);
        } catch (const nlohmann::json::exception&) {
            throw Error("--metadata '" + member + "' is not a JSON pointer; allowed: /member/member..., e.g. /method");
        }
        std::string text;
        try {
            dump_with_flat_arrays(img.metadata.at(ptr), 0, text);
        } catch (const nlohmann::json::exception&) {
            std::string names;
            for (const auto& [k, v] : img.metadata.items()) names += (names.empty() ? "" : ", ") + k;
            throw Error("--metadata " + member + ": the file's metadata has no such member; its top level: " + names);
        }
        std::cout << text << "\n";
        return 0;
    }
    const std::vector<ChannelStats> stats = channel_stats(img);
    if (json) {
        nlohmann::json j;
        j["file"] = file;
        j["width"] = img.width;
        j["height"] = img.height;
        j["depth"] = img.depth;
        j["pixel"] = img.stored_as();
        j["metadata"] = img.has_metadata ? img.metadata : nlohmann::json(nullptr);
        nlohmann::json ch = nlohmann::json::array();
        for (const auto& s : stats)
            ch.push_back({{"channel", s.channel}, {"min", s.min}, {"max", s.max}, {"mean", s.mean}, {"non_finite", s.non_finite}});
        j["channels"] = ch;
        std::cout << j.dump(2) << "\n";
        return 0;
    }
    const std::string slices = img.depth > 1 ? " (" + std::to_string(img.depth) + " slices of " +
                                                   std::to_string(img.height / img.depth) + " rows)"
                                             : std::string();
    std::printf("file:   %s\nsize:   %dx%d%s, %zu channel(s), %s\n", file.c_str(), img.width, img.height,
                slices.c_str(), img.channel_names.size(), std::string(img.stored_as()).c_str());
    std::printf("\n%-8s %-14s %-14s %-14s %s\n", "channel", "min", "max", "mean", "non-finite");
    for (const auto& s : stats)
        std::printf("%-8s %-14.7g %-14.7g %-14.7g %lld\n", s.channel.c_str(), s.min, s.max, s.mean, s.non_finite);
    if (img.has_metadata) std::printf("\nmetadata (%s):\n%s\n", kMetadataAttribute, img.metadata.dump(2).c_str());
    else std::printf("\nno brdflut metadata\n");
    return 0;
}

int run_sample(const SampleArgs& a) {
    const Described d = describe(a.describe);
    const auto& axes = d.lut.settings.axes;
    std::vector<double> params(axes.size(), std::nan(""));
    std::stringstream ss(a.at);
    std::string item;
    while (std::getline(ss, item, ',')) {
        const auto [name, value] = split_assignment("--at", item);
        bool found = false;
        for (std::size_t i = 0; i < axes.size(); ++i)
            if (axes[i].name == name) {
                params[i] = parse_double("--at " + name, value);
                found = true;
            }
        if (!found) {
            std::string names;
            for (const Axis& ax : axes) names += (names.empty() ? "" : ", ") + ax.name;
            throw Error("--at '" + item + "': the table has no axis '" + name + "'; its axes: " + names);
        }
    }
    for (std::size_t i = 0; i < axes.size(); ++i)
        if (std::isnan(params[i])) throw Error("--at must give a value for axis '" + axes[i].name + "'");
    for (std::size_t c = 0; c < d.image.channel_names.size(); ++c)
        std::printf("%s = %.9g\n", d.image.channel_names[c].c_str(), sample_lut(d.image, d.lut, params, static_cast<int>(c)));
    for (std::size_t i = 0; i < axes.size(); ++i)  // a decreasing axis has min > max
        if (params[i] < std::min(axes[i].min, axes[i].max) || params[i] > std::max(axes[i].min, axes[i].max))
            std::fprintf(stderr, "note: %s = %g is outside the table's range [%g, %g]; clamped to the edge\n",
                         axes[i].name.c_str(), params[i], axes[i].min, axes[i].max);
    return 0;
}

}  // namespace brdflut::cli
