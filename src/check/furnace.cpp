#include "brdflut/furnace.h"

#include <cmath>

#include "brdflut/catalogue.h"
#include "brdflut/error.h"
#include "brdflut/generate.h"
#include "brdflut/ggx_integrals.h"
#include "brdflut/exr.h"
#include "brdflut/lut.h"
#include "brdflut/quadrature.h"
#include "tables/registry.h"

namespace brdflut {
namespace {

// The settings of a furnace table: the grid of the report (size points on
// each free axis) or the table's default (size 0), the fixed axes at one
// value each, the model options.
TableSettings furnace_settings(const TableDefinition& def, const FurnaceModel& model, int size) {
    TableSettings s = default_settings(def);
    for (std::size_t a = 0; a < s.axes.size(); ++a) {
        Axis& ax = s.axes[a];
        bool fixed = false;
        for (const auto& [name, v] : model.fixed)
            if (ax.name == name) {
                // One texel at v: the centre of [v - d, v + d], linear.
                const AxisSpec& spec = def.axes[a];
                const double d = std::min(v - spec.domain_min, spec.domain_max - v);
                if (!(d > 0.0)) throw Error("furnace model '" + model.id + "': " + name + " = " + std::to_string(v) +
                                            " is outside the axis' allowed range");
                ax = Axis{ax.name, v - std::min(d, 1.0), v + std::min(d, 1.0), 1, Placement::center, Warp::linear};
                fixed = true;
            }
        if (!fixed && size > 0) ax.count = size;
    }
    for (const auto& [k, v] : model.params) s.params[k] = v;
    return s;
}

// One channel of a table, texel by texel.
std::vector<double> channel_of(const Table& t, int channel) {
    std::vector<double> out(t.texel_count());
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = t.at(k, channel);
    return out;
}

// Divides each value of `exact` (on its own grid) by the table at its
// default size, stored in float and looked up at the same parameters.
void compensate(std::vector<double>& values, const Table& exact, const TableDefinition& def,
                const FurnaceModel& model, int threads) {
    LutDescription d;
    d.def = &def;
    d.settings = furnace_settings(def, model, 0);
    GenerateOptions g;
    g.threads = threads;
    const Table shipped = generate(def, d.settings, g);
    ExrImage img;
    img.width = shipped.width();
    img.height = shipped.height();
    img.channel_names = shipped.channels;
    img.pixels.resize(shipped.values.size());
    for (std::size_t k = 0; k < img.pixels.size(); ++k) img.pixels[k] = static_cast<float>(shipped.values[k]);
    const std::size_t n = exact.texel_count();
    for (std::size_t k = 0; k < n; ++k) {
        std::vector<double> params;
        std::size_t rest = k;
        for (const Axis& a : exact.axes) {
            params.push_back(a.value(static_cast<int>(rest % static_cast<std::size_t>(a.count))));
            rest /= static_cast<std::size_t>(a.count);
        }
        values[k] /= sample_lut(img, d, params, model.channel);
    }
}

// 2 * integral of (1 - E(mu)) mu dmu by composite Gauss-Legendre on panels
// geometric from alpha (E falls to 0 where mu ~ alpha): a second rule,
// independent of the adaptive one behind ggx_albedo_average.
double ms_lobe_normalization(double alpha, Visibility vis) {
    std::vector<double> breaks{0.0};
    for (double m = alpha; m < 1.0; m *= 4.0) breaks.push_back(m);
    breaks.push_back(1.0);
    double sum = 0.0;
    for (std::size_t p = 0; p + 1 < breaks.size(); ++p)
        sum += integrate_gauss<1>(
            [&](double mu) {
                const Estimate<2> e = ggx_split_sum(mu, alpha, vis, 1e-11);
                return std::array<double, 1>{2.0 * mu * (1.0 - e.value[0] - e.value[1])};
            },
            breaks[p], breaks[p + 1], 16)[0];
    return sum;
}

}  // namespace

const std::vector<FurnaceModel>& furnace_models() { return families().furnace_models; }

const FurnaceModel& find_furnace_model(const std::string& id) {
    for (const auto& m : furnace_models())
        if (m.id == id) return m;
    std::string known;
    for (const auto& m : furnace_models()) known += (known.empty() ? "" : ", ") + m.id;
    throw Error("model '" + id + "' is not known; allowed: " + known);
}

FurnaceReport run_furnace(const FurnaceModel& model, const FurnaceOptions& opt) {
    if (opt.size < 2 || opt.size > 1024)
        throw Error("--size " + std::to_string(opt.size) + " is out of range; allowed: 2 to 1024");
    FurnaceReport rep;
    rep.model = &model;
    rep.tolerance = opt.tolerance >= 0 ? opt.tolerance : model.tolerance;

    const TableDefinition& def = find_table(model.albedo_table);
    const TableSettings s = furnace_settings(def, model, opt.size);
    GenerateOptions g;
    g.threads = opt.threads;
    const Table e = generate(def, s, g);
    rep.axes = e.axes;
    rep.albedo = channel_of(e, model.channel);
    if (model.compensated) compensate(rep.albedo, e, def, model, opt.threads);
    const int nx = e.axes[0].count;
    const int ny = e.axes.size() > 1 ? e.axes[1].count : 1;

    if (!model.average_table.empty()) {
        const TableDefinition& adef = find_table(model.average_table);
        TableSettings as = furnace_settings(adef, model, 0);
        as.axes[0] = s.axes[1];
        const Table avg = generate(adef, as, g);
        rep.averages = channel_of(avg, model.channel);
        if (model.compensated) compensate(rep.averages, avg, adef, model, opt.threads);
    } else {
        // A 1-D albedo table: its average 2 * integral of E(mu) mu dmu, by
        // adaptive quadrature over the table's own evaluator.
        const PreparedTable p = def.prepare(s);
        AdaptiveOptions ao;
        ao.abs_tol = 1e-10;
        rep.averages = {integrate_adaptive<1>(
                            [&](double mu) {
                                return std::array<double, 1>{2.0 * mu * p.evaluator->evaluate(&mu, 0).value[0]};
                            },
                            0.0, 1.0, ao)
                            .value[0]};
    }

    if (model.kulla_conty) {
        // E_total(mu) = E(mu) + integral of f_ms cos(theta_i) dw_i, with
        // f_ms = (1 - E(mu_o))(1 - E(mu_i)) / (pi (1 - E_avg)): the lobe's
        // albedo is (1 - E(mu_o)) * [2 integral of (1 - E) mu dmu] / (1 - E_avg),
        // the bracket by a second, independent rule. Exactly 1 in theory.
        const Visibility vis = visibility_from_string(s.params.at("visibility"));
        std::vector<double> norms(static_cast<std::size_t>(ny));
        parallel_for_index(norms.size(), opt.threads, [&](std::size_t j) {
            norms[j] = ms_lobe_normalization(e.axes[1].value(static_cast<int>(j)), vis);
        });
        for (int j = 0; j < ny; ++j) {
            const double loss_avg = 1.0 - rep.averages[static_cast<std::size_t>(j)];
            const double norm = norms[static_cast<std::size_t>(j)];
            for (int i = 0; i < nx; ++i) {
                double& v = rep.albedo[static_cast<std::size_t>(j * nx + i)];
                if (loss_avg > 0.0) v += (1.0 - v) * norm / loss_avg;
            }
            if (loss_avg > 0.0) rep.averages[static_cast<std::size_t>(j)] += norm;  // E_avg + (1 - E_avg) norm / (1 - E_avg)
        }
    }

    auto point = [&](std::size_t k, double value) {
        FurnacePoint p;
        p.value = value;
        p.params.push_back(e.axes[0].value(static_cast<int>(k % static_cast<std::size_t>(nx))));
        if (e.axes.size() > 1) p.params.push_back(e.axes[1].value(static_cast<int>(k / static_cast<std::size_t>(nx))));
        return p;
    };
    rep.min = point(0, rep.albedo[0]);
    rep.max = rep.min;
    rep.max_excess = point(0, rep.albedo[0] - 1.0);
    rep.worst_loss = point(0, 1.0 - rep.albedo[0]);
    for (std::size_t k = 0; k < rep.albedo.size(); ++k) {
        const double v = rep.albedo[k];
        if (v < rep.min.value) rep.min = point(k, v);
        if (v > rep.max.value) rep.max = point(k, v);
        if (v - 1.0 > rep.max_excess.value) rep.max_excess = point(k, v - 1.0);
        if (1.0 - v > rep.worst_loss.value) rep.worst_loss = point(k, 1.0 - v);
        if (model.conserves && !(std::abs(v - 1.0) <= rep.tolerance)) rep.pass = false;
    }
    rep.average_min = rep.average_max = rep.averages.front();
    for (double a : rep.averages) {
        rep.average_min = std::min(rep.average_min, a);
        rep.average_max = std::max(rep.average_max, a);
        if (model.conserves && !(std::abs(a - 1.0) <= rep.tolerance)) rep.pass = false;
    }
    return rep;
}

}  // namespace brdflut
