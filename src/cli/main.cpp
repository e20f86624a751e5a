// brdflut command line: a thin front end over the library. Only this file
// chooses exit codes: 0 success, 1 failure at run time, 2 usage error.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <csignal>
#include <iostream>
#include <string>
#include <vector>

#include "brdflut/error.h"
#include "brdflut/version.h"
#include "cli/commands.h"
#include "io/atomic_file.h"

namespace {

using namespace brdflut;
using namespace brdflut::cli;

extern "C" void on_signal(int sig) {
    remove_pending_temporary_files();
    std::signal(sig, SIG_DFL);
    std::raise(sig);
}

constexpr const char* kFileHelp =
    "The LUT file: OpenEXR, DDS, KTX2, PNG, NumPy .npy, or a source file (C, C++, GLSL, HLSL, JavaScript) with --array";

void add_read_options(CLI::App& app, ReadArgs& r) {
    app.add_option("--array", r.array, "Read the initializer of this array in a source file");
    app.add_option("--shape", r.shape,
                   "Shape of a source array or .npy data: W, WxH or WxHxD, optionally :C channels, interleaved, or :Cp, stored as planes (e.g. 32x32, 64x64:2, 32x32:3p)");
    app.add_option("--decode", r.decode,
                   "How integer samples become numbers: linear (q/255, q/65535), srgb (then the sRGB EOTF) or rgbd "
                   "(8-bit RGBA as Babylon.js's RGBD: (q/255)^2.2 / (a/255)); required for a PNG without brdflut "
                   "metadata");
}

void add_describe_options(CLI::App& app, DescribeArgs& d) {
    app.add_option("file", d.file, kFileHelp)->required();
    add_read_options(app, d.read);
    app.add_option("--as", d.as, "Table id of a foreign file (one without brdflut metadata)");
    add_table_options(app, d.table, false);
}

// Options from a TOML file (CLI11's reader) for every option not given on
// the command line: keys are the long option names without dashes.
void apply_config(CLI::App& app, const std::string& path) {
    std::vector<CLI::ConfigItem> items;
    try {
        items = CLI::ConfigTOML().from_file(path);
    } catch (const CLI::Error& e) {
        throw RuntimeError("cannot read config '" + path + "': " + e.what());
    }
    for (const CLI::ConfigItem& item : items) {
        if (item.name == "++" || item.name == "--") continue;  // section markers
        const std::string key = item.fullname();
        CLI::Option* opt = app.get_option_no_throw("--" + key);
        if (!opt) opt = app.get_option_no_throw(key);
        if (!opt || key == "config")
            throw Error("config '" + path + "': key '" + key + "' is not an option of 'generate'");
        if (opt->count() > 0) continue;  // the command line wins
        try {
            opt->add_result(item.inputs);
            opt->run_callback();
        } catch (const CLI::Error& e) {
            throw Error("config '" + path + "': " + key + ": " + e.what());
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
    // A file-size limit (ulimit -f) then fails the write with an error that
    // is reported, instead of killing the process mid-file.
    std::signal(SIGXFSZ, SIG_IGN);

    CLI::App app{"brdflut: precomputed BRDF lookup tables, exact to storage precision", "brdflut"};
    app.set_version_flag("--version", std::string(kName) + " " + kVersion);
    app.require_subcommand(1);
    app.footer("Run 'brdflut <command> --help' for the options of a command.");

    CLI::App* lst = app.add_subcommand("list", "List every table with its axes, channels and options");
    bool list_presets = false, list_json = false;
    lst->add_flag("--presets", list_presets, "List the engine presets only");
    lst->add_flag("--json", list_json, "Print the catalogue (tables, families, presets) as JSON");

    CLI::App* docs = app.add_subcommand("docs", "Write the reference pages (docs/reference) from the catalogue");
    std::string docs_output = "docs/reference";
    bool docs_check = false;
    docs->add_option("-o,--output", docs_output, "Folder of the pages, created if missing")->capture_default_str();
    docs->add_flag("--check", docs_check, "Write nothing; exit 1 if the pages in the folder differ from the catalogue's");

    CLI::App* gen = app.add_subcommand("generate", "Generate tables as OpenEXR, C++ header, 16-bit PNG, DDS or KTX2 files");
    GenerateArgs g;
    gen->add_option("ids", g.ids, "Table ids (see 'brdflut list')");
    gen->add_flag("--all", g.all, "Generate every table of the default set (not the presets)");
    gen->add_option("--preset", g.preset, "Generate every table of an engine preset (see 'brdflut list --presets')");
    gen->add_option("-o,--output", g.output, "Output folder, created if missing")->capture_default_str();
    gen->add_option("--pixel", g.pixel, "Stored pixel type: half or float")->capture_default_str();
    gen->add_option("--format", g.format,
                    "File format: exr, cpp (C++17 header), png16 (values in [0, 1] only), png (8- or 16-bit), dds or ktx2")
        ->capture_default_str();
    gen->add_option("--encoding", g.encoding,
                    "How values are stored, instead of --pixel: half, float, unorm16, unorm8, rgb10a2 (dds, ktx2) or "
                    "rgbd (Babylon.js RGBD in RGBA8); integer encodings round to nearest and refuse values out of "
                    "range");
    gen->add_option("--shader", g.shaders,
                    "Also write a lookup function <id>.glsl or <id>.hlsl beside each table (glsl or hlsl; repeatable)");
    gen->add_option("--threads", g.threads, "Worker threads; 0 uses every core")->capture_default_str();
    gen->add_flag("-q,--quiet", g.quiet, "Print nothing but errors");
    std::string config_file;
    gen->add_option("--config", config_file,
                    "Read generate options from a TOML file, keys named as the long options (command-line options win)");
    add_table_options(*gen, g.table, true);

    CLI::App* ver = app.add_subcommand("verify", "Check tables against closed forms and Monte Carlo");
    VerifyArgs v;
    ver->add_option("ids", v.ids, "Table ids (default: every table)");
    ver->add_flag("--json", v.json, "Print the results as JSON");
    ver->add_option("--samples", v.samples, "Monte Carlo samples per checked texel")->capture_default_str();

    CLI::App* fur = app.add_subcommand("furnace", "White-furnace report: albedo of every BRDF model over its parameters");
    FurnaceArgs f;
    fur->add_option("models", f.models, "Model ids (default: every model)");
    fur->add_flag("--json", f.json, "Print the report as JSON");
    fur->add_option("--size", f.size, "Grid points per axis")->capture_default_str();
    fur->add_option("--threads", f.threads, "Worker threads; 0 uses every core");
    fur->add_option("--tolerance", f.tolerance,
                    "Allowed |E - 1| for the models meant to conserve energy (default: each model's own)");
    fur->add_option("--plot", f.plot, "Folder for one PNG heatmap per model (furnace_<model>.png)");

    CLI::App* cmp = app.add_subcommand("compare", "Compare a LUT file with exact values");
    CompareArgs c;
    add_describe_options(*cmp, c.describe);
    cmp->add_flag("--json", c.json, "Print the report as JSON");
    cmp->add_option("--worst", c.worst, "How many of the worst texels to list")->capture_default_str();
    cmp->add_option("--threads", c.threads, "Worker threads for the exact values; 0 uses every core");
    cmp->add_option("--plot", c.plot, "Write a PNG heatmap of log10 |stored - exact| to this file");
    cmp->add_option("--tolerance", c.tolerance,
                    "Largest allowed |stored - exact|: X (absolute) or X% (of the exact value); default: the "
                    "file's error_bound, or one storage step of a foreign file's pixel type. Exit 1 when exceeded");
    cmp->add_flag("--relative", c.relative,
                  "Also print each channel's largest |stored - exact| / |exact| and where (over the values the "
                  "pixel type resolves to 0.1%)");
    cmp->add_option("--transform", c.transform,
                    "What the file holds of the table's values: none (default) or srgb (their sRGB EOTF, as a "
                    "linear table decoded or sampled as sRGB reads)");

    CLI::App* idf = app.add_subcommand("identify", "Find which table and layout a LUT of unknown convention holds");
    IdentifyArgs id;
    idf->add_option("file", id.file, kFileHelp)->required();
    add_read_options(*idf, id.read);
    idf->add_option("--top", id.top, "How many explanations to print")->capture_default_str();
    idf->add_flag("--json", id.json, "Print the explanations as JSON");
    idf->add_option("--threads", id.threads, "Worker threads; 0 uses every core");

    CLI::App* ins = app.add_subcommand("inspect", "Show a LUT file's metadata and channel statistics");
    std::string inspect_file;
    bool inspect_json = false;
    ReadArgs inspect_read;
    ins->add_option("file", inspect_file, kFileHelp)->required();
    add_read_options(*ins, inspect_read);
    ins->add_flag("--json", inspect_json, "Print as JSON");
    std::string inspect_member;
    ins->add_option("--metadata", inspect_member,
                    "Print only this member of the brdflut metadata, as a JSON pointer, e.g. /method/separable_error");

    CLI::App* smp = app.add_subcommand("sample", "Value of a LUT at a parameter point, filtered as a GPU does");
    SampleArgs s;
    add_describe_options(*smp, s.describe);
    smp->add_option("--at", s.at, "Parameter point, e.g. cos_theta=0.5,alpha=0.1")->required();

    CLI::App* mtl = app.add_subcommand(
        "metals", "RGB colours of the metal presets from their measured spectra (CIE 1931 observer, D65)");
    MetalsArgs metals;
    mtl->add_option("--colour-space", metals.colour_space,
                    "RGB space: srgb (Rec.709 primaries, D65), acescg (AP1, the ACES white) or rec2020 (D65)")
        ->capture_default_str();
    mtl->add_option("--metal", metals.metal, "Only this metal (a --metal name of fresnel_conductor)");
    mtl->add_flag("--json", metals.json, "Print as JSON");

    const std::vector<std::string> commands{"list",     "docs",    "generate", "verify", "furnace",
                                            "compare",  "identify", "inspect", "sample", "metals"};
    if (argc > 1 && argv[1][0] != '-' && std::find(commands.begin(), commands.end(), argv[1]) == commands.end()) {
        std::string known;
        for (const auto& name : commands) known += (known.empty() ? "" : ", ") + name;
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
        if (app.got_subcommand(gen)) {
            if (!config_file.empty()) apply_config(*gen, config_file);
            collect_params(*gen, g.table);
            g.pixel_given = gen->count("--pixel") > 0;
            return run_generate(g);
        }
        if (app.got_subcommand(ver)) return run_verify(v);
        if (app.got_subcommand(fur)) return run_furnace(f);
        if (app.got_subcommand(cmp)) {
            collect_params(*cmp, c.describe.table);
            return run_compare(c);
        }
        if (app.got_subcommand(idf)) return run_identify(id);
        if (app.got_subcommand(ins)) return run_inspect(inspect_file, inspect_read, inspect_json, inspect_member);
        if (app.got_subcommand(smp)) {
            collect_params(*smp, s.describe.table);
            return run_sample(s);
        }
        if (app.got_subcommand(mtl)) return run_metals(metals);
        if (app.got_subcommand(docs)) {
            // The formatter directly: App::help() would print the selected
            // subcommand's (docs) help for the whole tool.
            CommandHelp help{{"", app.get_formatter()->make_help(&app, "brdflut", CLI::AppFormatMode::Normal)}};
            for (const CLI::App* sub : app.get_subcommands({})) help.emplace_back(sub->get_name(), sub->help("brdflut"));
            return run_docs(docs_output, docs_check, help);
        }
        return run_list(list_presets, list_json);
    } catch (const Error& e) {
        std::cerr << "brdflut: error: " << e.what() << "\n";
        return kExitUsage;
    } catch (const std::exception& e) {
        std::cerr << "brdflut: error: " << e.what() << "\n";
        return kExitFailure;
    }
}
