#include <cmath>
#include <filesystem>
#include <cstdio>
#include <iostream>

#include "brdflut/error.h"
#include "brdflut/furnace.h"
#include "brdflut/plot.h"
#include "cli/commands.h"

namespace brdflut::cli {
namespace {

std::string where(const FurnaceReport& r, const FurnacePoint& p) {
    std::string s;
    for (std::size_t i = 0; i < p.params.size(); ++i) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%s%s=%.4g", i ? "," : "", r.axes[i].name.c_str(), p.params[i]);
        s += buf;
    }
    return s;
}

nlohmann::json point_json(const FurnaceReport& r, const FurnacePoint& p) {
    nlohmann::json at;
    for (std::size_t i = 0; i < p.params.size(); ++i) at[r.axes[i].name] = p.params[i];
    return {{"value", p.value}, {"at", at}};
}

void plot(const FurnaceReport& r, const std::string& dir) {
    Heatmap h;
    h.title = r.model->id + ": directional albedo E (white furnace, F = 1, unit colour)";
    h.x = {"cos_theta = cos(theta_o)", r.axes[0]};
    h.y = r.axes.size() > 1 ? HeatmapAxis{r.axes[1].name, r.axes[1]}
                            : HeatmapAxis{"(no parameter)", Axis{"none", 0.0, 1.0, 1, Placement::center, Warp::linear}};
    h.values = r.albedo;
    h.colorbar_label = "albedo E";
    h.highlight = HeatmapHighlight{1.0, "outline: E > 1 (gains energy)"};
    const std::string path = (std::filesystem::path(dir) / ("furnace_" + r.model->id + ".png")).string();
    write_heatmap_png(path, h);
}

}  // namespace

int run_furnace(const FurnaceArgs& a) {
    std::vector<const FurnaceModel*> models;
    if (a.models.empty())
        for (const auto& m : furnace_models()) models.push_back(&m);
    for (const auto& id : a.models) models.push_back(&find_furnace_model(id));
    if (!(a.tolerance < 0 || (a.tolerance >= 0 && a.tolerance <= 1)) || std::isnan(a.tolerance))
        throw Error("--tolerance " + std::to_string(a.tolerance) + " is out of range; allowed: 0 to 1");
    FurnaceOptions opt;
    opt.size = a.size;
    opt.threads = a.threads;
    opt.tolerance = a.tolerance;
    if (!a.plot.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(a.plot, ec);
        if (ec || !std::filesystem::is_directory(a.plot))
            throw RuntimeError("cannot create plot folder '" + a.plot + "'" + (ec ? ": " + ec.message() : ""));
    }
    bool ok = true;
    nlohmann::json out = nlohmann::json::array();
    if (!a.json)
        std::printf("%-18s %-9s %-10s %-10s %-10s %-30s %-10s %-23s %s\n", "model", "conserves", "min E", "max E",
                    "E - 1 max", "at", "worst loss", "E_avg range", "result");
    for (const FurnaceModel* m : models) {
        const FurnaceReport r = run_furnace(*m, opt);
        ok = ok && r.pass;
        if (!a.plot.empty()) plot(r, a.plot);
        if (a.json) {
            out.push_back({{"model", m->id},
                           {"description", m->description},
                           {"conserves", m->conserves},
                           {"tolerance", r.tolerance},
                           {"min", point_json(r, r.min)},
                           {"max", point_json(r, r.max)},
                           {"max_excess", point_json(r, r.max_excess)},
                           {"worst_loss", point_json(r, r.worst_loss)},
                           {"average_min", r.average_min},
                           {"average_max", r.average_max},
                           {"pass", r.pass}});
            continue;
        }
        char avg[64];
        std::snprintf(avg, sizeof avg, "%.6f..%.6f", r.average_min, r.average_max);
        std::printf("%-18s %-9s %-10.6f %-10.6f %-+10.2e %-30s %-10.2e %-23s %s\n", m->id.c_str(),
                    m->conserves ? "yes" : "no", r.min.value, r.max.value, r.max_excess.value,
                    r.max_excess.value > 0 ? where(r, r.max_excess).c_str() : "-", r.worst_loss.value, avg,
                    m->conserves ? (r.pass ? "pass" : "FAIL") : (r.max_excess.value > 0 ? "exceeds 1" : "-"));
        std::fflush(stdout);
    }
    if (a.json) std::cout << nlohmann::json{{"pass", ok}, {"models", out}}.dump(2) << "\n";
    return ok ? 0 : kExitFailure;
}

}  // namespace brdflut::cli
