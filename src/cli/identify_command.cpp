// identify: which catalogue table and layout a LUT file holds.
#include <cctype>
#include <cstdio>
#include <iostream>

#include "brdflut/error.h"
#include "brdflut/formats.h"
#include "brdflut/identify.h"
#include "cli/commands.h"

namespace brdflut::cli {
namespace {

// The file name as one shell word.
std::string shell_word(const std::string& s) {
    bool plain = !s.empty();
    for (char c : s)
        plain = plain && (std::isalnum(static_cast<unsigned char>(c)) || std::string("/._-+=:,").find(c) != std::string::npos);
    if (plain) return s;
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string axis_text(const Axis& a) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%s [%g, %g] %d %s %s", a.name.c_str(), a.min, a.max, a.count,
                  std::string(to_string(a.placement)).c_str(), std::string(to_string(a.warp)).c_str());
    std::string s = buf;
    if (a.flip) s += " flipped";
    if (a.shift != 0) {
        std::snprintf(buf, sizeof buf, " shifted %+g texel", a.shift);
        s += buf;
    }
    if (a.has_clamp()) {
        std::snprintf(buf, sizeof buf, " clamped to [%g, %g]", a.clamp_lo, a.clamp_hi);
        s += buf;
    }
    return s;
}

}  // namespace

int run_identify(const IdentifyArgs& a) {
    IdentifyOptions opt;
    opt.top = a.top;
    opt.threads = a.threads;
    if (opt.top < 1 || opt.top > 50) throw Error("--top " + std::to_string(a.top) + " is out of range; allowed: 1 to 50");
    if (opt.threads < 0) throw Error("--threads " + std::to_string(a.threads) + " is out of range; allowed: 0 (all) or more");
    const ExrImage img = read_table_image(a.file, read_options(a.read));
    const IdentifyReport rep = identify(img, opt);
    // The file and how it was read, as compare must read it.
    std::string file = shell_word(a.file);
    if (!a.read.array.empty()) file += " --array " + shell_word(a.read.array);
    if (!a.read.shape.empty()) file += " --shape " + shell_word(a.read.shape);
    if (!a.read.decode.empty()) file += " --decode " + shell_word(a.read.decode);
    if (a.json) {
        nlohmann::json j;
        j["file"] = a.file;
        j["width"] = img.width;
        j["height"] = img.height;
        j["channels"] = img.channel_names.size();
        j["searched"] = {{"tables", rep.tables}, {"coarse_candidates", rep.coarse_candidates},
                         {"refined_candidates", rep.refined_candidates}};
        nlohmann::json list = nlohmann::json::array();
        for (const Explanation& e : rep.explanations) {
            nlohmann::json axes = nlohmann::json::array();
            for (const Axis& ax : e.description.settings.axes) axes.push_back(axis_text(ax));
            list.push_back({{"table", e.description.def->id},
                            {"axes", axes},
                            {"options", e.description.settings.params},
                            {"transform", std::string(to_string(e.description.values))},
                            {"max_error", e.max_error},
                            {"rms_error", e.rms_error},
                            {"pass", e.pass},
                            {"tolerance_source", e.tolerance.source},
                            {"padding", e.padding},
                            {"findings", e.findings},
                            {"flat_shape", e.flat_shape},
                            {"compare", "brdflut compare " + file + " " + e.compare_arguments}});
        }
        j["explanations"] = list;
        std::cout << j.dump(2) << "\n";
        return 0;
    }
    std::printf("file: %s (%dx%d, %zu channel(s))\n", a.file.c_str(), img.width, img.height, img.channel_names.size());
    std::printf("searched: %zu tables and option values, %zu layouts on a coarse subset, %zu refined exactly\n",
                rep.tables, rep.coarse_candidates, rep.refined_candidates);
    int rank = 0;
    for (const Explanation& e : rep.explanations) {
        std::printf("\n#%d %s: max |error| %s, rms %s, %s\n", ++rank, e.description.def->id.c_str(),
                    sci(e.max_error).c_str(), sci(e.rms_error).c_str(),
                    e.pass ? "passes compare" : "fails compare");
        if (!e.flat_shape.empty()) std::printf("   the flat array read as %s\n", e.flat_shape.c_str());
        const auto& axes = e.description.settings.axes;
        for (std::size_t i = 0; i < axes.size(); ++i)
            std::printf("   %s %s\n", i == 0 ? "x:" : "y:", axis_text(axes[i]).c_str());
        for (const std::string& p : e.padding) std::printf("   padding: %s\n", p.c_str());
        if (e.findings.empty()) std::printf("   the table's own default layout\n");
        for (const std::string& f : e.findings) std::printf("   - %s\n", f.c_str());
        std::printf("   brdflut compare %s %s\n", file.c_str(), e.compare_arguments.c_str());
    }
    return 0;
}

}  // namespace brdflut::cli
