#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <unistd.h>

#include "brdflut/error.h"
#include "brdflut/formats.h"
#include "brdflut/generate.h"
#include "brdflut/shader.h"
#include "cli/commands.h"
#include "io/table_checks.h"

namespace brdflut::cli {
namespace {

std::string describe_axis(const Axis& a) {
    std::ostringstream s;
    s << a.name << " [" << a.min << ", " << a.max << "] " << a.count << " " << to_string(a.placement) << " "
      << to_string(a.warp);
    return s.str();
}

class ProgressBar {
public:
    ProgressBar(std::string label, bool enabled) : label_(std::move(label)), enabled_(enabled) {}
    void update(std::size_t done, std::size_t total) {
        if (!enabled_ || total == 0) return;
        const int percent = static_cast<int>(100.0 * static_cast<double>(done) / static_cast<double>(total));
        if (percent == last_) return;
        last_ = percent;
        const int width = 30, filled = percent * width / 100;
        std::fprintf(stderr, "\r%-24s [%s%s] %3d%%", label_.c_str(),
                     std::string(static_cast<std::size_t>(filled), '#').c_str(),
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

}  // namespace

bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) != 0; }

int run_list(bool presets_only, bool json) {
    static const char* kAxisLetters[3] = {"x", "y", "z"};
    static const char* kChannels[4] = {"R", "G", "B", "A"};
    if (json) {
        nlohmann::json j = catalogue_json();
        if (presets_only) j = {{"presets", j["presets"]}};
        std::cout << j.dump(2) << "\n";
        return 0;
    }
    if (presets_only) {
        for (const Preset& p : presets()) {
            std::cout << p.name << "\n  " << p.description << "\n  tables:";
            for (const TableDefinition* d : preset_tables(p.name)) {
                std::cout << " " << d->id;
                if (d->engine_storage) std::cout << " [engine: " << to_string(*d->engine_storage) << "]";
            }
            std::cout << " (" << to_string(p.pixel) << ")\n\n";
        }
        return 0;
    }
    for (const TableDefinition& d : catalogue()) {
        std::cout << d.id << (d.preset.empty() ? "" : " [preset: " + d.preset + "]") << "\n  " << d.description
                  << "\n";
        for (std::size_t i = 0; i < d.axes.size(); ++i)
            std::cout << "  " << kAxisLetters[i] << ": " << describe_axis(d.axes[i].axis) << "\n";
        for (std::size_t c = 0; c < d.channels.size(); ++c)
            std::cout << "  " << kChannels[c] << ": " << d.channels[c]
                      << (c < d.channel_recipes.size() ? " = " + d.channel_recipes[c] : std::string()) << "\n";
        if (!d.engine_source.empty()) std::cout << "  source: " << d.engine_source << "\n";
        if (d.engine_storage)
            std::cout << "  engine storage: " << to_string(*d.engine_storage)
                      << " (generate writes it in the formats that hold it unless --pixel or --encoding is given)\n";
        for (const ModelOption& o : d.options) {
            std::cout << "  --" << o.name;
            if (!o.default_value.empty()) std::cout << " (default " << o.default_value;
            else std::cout << " (no default";
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

int run_generate(const GenerateArgs& a) {
    std::vector<const TableDefinition*> defs;
    PixelType pixel = pixel_type_from_string(a.pixel);
    if (!a.preset.empty()) {
        if (a.all || !a.ids.empty()) throw Error("give table ids, --all or --preset, only one of them");
        defs = preset_tables(a.preset);
        if (!a.pixel_given) pixel = find_preset(a.preset).pixel;
    } else if (a.all) {
        if (!a.ids.empty()) throw Error("give table ids or --all, not both");
        for (const auto& d : catalogue())
            if (d.preset.empty()) defs.push_back(&d);
    } else {
        if (a.ids.empty()) throw Error("no table given; name one or more ids (see 'brdflut list'), --all or --preset NAME");
        for (const auto& id : a.ids) defs.push_back(&find_table(id));
    }
    const Format format = format_from_string(a.format);
    if (format == Format::png16 && pixel == PixelType::half && a.pixel_given && a.encoding.empty())
        throw Error("--pixel half does not apply to --format png16, which stores 16-bit integers round(v * 65535)");
    if (!a.encoding.empty() && a.pixel_given) throw Error("give --pixel or --encoding, not both");
    // A preset's half pixels in a format without half: the format's own storage.
    const Storage storage = a.encoding.empty() ? storage_for(format, pixel) : storage_from_string(a.encoding);
    check_format_holds(format, storage);
    // Each table's storage: a preset table's engine encoding where the format
    // holds it and no --pixel or --encoding was given, else `storage`.
    const auto storage_of_table = [&](const TableDefinition& d) {
        const bool engine = a.encoding.empty() && !a.pixel_given && d.engine_storage &&
                            format_holds(format, *d.engine_storage);
        return engine ? *d.engine_storage : storage;
    };
    // The lookup functions read linear values; rgbd needs its decode after filtering.
    if (!a.shaders.empty())
        for (const TableDefinition* d : defs)
            if (storage_of_table(*d) == Storage::rgbd)
                throw Error("--shader does not apply to " +
                            (a.encoding.empty() ? d->id + "'s engine encoding rgbd" : std::string("--encoding rgbd")) +
                            ": the lookup functions read linear values, and rgbd needs its decode (fromRGBD) after "
                            "filtering; allowed with --shader: half, float, unorm16, unorm8, rgb10a2 (--pixel or "
                            "--encoding)");
    std::vector<ShaderLanguage> shaders;
    for (const std::string& s : a.shaders) {
        try {
            shaders.push_back(shader_language_from_string(s));
        } catch (const Error& e) {
            throw Error(std::string("--shader: ") + e.what());
        }
    }
    if (a.threads < 0 || a.threads > 1024)
        throw Error("--threads " + std::to_string(a.threads) + " is out of range; allowed: 0 (all cores) to 1024");
    const Method method = method_from_string(a.table.method);
    if (method == Method::monte_carlo && (a.table.samples < 1 || a.table.samples > (1LL << 32)))
        throw Error("--samples " + std::to_string(a.table.samples) + " is out of range; allowed: 1 to " +
                    std::to_string(1LL << 32));

    // Build and check every table's settings before any work starts.
    std::set<std::string> used;
    std::vector<TableSettings> settings;
    for (const auto* d : defs) {
        if (method == Method::monte_carlo && !d->supports_monte_carlo && a.all) {
            settings.push_back({});
            continue;  // --all --method mc: tables without a Monte Carlo route are skipped below
        }
        settings.push_back(settings_for(*d, a.table, used));
        validate_settings(*d, settings.back());
    }
    check_all_used(a.table, used);

    std::error_code ec;
    std::filesystem::create_directories(a.output, ec);
    if (ec || !std::filesystem::is_directory(a.output))
        throw RuntimeError("cannot create output folder '" + a.output + "'" + (ec ? ": " + ec.message() : ""));

    // Every table is computed and checked against the storage before the
    // first file is written, so a table that cannot be stored (a value
    // outside png16's [0, 1], say) leaves no partial set of files behind.
    const bool bar = !a.quiet && stderr_is_terminal();
    std::vector<Table> tables;
    std::vector<Storage> storages;
    std::vector<double> seconds;
    for (std::size_t i = 0; i < defs.size(); ++i) {
        if (settings[i].axes.empty()) {
            if (!a.quiet) std::printf("skipped %s: it has no Monte Carlo method\n", defs[i]->id.c_str());
            continue;
        }
        const auto t0 = std::chrono::steady_clock::now();
        ProgressBar progress(defs[i]->id, bar);
        GenerateOptions opt;
        opt.threads = a.threads;
        opt.progress = [&](std::size_t done, std::size_t total) { progress.update(done, total); };
        tables.push_back(generate(*defs[i], settings[i], opt));
        progress.finish();
        seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        storages.push_back(storage_of_table(*defs[i]));
        check_storable(tables.back(), storages.back());
    }
    for (std::size_t i = 0; i < tables.size(); ++i) {
        const Table& table = tables[i];
        const std::string path =
            (std::filesystem::path(a.output) / (table.id + "." + file_extension(format))).string();
        const Storage storage_i = storages[i];
        write_table(path, table, storage_i, format);
        for (const ShaderLanguage lang : shaders) {
            const std::string shader_path =
                (std::filesystem::path(a.output) / (table.id + "." + shader_extension(lang))).string();
            write_shader(shader_path, table, storage_i, lang);
            if (!a.quiet) std::printf("wrote %s\n", shader_path.c_str());
        }
        if (!a.quiet) {
            std::printf("wrote %s: %dx%d, %d channel(s), %s, error bound %.2e, %.2f s\n", path.c_str(),
                        table.width(), table.height(), table.channel_count(),
                        std::string(to_string(storage_i)).c_str(), error_bound(table, storage_i), seconds[i]);
            std::fflush(stdout);
        }
    }
    return 0;
}

}  // namespace brdflut::cli
