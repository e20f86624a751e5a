#include "brdflut/verify.h"

#include <cmath>
#include <sstream>

#include "brdflut/error.h"

namespace brdflut {
namespace {
std::string describe(const TableDefinition& def, const std::vector<double>& coords) {
    std::ostringstream s;
    s.precision(6);
    for (std::size_t a = 0; a < coords.size(); ++a)
        s << (a ? ", " : "") << def.axes[a].axis.name << " = " << coords[a];
    return s.str();
}
}  // namespace

const std::vector<ClosedFormCheck>& closed_form_checks(const std::string& table_id) {
    return find_table(table_id).checks;
}

std::vector<std::vector<int>> verify_texels(const TableDefinition& def) {
    std::vector<std::vector<int>> out{{}};
    for (const AxisSpec& spec : def.axes) {
        const int n = spec.axis.count;
        std::vector<int> picks{0};
        if (n > 2) picks.push_back(n / 2);
        if (n > 1) picks.push_back(n - 1);
        std::vector<std::vector<int>> next;
        for (const auto& prefix : out)
            for (int i : picks) {
                auto v = prefix;
                v.push_back(i);
                next.push_back(std::move(v));
            }
        out = std::move(next);
    }
    return out;
}

std::vector<CheckRow> verify_table(const TableDefinition& def, const VerifyOptions& opt) {
    std::vector<CheckRow> rows;
    const TableSettings settings = default_settings(def);
    const PreparedTable quad = def.prepare(settings);

    for (const ClosedFormCheck& c : def.checks) {
        CheckRow r{def.id, c.name, 0.0, c.tolerance, false, ""};
        const auto [err, where] = c.run(*quad.evaluator);
        r.max_error = err;
        r.where = where;
        r.pass = std::isfinite(err) && err <= c.tolerance;
        rows.push_back(r);
    }

    if (def.supports_monte_carlo) {
        TableSettings mc_settings = settings;
        mc_settings.method = Method::monte_carlo;
        mc_settings.samples = opt.mc_samples;
        mc_settings.seed = opt.seed;
        const PreparedTable mc = def.prepare(mc_settings);
        CheckRow r{def.id, "quadrature vs Monte Carlo (" + std::to_string(opt.mc_samples) +
                               " samples, 4 standard errors)", 0.0, 0.0, true, ""};
        double worst_ratio = -1.0;
        std::uint64_t texel = 0;
        for (const auto& idx : verify_texels(def)) {
            std::vector<double> coords;
            for (std::size_t a = 0; a < idx.size(); ++a) coords.push_back(settings.axes[a].value(idx[a]));
            const TexelValue q = quad.evaluator->evaluate(coords.data(), texel);
            const TexelValue m = mc.evaluator->evaluate(coords.data(), texel);
            ++texel;
            for (std::size_t c = 0; c < def.channels.size(); ++c) {
                const double diff = std::abs(q.value[c] - m.value[c]);
                // The Monte Carlo error is 4 standard errors; add the quadrature's own
                // estimate and 1e-12 for the rounding of two long double-precision sums.
                const double tol = m.error[c] + q.error[c] + 1e-12;
                const double ratio = diff / tol;
                if (!(ratio <= 1.0)) r.pass = false;
                if (ratio > worst_ratio || !std::isfinite(ratio)) {
                    worst_ratio = ratio;
                    r.max_error = diff;
                    r.tolerance = tol;
                    r.where = describe(def, coords) + ", channel " + "RGBA"[c];
                }
            }
        }
        rows.push_back(r);
    }
    return rows;
}

}  // namespace brdflut
