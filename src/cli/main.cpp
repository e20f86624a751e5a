// brdflut command line: a thin front end over the library. Only this file
// chooses exit codes: 0 success, 1 failure at run time, 2 usage error.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "brdflut/catalogue.h"
#include "brdflut/error.h"
#include "brdflut/exr.h"
#include "brdflut/generate.h"
#include "brdflut/version.h"
#include "io/atomic_file.h"

namespace {

using namespace brdflut;

constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;

std::string describe_axis(const Axis& a) {
    std::ostringstream s;
    s << a.name << " [" << a.min << ", " << a.max << "] " << a.count << " " << to_string(a.placement)
      << " " << to_string(a.warp);
    return s.str();
}

int run_list() {
    static const char* kAxisLetters[3] = {"x", "y", "z"};
    static const char* kChannels[4] = {"R", "G", "B", "A"};
    for (const TableDefinition& d : catalogue()) {
        std::cout << d.id << "\n  " << d.description << "\n";
        for (std::size_t i = 0; i < d.axes.size(); ++i)
            std::cout << "  " << kAxisLetters[i] << ": " << describe_axis(d.axes[i].axis) << "\n";
        for (std::size_t c = 0; c < d.channels.size(); ++c)
            std::cout << "  " << kChannels[c] << ": " << d.channels[c] << "\n";
        for (const ModelOption& o : d.options) {
            std::cout << "  --" << o.name << " (default " << o.default_value;
            if (!o.allowed.empty()) {
                std::cout << "; allowed:";
                for (const auto& v : o.allowed) std::cout << " " << v;
            }
            std::cout << ")\n";
        }
        std::cout << "  methods: quadrature" << (d.supports_monte_carlo ? ", mc" : "") << "\n\n";
    }
    return 0;
}

// "N" or "NxM".
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

// "name=value"
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

struct GenerateArgs {
    std::vector<std::string> ids;
    bool all = false;
    std::string output = ".";
    std::string size;
    std::string pixel = "float";
    int threads = 0;
    std::string method = "quadrature";
    long long samples = 4096;
    unsigned long long seed = 1;
    bool quiet = false;
    std::vector<std::string> ranges, counts, placements, warps;
    std::map<std::string, std::string> params;  // model options given on the command line
};

class ProgressBar {
public:
    ProgressBar(std::string label, bool enabled) : label_(std::move(label)), enabled_(enabled) {}
    void update(std::size_t done, std::size_t total) {
        if (!enabled_ || total == 0) return;
        const int percent = static_cast<int>(100.0 * static_cast<double>(done) / static_cast<double>(total));
        if (percent == last_) return;
        last_ = percent;
        const int width = 30, filled = percent * width / 100;
        std::fprintf(stderr, "\r%-24s [%s%s] %3d%%", label_.c_str(), std::string(static_cast<std::size_t>(filled), '#').c_str(),
                     std::string(static_cast<std::size_t>(width - filled), ' ').c_str(), percent);
        std::fflush(stderr);
    }
    void finish() {
        if (enabled_ && last_ >= 0) std::fprintf(stderr, "\r%*s\r", 64, "");
    }

private:
    std::string label_;
    bool enabled_;
    int last_ = -1;
};

TableSettings settings_for(const TableDefinition& def, const GenerateArgs& a,
                           std::set<std::string>& used) {
    TableSettings s = default_settings(def);
    if (!a.size.empty()) {
        const std::vector<int> n = parse_size(a.size);
        if (n.size() > def.axes.size())
            throw Error("--size '" + a.size + "' has " + std::to_string(n.size()) + " counts but table '" +
                        def.id + "' has " + std::to_string(def.axes.size()) + " axis(es)");
        for (std::size_t i = 0; i < n.size(); ++i) s.axes[i].count = n[i];
        // A single N sets every axis of a multi-axis table: N x N.
        if (n.size() == 1)
            for (auto& ax : s.axes) ax.count = n[0];
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
            ax->min = parse_double("--range " + name, value.substr(0, colon));
            ax->max = parse_double("--range " + name, value.substr(colon + 1));
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
    for (const auto& [name, value] : a.params) {
        if (s.params.count(name)) {
            s.params[name] = value;
            used.insert("--" + name);
        }
    }
    s.method = method_from_string(a.method);
    s.samples = a.samples;
    s.seed = a.seed;
    return s;
}

int run_generate(const GenerateArgs& a) {
    std::vector<const TableDefinition*> defs;
    if (a.all) {
        if (!a.ids.empty()) throw Error("give table ids or --all, not both");
        for (const auto& d : catalogue()) defs.push_back(&d);
    } else {
        if (a.ids.empty()) throw Error("no table given; name one or more ids (see 'brdflut list') or use --all");
        for (const auto& id : a.ids) defs.push_back(&find_table(id));
    }
    const PixelType pixel = pixel_type_from_string(a.pixel);
    if (a.threads < 0 || a.threads > 1024)
        throw Error("--threads " + std::to_string(a.threads) + " is out of range; allowed: 0 (all cores) to 1024");
    const Method method = method_from_string(a.method);
    if (method == Method::monte_carlo && (a.samples < 1 || a.samples > (1LL << 32)))
        throw Error("--samples " + std::to_string(a.samples) + " is out of range; allowed: 1 to " +
                    std::to_string(1LL << 32));

    // Build and check every table's settings before any work starts.
    std::set<std::string> used;
    std::vector<TableSettings> settings;
    for (const auto* d : defs) {
        settings.push_back(settings_for(*d, a, used));
        validate_settings(*d, settings.back());
    }
    auto unused = [&](const std::string& option, const std::vector<std::string>& values) {
        for (const auto& v : values) {
            const std::string name = v.substr(0, v.find('='));
            if (!used.count(option + " " + name))
                throw Error(option + " '" + v + "': no requested table has an axis named '" + name + "'");
        }
    };
    unused("--range", a.ranges);
    unused("--count", a.counts);
    unused("--placement", a.placements);
    unused("--warp", a.warps);
    for (const auto& [name, value] : a.params)
        if (!used.count("--" + name))
            throw Error("--" + name + " does not apply to any requested table");

    std::error_code ec;
    std::filesystem::create_directories(a.output, ec);
    if (ec || !std::filesystem::is_directory(a.output))
        throw RuntimeError("cannot create output folder '" + a.output + "'" +
                           (ec ? ": " + ec.message() : ""));

    const bool bar = !a.quiet && ::isatty(STDERR_FILENO);
    for (std::size_t i = 0; i < defs.size(); ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        ProgressBar progress(defs[i]->id, bar);
        GenerateOptions opt;
        opt.threads = a.threads;
        opt.progress = [&](std::size_t done, std::size_t total) { progress.update(done, total); };
        const Table table = generate(*defs[i], settings[i], opt);
        progress.finish();
        const std::string path = (std::filesystem::path(a.output) / (table.id + ".exr")).string();
        write_exr(path, table, pixel);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (!a.quiet) {
            std::printf("wrote %s: %dx%d, %d channel(s), %s, error bound %.2e, %.2f s\n", path.c_str(),
                        table.width(), table.height(), table.channel_count(),
                        std::string(to_string(pixel)).c_str(), error_bound(table, pixel), seconds);
        }
    }
    return 0;
}

extern "C" void on_signal(int sig) {
    remove_pending_temporary_files();
    std::signal(sig, SIG_DFL);
    std::raise(sig);
}

}  // namespace

int main(int argc, char** argv) {
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);

    CLI::App app{"brdflut: precomputed BRDF lookup tables, exact to storage precision"};
    app.set_version_flag("--version", std::string(kName) + " " + kVersion);
    app.require_subcommand(1);
    app.footer("Run 'brdflut <command> --help' for the options of a command.");

    app.add_subcommand("list", "List every table with its axes, channels and options");
    CLI::App* gen = app.add_subcommand("generate", "Generate tables as OpenEXR files");
    GenerateArgs g;
    gen->add_option("ids", g.ids, "Table ids (see 'brdflut list')");
    gen->add_flag("--all", g.all, "Generate every table of the catalogue");
    gen->add_option("-o,--output", g.output, "Output folder, created if missing")->capture_default_str();
    gen->add_option("--size", g.size, "Grid size: N (every axis) or NxM (x by y)");
    gen->add_option("--pixel", g.pixel, "Stored pixel type: half or float")->capture_default_str();
    gen->add_option("--threads", g.threads, "Worker threads; 0 uses every core")->capture_default_str();
    gen->add_option("--method", g.method, "Integration: quadrature (deterministic) or mc (Monte Carlo)")
        ->capture_default_str();
    gen->add_option("--samples", g.samples, "Samples per texel with --method mc")->capture_default_str();
    gen->add_option("--seed", g.seed, "Seed with --method mc")->capture_default_str();
    gen->add_option("--range", g.ranges, "Axis range AXIS=MIN:MAX, e.g. alpha=0.01:1 (repeatable)");
    gen->add_option("--count", g.counts, "Axis count AXIS=N (repeatable)");
    gen->add_option("--placement", g.placements, "Axis placement AXIS=center|endpoints (repeatable)");
    gen->add_option("--warp", g.warps, "Axis warp AXIS=linear|square|sqrt|log (repeatable)");
    gen->add_flag("-q,--quiet", g.quiet, "Print nothing but errors");
    // Model options of every table, each registered once.
    std::map<std::string, std::string> option_values;
    std::map<std::string, std::string> option_help;
    for (const TableDefinition& d : catalogue())
        for (const ModelOption& o : d.options) {
            std::string& h = option_help[o.name];
            if (h.empty()) h = o.help;
            h += (h.find(" [tables:") == std::string::npos ? " [tables: " : ", ") + d.id;
        }
    for (auto& [name, help] : option_help) {
        help += "]";
        gen->add_option("--" + name, option_values[name], help);
    }

    const std::vector<std::string> commands{"list", "generate"};
    if (argc > 1 && argv[1][0] != '-' &&
        std::find(commands.begin(), commands.end(), argv[1]) == commands.end()) {
        std::string known;
        for (const auto& c : commands) known += (known.empty() ? "" : ", ") + c;
        std::cerr << "brdflut: error: '" << argv[1] << "' is not a command; allowed: " << known << "\n";
        return kExitUsage;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "brdflut: error: " << e.what() << "\n";
        std::cerr << "Run 'brdflut --help' or 'brdflut <command> --help' for usage.\n";
        return kExitUsage;
    }

    try {
        if (app.got_subcommand("list")) return run_list();
        for (const auto& [name, value] : option_values)
            if (gen->count("--" + name)) g.params[name] = value;
        return run_generate(g);
    } catch (const Error& e) {
        std::cerr << "brdflut: error: " << e.what() << "\n";
        return kExitUsage;
    } catch (const std::exception& e) {
        std::cerr << "brdflut: error: " << e.what() << "\n";
        return kExitFailure;
    }
}
