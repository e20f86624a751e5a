// brdflut identify: a coarse search over the catalogue and the axis
// vocabulary on a subset of texels, exact refinement of the best, and the
// final figures from compare_values (identify.h describes the stages).
#include "brdflut/identify.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <tuple>

#include "brdflut/error.h"
#include "brdflut/generate.h"

namespace brdflut {
namespace {

constexpr int kCoarsePerAxis = 8;    // texels per axis scored in the coarse stage
constexpr int kRefinePerAxis = 12;   // texels per axis evaluated exactly in refinement
constexpr int kDense2D = 33;         // draft grid per axis of a 2-D table
constexpr int kDense1D = 129;        // draft grid of a 1-D table
constexpr std::size_t kKeepLinear = 20;  // coarse candidates refined, values as they are
constexpr std::size_t kKeepSrgb = 4;     // and with the sRGB EOTF
constexpr std::size_t kMaxOptionCombinations = 24;
// Clamps at the lower end of an axis whose grid reaches its domain's lower
// end, as a fraction of the range (cos_theta >= 1e-4, >= 1e-3).
constexpr double kEndClamps[] = {1e-4, 1e-3};
constexpr double kShifts[] = {0.0, 1.0, -1.0, 0.5, -0.5};
// The coarse search scores layouts that change at most this many fields of
// the table's default axes (placement, warp, range, flip, clamp: 1 each; a
// shift: 2), over both axes together.
constexpr int kMaxLayoutCost = 4;

std::string shortest(double v) {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char buf[40];
    for (int p = 1; p <= 17; ++p) {
        std::snprintf(buf, sizeof buf, "%.*g", p, v);
        if (std::strtod(buf, nullptr) == v) break;
    }
    return buf;
}

// ---- axis candidates -------------------------------------------------------

struct AxisCandidate {
    Axis axis;
    int cost = 0;  // fields that differ from the table's default
    // Cubic taps into the dense draft grid at the coarse subset positions.
    std::vector<std::array<int, 4>> idx;
    std::vector<std::array<double, 4>> w;
};

int axis_cost(const Axis& a, const Axis& def) {
    int c = 0;
    if (a.placement != def.placement) ++c;
    if (a.warp != def.warp) ++c;
    if (a.min != def.min || a.max != def.max) ++c;
    if (a.flip != def.flip) ++c;
    if (a.shift != def.shift) c += 2;
    if (a.clamp_lo != def.clamp_lo || a.clamp_hi != def.clamp_hi) ++c;
    return c;
}

std::vector<int> subset_positions(int n, int k) {
    std::vector<int> out;
    if (n <= k) {
        for (int i = 0; i < n; ++i) out.push_back(i);
        return out;
    }
    for (int s = 0; s < k; ++s) {
        const int i = static_cast<int>(std::lround(static_cast<double>(s) * (n - 1) / (k - 1)));
        if (out.empty() || out.back() != i) out.push_back(i);
    }
    return out;
}

// Catmull-Rom taps at continuous position t of a grid of m nodes, with
// linear extrapolation of the missing neighbour at either end.
void cubic_taps(double t, int m, std::array<int, 4>& idx, std::array<double, 4>& w) {
    if (m == 1) {
        idx = {0, 0, 0, 0};
        w = {1.0, 0.0, 0.0, 0.0};
        return;
    }
    if (!std::isfinite(t)) t = 0.0;
    t = std::clamp(t, 0.0, static_cast<double>(m - 1));
    const int i = std::clamp(static_cast<int>(std::floor(t)), 0, m - 2);
    const double f = t - i, f2 = f * f, f3 = f2 * f;
    idx = {i - 1, i, i + 1, i + 2};
    w = {0.5 * (-f3 + 2 * f2 - f), 0.5 * (3 * f3 - 5 * f2 + 2), 0.5 * (-3 * f3 + 4 * f2 + f), 0.5 * (f3 - f2)};
    if (idx[0] < 0) {  // p[-1] = 2 p[0] - p[1]
        w[1] += 2 * w[0];
        w[2] -= w[0];
        w[0] = 0.0;
        idx[0] = i;
    }
    if (idx[3] > m - 1) {  // p[m] = 2 p[m - 1] - p[m - 2]
        w[2] += 2 * w[3];
        w[1] -= w[3];
        w[3] = 0.0;
        idx[3] = i + 1;
    }
}

// Every description of one axis with `count` texels that the vocabulary
// offers, simplest first, one per distinct parameter grid.
std::vector<AxisCandidate> axis_candidates(const AxisSpec& spec, int count, const Axis& dense) {
    const Axis& def = spec.axis;
    std::vector<AxisCandidate> all;
    for (Placement p : {def.placement, def.placement == Placement::center ? Placement::endpoints : Placement::center}) {
        if (p == Placement::endpoints && count < 2) continue;
        if (p == Placement::zero_then_endpoints && count < 2) continue;
        if (p == Placement::split_endpoints && count < 2) continue;
        for (const WarpDef& wd : warps()) {
            for (bool reversed : {false, true}) {
                const double lo = reversed ? def.max : def.min, hi = reversed ? def.min : def.max;
                if (!wd.range_problem(lo, hi).empty()) continue;
                for (bool flip : {false, true}) {
                    for (double shift : kShifts) {
                        Axis a = def;
                        a.count = count;
                        a.placement = p;
                        a.warp = wd.warp;
                        a.min = lo;
                        a.max = hi;
                        a.flip = flip;
                        a.shift = shift;
                        if (shift != 0.0) {
                            // A shifted grid leaves [0, 1] in u: clamp it to
                            // the domain where it leaves it.
                            const double v0 = a.value(0), v1 = a.value(count - 1);
                            if (std::isnan(v0) || std::isnan(v1)) continue;
                            if (std::min(v0, v1) < spec.domain_min || std::max(v0, v1) > spec.domain_max) {
                                a.clamp_lo = std::max(a.clamp_lo, spec.domain_min);
                                a.clamp_hi = std::min(a.clamp_hi, spec.domain_max);
                            }
                        }
                        try {
                            a.validate();
                        } catch (const Error&) {
                            continue;
                        }
                        if (a.lowest() < spec.domain_min || a.highest() > spec.domain_max) continue;
                        all.push_back({a, axis_cost(a, def), {}, {}});
                    }
                }
            }
        }
    }
    std::stable_sort(all.begin(), all.end(), [](const AxisCandidate& x, const AxisCandidate& y) { return x.cost < y.cost; });
    std::vector<AxisCandidate> kept;
    std::vector<std::vector<double>> grids;
    for (AxisCandidate& c : all) {
        std::vector<double> g(static_cast<std::size_t>(count));
        for (int i = 0; i < count; ++i) g[static_cast<std::size_t>(i)] = c.axis.value(i);
        const bool same = std::any_of(grids.begin(), grids.end(), [&](const std::vector<double>& o) {
            for (std::size_t i = 0; i < g.size(); ++i)
                if (!(std::abs(g[i] - o[i]) <= 1e-12 * (1.0 + std::abs(o[i])))) return false;
            return true;
        });
        if (same) continue;
        grids.push_back(std::move(g));
        kept.push_back(std::move(c));
    }
    const std::vector<int> pos = subset_positions(count, kCoarsePerAxis);
    for (AxisCandidate& c : kept) {
        for (int i : pos) {
            std::array<int, 4> idx;
            std::array<double, 4> w;
            const double u = dense.u_of_value(c.axis.value(i));
            cubic_taps(u * (dense.count - 1), dense.count, idx, w);
            c.idx.push_back(idx);
            c.w.push_back(w);
        }
    }
    return kept;
}

// ---- tables and their option values ---------------------------------------

struct Variant {
    const TableDefinition* def = nullptr;
    std::map<std::string, std::string> params;
    int cost = 0;                // options that differ from their default
    std::vector<Axis> dense;     // draft grid axes, definition order
    std::vector<double> values;  // draft values, axis 0 fastest, channels interleaved
};

std::vector<std::map<std::string, std::string>> option_combinations(const TableDefinition& def) {
    std::vector<std::map<std::string, std::string>> out{default_settings(def).params};
    for (const ModelOption& o : def.options) {
        if (o.allowed.empty() || o.default_value.empty()) continue;
        std::vector<std::map<std::string, std::string>> next;
        for (const auto& base : out)
            for (const std::string& v : o.allowed) {
                auto m = base;
                m[o.name] = v;
                if (next.size() < kMaxOptionCombinations) next.push_back(m);
            }
        out = std::move(next);
    }
    // Defaults first.
    std::stable_sort(out.begin(), out.end(), [&](const auto& x, const auto& y) {
        auto cost = [&](const std::map<std::string, std::string>& m) {
            int c = 0;
            for (const ModelOption& o : def.options)
                if (m.count(o.name) && m.at(o.name) != o.default_value) ++c;
            return c;
        };
        return cost(x) < cost(y);
    });
    return out;
}

int option_cost(const TableDefinition& def, const std::map<std::string, std::string>& params) {
    int c = 0;
    for (const ModelOption& o : def.options)
        if (params.count(o.name) && params.at(o.name) != o.default_value) ++c;
    return c;
}

// ---- channels --------------------------------------------------------------

// What a file channel is read as: a sum of one or two table channels, or a
// constant (padding).
struct ChannelChoice {
    std::vector<int> sum;  // empty: constant
    double constant = 0.0;
};

std::vector<std::vector<int>> channel_sums(int nc) {
    std::vector<std::vector<int>> out;
    for (int a = 0; a < nc; ++a) out.push_back({a});
    for (int a = 0; a < nc; ++a)
        for (int b = a + 1; b < nc; ++b) out.push_back({a, b});
    return out;
}

std::string letter(int c) { return std::string(1, "RGBA"[c]); }

// ---- coarse search ----------------------------------------------------------

struct Coarse {
    double score = 0.0;  // sum of squared errors over the coarse subset
    int cost = 0;
    std::size_t variant = 0;
    int order = 0;  // 0: definition order, 1: transposed
    std::size_t c0 = 0, c1 = 0;
    ValueTransform values = ValueTransform::none;
};

bool coarse_less(const Coarse& x, const Coarse& y) {
    return std::tie(x.score, x.cost, x.variant, x.order, x.c0, x.c1, x.values) <
           std::tie(y.score, y.cost, y.variant, y.order, y.c0, y.c1, y.values);
}

void keep_best(std::vector<Coarse>& v, std::size_t n) {
    if (v.size() <= n) return;
    std::partial_sort(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(n), v.end(), coarse_less);
    v.resize(n);
}

// ---- refinement --------------------------------------------------------------

struct Refined {
    LutDescription d;
    double max_error = 0.0, rms = 0.0;
    int cost = 0;
    std::vector<std::string> padding;
};

// Errors equal to three significant digits rank as equal: the simpler
// description, then the earlier catalogue table, comes first.
double rounded(double v) {
    if (!(std::abs(v) > 0) || !std::isfinite(v)) return v;
    const double scale = std::pow(10.0, 2 - std::floor(std::log10(std::abs(v))));
    return std::round(v * scale) / scale;
}

std::size_t catalogue_index(const TableDefinition* def) { return static_cast<std::size_t>(def - catalogue().data()); }

// Each field a description changes from its table's defaults (its cost) must
// buy an error smaller by this factor to rank above the description without
// it: a clamp or a shift that trims a largest error by a percent (Heitz's
// ltc_2, whose grazing n0 is 6 % low, "fits better" with a view-cosine clamp
// at the grid end) is not a finding, while the layouts engines do use cut the
// error by orders of magnitude.
constexpr double kCostFactor = 1.25;

// The ranking of candidates, best first: largest error, then rms error, each
// weighted by kCostFactor^cost and rounded to three digits; then the cost;
// then the catalogue order.
std::tuple<double, double, int, std::size_t> rank_key(double max_error, double rms, int cost,
                                                      const TableDefinition* def) {
    const double w = std::pow(kCostFactor, cost);
    return {rounded(max_error * w), rounded(rms * w), cost, catalogue_index(def)};
}

bool refined_less(const Refined& x, const Refined& y) {
    return rank_key(x.max_error, x.rms, x.cost, x.d.def) < rank_key(y.max_error, y.rms, y.cost, y.d.def);
}

bool explanation_less(const Explanation& x, const Explanation& y) {
    return rank_key(x.max_error, x.rms_error, x.cost, x.description.def) <
           rank_key(y.max_error, y.rms_error, y.cost, y.description.def);
}

double pixel(const ExrImage& img, int x, int y, int c) {
    const std::size_t nc = img.channel_names.size();
    return img.pixels[(static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(x)) * nc +
                      static_cast<std::size_t>(c)];
}

// Chooses what each file channel holds from exact table values at points
// (nc per point) against the file's values there (nf per point), with the
// values transformed as `t`; fills the channel map, padding and errors.
void choose_channels(const std::vector<double>& table, const std::vector<double>& file, std::size_t points, int nc,
                     int nf, ValueTransform t, Refined& r) {
    const auto sums = channel_sums(nc);
    struct Best {
        double max = HUGE_VAL, sse = HUGE_VAL;
        ChannelChoice choice;
    };
    std::vector<Best> best(static_cast<std::size_t>(nf)), best_const(static_cast<std::size_t>(nf));
    auto consider = [](Best& b, double mx, double sse, const ChannelChoice& ch) {
        if (std::tie(mx, sse) < std::tie(b.max, b.sse)) b = {mx, sse, ch};
    };
    for (int f = 0; f < nf; ++f) {
        const bool transformed = t == ValueTransform::srgb && f < 3;
        for (const auto& s : sums) {
            double mx = 0.0, sse = 0.0;
            for (std::size_t p = 0; p < points; ++p) {
                double v = 0.0;
                for (int a : s) v += table[p * static_cast<std::size_t>(nc) + static_cast<std::size_t>(a)];
                if (transformed) v = srgb_eotf(v);
                const double e = file[p * static_cast<std::size_t>(nf) + static_cast<std::size_t>(f)] - v;
                const double ae = std::isfinite(e) ? std::abs(e) : HUGE_VAL;
                mx = std::max(mx, ae);
                sse += ae * ae;
            }
            consider(best[static_cast<std::size_t>(f)], mx, sse, {s, 0.0});
        }
        for (double k : {0.0, 1.0}) {
            double mx = 0.0, sse = 0.0;
            for (std::size_t p = 0; p < points; ++p) {
                const double e = file[p * static_cast<std::size_t>(nf) + static_cast<std::size_t>(f)] - k;
                const double ae = std::isfinite(e) ? std::abs(e) : HUGE_VAL;
                mx = std::max(mx, ae);
                sse += ae * ae;
            }
            consider(best_const[static_cast<std::size_t>(f)], mx, sse, {{}, k});
        }
    }
    // Trailing channels that are better read as constants are padding.
    int compared = nf;
    while (compared > 1) {
        const Best& c = best_const[static_cast<std::size_t>(compared - 1)];
        const Best& s = best[static_cast<std::size_t>(compared - 1)];
        if (!(std::tie(c.max, c.sse) < std::tie(s.max, s.sse))) break;
        --compared;
    }
    std::vector<std::vector<int>> map;
    double mx = 0.0, sse = 0.0;
    for (int f = 0; f < compared; ++f) {
        map.push_back(best[static_cast<std::size_t>(f)].choice.sum);
        mx = std::max(mx, best[static_cast<std::size_t>(f)].max);
        sse += best[static_cast<std::size_t>(f)].sse;
    }
    r.padding.clear();
    for (int f = compared; f < nf; ++f) {
        const Best& c = best_const[static_cast<std::size_t>(f)];
        r.padding.push_back(letter(f) + " = " + shortest(c.choice.constant) +
                            (c.max > 0 ? " (within " + shortest(std::stod(shortest(c.max))) + ")" : ""));
        mx = std::max(mx, c.max);
    }
    // The identity over every table channel is the default map.
    bool identity = static_cast<int>(map.size()) == nc;
    for (std::size_t f = 0; f < map.size() && identity; ++f) identity = map[f] == std::vector<int>{static_cast<int>(f)};
    r.d.settings.channel_map = identity ? std::vector<std::vector<int>>{} : map;
    if (!identity)
        for (std::size_t f = 0; f < map.size(); ++f) r.cost += map[f] == std::vector<int>{static_cast<int>(f)} ? 0 : 1;
    r.d.values = t;
    r.max_error = mx;
    r.rms = std::sqrt(sse / static_cast<double>(points * static_cast<std::size_t>(std::max(compared, 1))));
}

// ---- statements ------------------------------------------------------------------

std::string uniform_in(const Axis& a) {
    const std::string& x = a.name;
    auto norm = [&]() -> std::string {
        if (a.min == 0 && a.max == 1) return x;
        if (a.min == 1 && a.max == 0) return "1 - " + x;
        return "(" + x + " - " + shortest(a.min) + ")/(" + shortest(a.max) + " - " + shortest(a.min) + ")";
    };
    switch (a.warp) {
        case Warp::linear: return norm();
        case Warp::square: return "sqrt(" + norm() + ")";
        case Warp::sqrt: return "(" + norm() + ")^2";
        case Warp::log: return "log " + x;
        case Warp::ior_z: return "z = sqrt((" + x + " - 1)/(" + x + " + 1))";
        case Warp::saturating_exp: return "-ln(1 - (1 - e^-8) " + norm() + ")/8";
        case Warp::ior_split:
            return "1/" + x + " below 1 and " + x + " above (" + shortest(a.min) + " to 1 to " + shortest(a.max) + ")";
    }
    return x;
}

std::string texel_words(double shift) {
    const double a = std::abs(shift);
    const std::string size = a == 1.0 ? "one texel" : a == 0.5 ? "half a texel" : shortest(a) + " texels";
    return size + (shift > 0 ? " high" : " low");
}

std::string phrase_value(const std::string& v) {
    std::string s = v;
    std::replace(s.begin(), s.end(), '_', '-');
    return s;
}

}  // namespace

std::vector<std::string> describe_findings(const LutDescription& d) {
    std::vector<std::string> out;
    const TableDefinition& def = *d.def;
    const TableSettings base = default_settings(def);
    const auto& axes = d.settings.axes;
    if (axes.size() == 2 && axes[0].name != base.axes[0].name)
        out.push_back("axes transposed: columns hold " + axes[0].name + " and rows " + axes[1].name +
                      ", where the table's default has columns of " + base.axes[0].name);
    for (std::size_t s = 0; s < axes.size(); ++s) {
        const Axis& a = axes[s];
        const AxisSpec* spec = nullptr;
        for (const AxisSpec& sp : def.axes)
            if (sp.axis.name == a.name) spec = &sp;
        if (!spec) continue;
        const Axis& da = spec->axis;
        const std::string role = axes.size() == 1 ? "texels" : s == 0 ? "columns" : "rows";
        const std::string j = s == 0 ? "i" : "j", n = s == 0 ? "w" : "h";
        if (a.flip) out.push_back(role + " are flipped: the first " + (s == 0 ? "column" : "row") + " holds the last grid index");
        const bool reversed = a.min == da.max && a.max == da.min;
        if (reversed) out.push_back(a.name + " runs from " + shortest(a.min) + " down to " + shortest(a.max) + " (a reversed range)");
        else if (a.min != da.min || a.max != da.max)
            out.push_back(a.name + " over [" + shortest(a.min) + ", " + shortest(a.max) + "] where the default is [" +
                          shortest(da.min) + ", " + shortest(da.max) + "]");
        if (a.warp != da.warp || reversed) {
            std::string line = role + " uniform in " + uniform_in(a) + " (warp " + std::string(to_string(a.warp)) + ")";
            if (!spec->root_name.empty() && da.warp == Warp::square && a.warp == Warp::linear)
                line = "linear in " + a.name + " where the table is indexed by " + spec->root_name + " (" + a.name +
                       " = " + spec->root_name + "^2): " + line;
            else if (!spec->square_name.empty() && da.warp == Warp::linear && a.warp == Warp::sqrt)
                line = "linear in " + spec->square_name + " (= " + a.name + "^2) where the table is indexed by " +
                       a.name + ": " + line;
            else if (a.warp != da.warp)
                line += ", where the table's default is uniform in " + uniform_in(da);
            out.push_back(line);
        }
        if (a.placement != da.placement) {
            const auto plain = [](Placement p) { return p == Placement::endpoints || p == Placement::center; };
            if (!plain(a.placement) || !plain(da.placement))
                out.push_back(role + " at placement " + std::string(to_string(a.placement)) +
                              ", where the table's default is " + std::string(to_string(da.placement)));
            else if (a.placement == Placement::endpoints)
                out.push_back("cell centres described as end points: half a texel: " + role + " hold " + a.name +
                              " at u = " + j + "/(" + n + " - 1), the table's default at cell centres (" + j + " + 0.5)/" + n);
            else
                out.push_back("end points described as cell centres: half a texel: " + role + " hold " + a.name +
                              " at u = (" + j + " + 0.5)/" + n + ", the table's default at end points " + j + "/(" + n + " - 1)");
        }
        if (a.shift != 0.0) {
            const std::string u = a.placement == Placement::center
                                      ? "(" + j + " + " + shortest(0.5 + a.shift) + ")/" + n
                                      : "(" + j + " + " + shortest(a.shift) + ")/(" + n + " - 1)";
            const bool plain = a.warp == Warp::linear && a.min == 0 && a.max == 1;
            std::string line = role + " hold " + a.name + (plain ? " " : " at u = ") + u + ": " + texel_words(a.shift);
            out.push_back(line);
        }
        if (a.clamp_lo != da.clamp_lo || a.clamp_hi != da.clamp_hi) {
            std::string line = a.name + " clamped to [" + shortest(a.clamp_lo) + ", " + shortest(a.clamp_hi) + "] at the grid ends";
            if (a.shift != 0.0) line += " (the domain end that the shift passes)";
            out.push_back(line);
        }
    }
    if (!d.settings.channel_map.empty()) {
        std::string line = "channels: ";
        bool sum = false;
        for (std::size_t f = 0; f < d.settings.channel_map.size(); ++f) {
            std::string held;
            for (int c : d.settings.channel_map[f]) held += (held.empty() ? "" : " + ") + letter(c);
            sum = sum || d.settings.channel_map[f].size() > 1;
            line += (f ? ", " : "") + letter(static_cast<int>(f)) + " holds " + held;
        }
        if (sum) line += " (a sum of the table's channels)";
        out.push_back(line);
    }
    for (const ModelOption& o : def.options) {
        auto it = d.settings.params.find(o.name);
        if (it == d.settings.params.end() || it->second == o.default_value || o.default_value.empty()) continue;
        if (o.name == "visibility")
            out.push_back(phrase_value(it->second) + " Smith G where " + phrase_value(o.default_value) + " is usual");
        else
            out.push_back("--" + o.name + " " + it->second + " where " + o.default_value + " is the default");
    }
    if (d.values == ValueTransform::srgb)
        out.push_back("values decoded as sRGB: the file holds the sRGB EOTF of the table's values "
                      "(a linear table read or sampled as an sRGB texture)");
    return out;
}

std::string compare_arguments(const LutDescription& d, const ExrImage& img) {
    (void)img;
    const TableDefinition& def = *d.def;
    const TableSettings base = default_settings(def);
    std::ostringstream s;
    s << "--as " << def.id;
    const auto& axes = d.settings.axes;
    if (axes.size() > 1 && axes[0].name != base.axes[0].name) {
        s << " --order ";
        for (std::size_t i = 0; i < axes.size(); ++i) s << (i ? "," : "") << axes[i].name;
    }
    for (const Axis& a : axes) {
        const Axis* da = nullptr;
        for (const Axis& b : base.axes)
            if (b.name == a.name) da = &b;
        if (!da) continue;
        if (a.min != da->min || a.max != da->max) s << " --range " << a.name << "=" << shortest(a.min) << ":" << shortest(a.max);
        if (a.placement != da->placement) s << " --placement " << a.name << "=" << to_string(a.placement);
        if (a.warp != da->warp) s << " --warp " << a.name << "=" << to_string(a.warp);
        if (a.flip != da->flip) s << " --flip " << a.name;
        if (a.shift != da->shift) s << " --shift " << a.name << "=" << shortest(a.shift);
        if (a.clamp_lo != da->clamp_lo || a.clamp_hi != da->clamp_hi)
            s << " --clamp " << a.name << "=" << shortest(a.clamp_lo) << ":" << shortest(a.clamp_hi);
    }
    if (!d.settings.channel_map.empty()) {
        s << " --channels ";
        for (std::size_t f = 0; f < d.settings.channel_map.size(); ++f) {
            s << (f ? "," : "") << letter(static_cast<int>(f)) << "=";
            for (std::size_t k = 0; k < d.settings.channel_map[f].size(); ++k)
                s << (k ? "+" : "") << letter(d.settings.channel_map[f][k]);
        }
    }
    for (const ModelOption& o : def.options) {
        auto it = d.settings.params.find(o.name);
        auto bt = base.params.find(o.name);
        if (it != d.settings.params.end() && (bt == base.params.end() || bt->second != it->second))
            s << " --" << o.name << " " << it->second;
    }
    if (d.values != ValueTransform::none) s << " --transform " << to_string(d.values);
    return s.str();
}

namespace {

// Tables with `ndim` axes, each with its option values, tabulated at draft
// quality on dense end-point grids.
std::vector<Variant> tabulate_variants(int ndim, int threads) {
    std::vector<Variant> variants;
    for (const TableDefinition& def : catalogue()) {
        if (static_cast<int>(def.axes.size()) != ndim || !def.searched_by_identify) continue;
        for (const auto& params : option_combinations(def)) {
            Variant v;
            v.def = &def;
            v.params = params;
            v.cost = option_cost(def, params);
            for (const AxisSpec& sp : def.axes) {
                Axis a = sp.axis;
                a.count = ndim == 1 ? kDense1D : kDense2D;
                a.placement = Placement::endpoints;
                a.flip = false;
                a.shift = 0.0;
                v.dense.push_back(a);
            }
            variants.push_back(std::move(v));
        }
    }
    if (variants.empty())
        throw RuntimeError("no catalogue table has " + std::to_string(ndim) + " axis(es) like the file");
    parallel_for_index(variants.size(), threads, [&](std::size_t i) {
        Variant& v = variants[i];
        TableSettings s = default_settings(*v.def);
        s.params = v.params;
        s.axes = v.dense;
        s.quality = Quality::draft;
        s.method = Method::quadrature;
        try {
            GenerateOptions g;
            g.threads = 1;
            v.values = generate(*v.def, s, g).values;
        } catch (const std::exception&) {
            v.values.clear();
        }
    });
    return variants;
}

// The coarse tabulation of the tables of `ndim` axes, made once per process
// and shared by every later identify call: draft quadrature on fixed dense
// grids, each variant on one thread, so its values do not depend on the
// thread count or on the file. At most two entries (1 and 2 axes).
const std::vector<Variant>& tabulated_variants(int ndim, int threads) {
    static std::mutex m;
    static std::map<int, std::vector<Variant>> cache;  // std::map: references stay valid
    const std::lock_guard<std::mutex> lock(m);
    auto it = cache.find(ndim);
    if (it == cache.end()) it = cache.emplace(ndim, tabulate_variants(ndim, threads)).first;
    return it->second;
}

IdentifyReport identify_shape(const ExrImage& img, const IdentifyOptions& opt, const std::vector<Variant>& variants) {
    const int ndim = img.height == 1 ? 1 : 2;
    const int nf = static_cast<int>(img.channel_names.size());
    const int counts[2] = {img.width, img.height};
    IdentifyReport report;
    report.tables = variants.size();

    // Axis candidates per (table, definition axis, texel count).
    std::map<std::tuple<const TableDefinition*, int, int>, std::vector<AxisCandidate>> cand_cache;
    auto candidates = [&](const Variant& v, int def_axis, int count) -> const std::vector<AxisCandidate>& {
        auto key = std::make_tuple(v.def, def_axis, count);
        auto it = cand_cache.find(key);
        if (it == cand_cache.end())
            it = cand_cache.emplace(key, axis_candidates(v.def->axes[static_cast<std::size_t>(def_axis)], count,
                                                         v.dense[static_cast<std::size_t>(def_axis)]))
                     .first;
        return it->second;
    };
    const std::vector<int> pos[2] = {subset_positions(counts[0], kCoarsePerAxis),
                                     subset_positions(ndim == 2 ? counts[1] : 1, kCoarsePerAxis)};
    // A dummy second axis of a 1-D table: one tap.
    AxisCandidate none_axis;
    none_axis.idx.push_back({0, 0, 0, 0});
    none_axis.w.push_back({1.0, 0.0, 0.0, 0.0});
    const std::vector<AxisCandidate> none_list{none_axis};

    struct Task {
        std::size_t variant;
        int order;
        std::size_t c0;
    };
    std::vector<Task> tasks;
    for (std::size_t v = 0; v < variants.size(); ++v) {
        if (variants[v].values.empty()) continue;
        for (int order = 0; order < ndim; ++order) {
            const int s0 = order == 0 ? 0 : 1;  // storage axis of definition axis 0
            const auto& c0s = candidates(variants[v], 0, counts[s0]);
            if (ndim == 2) candidates(variants[v], 1, counts[1 - s0]);
            for (std::size_t c = 0; c < c0s.size(); ++c)
                if (c0s[c].cost <= kMaxLayoutCost) tasks.push_back({v, order, c});
        }
    }
    // File values at the coarse subset, per order: point (s, t) with s the
    // position along definition axis 0; also through the inverse EOTF.
    std::vector<double> file_sub[2], file_srgb[2];
    for (int order = 0; order < ndim; ++order) {
        const std::vector<int>& p0 = pos[order == 0 ? 0 : 1];
        const std::vector<int>& p1 = ndim == 2 ? pos[order == 0 ? 1 : 0] : pos[1];
        for (int s : p0)
            for (int t : p1) {
                const int x = order == 0 ? s : t, y = order == 0 ? t : s;
                for (int f = 0; f < nf; ++f) {
                    double v = pixel(img, x, y, f);
                    if (!std::isfinite(v)) v = 0.0;
                    file_sub[order].push_back(v);
                    file_srgb[order].push_back(f < 3 ? srgb_inverse_eotf(v) : v);
                }
            }
    }
    std::vector<std::vector<Coarse>> task_best(tasks.size());
    parallel_for_index(tasks.size(), opt.threads, [&](std::size_t ti) {
        const Task& task = tasks[ti];
        const Variant& v = variants[task.variant];
        const int s0 = task.order == 0 ? 0 : 1;
        const auto& c0s = cand_cache.at(std::make_tuple(v.def, 0, counts[s0]));
        const auto& c1s = ndim == 2 ? cand_cache.at(std::make_tuple(v.def, 1, counts[1 - s0])) : none_list;
        const AxisCandidate& c0 = c0s[task.c0];
        const int nc = static_cast<int>(v.def->channels.size());
        const std::size_t m0 = static_cast<std::size_t>(v.dense[0].count);
        const std::size_t m1 = ndim == 2 ? static_cast<std::size_t>(v.dense[1].count) : 1;
        const std::size_t k0 = c0.idx.size();
        // Along definition axis 0, for every dense row.
        std::vector<double> t0(k0 * m1 * static_cast<std::size_t>(nc), 0.0);
        for (std::size_t s = 0; s < k0; ++s)
            for (std::size_t b = 0; b < m1; ++b)
                for (int q = 0; q < 4; ++q) {
                    const double w = c0.w[s][static_cast<std::size_t>(q)];
                    if (w == 0.0) continue;
                    const std::size_t a = static_cast<std::size_t>(c0.idx[s][static_cast<std::size_t>(q)]);
                    for (int c = 0; c < nc; ++c)
                        t0[(s * m1 + b) * static_cast<std::size_t>(nc) + static_cast<std::size_t>(c)] +=
                            w * v.values[(b * m0 + a) * static_cast<std::size_t>(nc) + static_cast<std::size_t>(c)];
                }
        const auto sums = channel_sums(nc);
        std::vector<Coarse> best;
        std::vector<double> vals;
        const std::vector<double>& F = file_sub[task.order];
        const std::vector<double>& G = file_srgb[task.order];
        for (std::size_t ci = 0; ci < c1s.size(); ++ci) {
            const AxisCandidate& c1 = c1s[ci];
            if (c0.cost + c1.cost > kMaxLayoutCost) break;  // candidates are sorted by cost
            const std::size_t k1 = c1.idx.size();
            const std::size_t points = k0 * k1;
            vals.assign(points * static_cast<std::size_t>(nc), 0.0);
            for (std::size_t s = 0; s < k0; ++s)
                for (std::size_t t = 0; t < k1; ++t)
                    for (int q = 0; q < 4; ++q) {
                        const double w = c1.w[t][static_cast<std::size_t>(q)];
                        if (w == 0.0) continue;
                        const std::size_t b = static_cast<std::size_t>(c1.idx[t][static_cast<std::size_t>(q)]);
                        for (int c = 0; c < nc; ++c)
                            vals[(s * k1 + t) * static_cast<std::size_t>(nc) + static_cast<std::size_t>(c)] +=
                                w * t0[(s * m1 + b) * static_cast<std::size_t>(nc) + static_cast<std::size_t>(c)];
                    }
            // Sums of products, then every channel choice in closed form.
            double saa[4][4] = {}, sfa[2][4][4] = {}, sff[2][4] = {}, sf[2][4] = {};
            for (std::size_t p = 0; p < points; ++p) {
                const double* x = &vals[p * static_cast<std::size_t>(nc)];
                for (int a = 0; a < nc; ++a)
                    for (int b = a; b < nc; ++b) saa[a][b] += x[a] * x[b];
                for (int f = 0; f < nf && f < 4; ++f) {
                    const double fv[2] = {F[p * static_cast<std::size_t>(nf) + static_cast<std::size_t>(f)],
                                          G[p * static_cast<std::size_t>(nf) + static_cast<std::size_t>(f)]};
                    for (int tr = 0; tr < 2; ++tr) {
                        sff[tr][f] += fv[tr] * fv[tr];
                        sf[tr][f] += fv[tr];
                        for (int a = 0; a < nc; ++a) sfa[tr][f][a] += fv[tr] * x[a];
                    }
                }
            }
            for (int tr = 0; tr < 2; ++tr) {
                double total = 0.0;
                for (int f = 0; f < nf && f < 4; ++f) {
                    double e = HUGE_VAL;
                    for (const auto& sum : sums) {
                        double sse = sff[tr][f];
                        for (std::size_t i = 0; i < sum.size(); ++i) {
                            sse -= 2 * sfa[tr][f][sum[i]];
                            for (std::size_t k = 0; k < sum.size(); ++k) {
                                const int a = std::min(sum[i], sum[k]), b = std::max(sum[i], sum[k]);
                                sse += saa[a][b];
                            }
                        }
                        e = std::min(e, sse);
                    }
                    if (f > 0) {
                        e = std::min(e, sff[tr][f]);
                        e = std::min(e, sff[tr][f] - 2 * sf[tr][f] + static_cast<double>(points));
                    }
                    total += std::max(e, 0.0);
                }
                Coarse c;
                c.score = total;
                c.cost = v.cost + c0.cost + c1.cost + task.order + tr;
                c.variant = task.variant;
                c.order = task.order;
                c.c0 = task.c0;
                c.c1 = ci;
                c.values = tr ? ValueTransform::srgb : ValueTransform::none;
                best.push_back(c);
            }
            if (best.size() > 4 * (kKeepLinear + kKeepSrgb)) {
                std::vector<Coarse> lin, srgb;
                for (const Coarse& c : best) (c.values == ValueTransform::none ? lin : srgb).push_back(c);
                keep_best(lin, kKeepLinear);
                keep_best(srgb, kKeepSrgb);
                best = lin;
                best.insert(best.end(), srgb.begin(), srgb.end());
            }
        }
        task_best[ti] = std::move(best);
    });
    std::vector<Coarse> lin, srgb;
    for (const auto& tb : task_best)
        for (const Coarse& c : tb) (c.values == ValueTransform::none ? lin : srgb).push_back(c);
    for (const Task& t : tasks) {
        const Variant& v = variants[t.variant];
        const int s0 = t.order == 0 ? 0 : 1;
        const int c0 = cand_cache.at(std::make_tuple(v.def, 0, counts[s0]))[t.c0].cost;
        if (ndim == 1) {
            ++report.coarse_candidates;
            continue;
        }
        for (const AxisCandidate& c1 : cand_cache.at(std::make_tuple(v.def, 1, counts[1 - s0])))
            if (c0 + c1.cost <= kMaxLayoutCost) ++report.coarse_candidates;
    }
    report.coarse_candidates *= 2;  // values as they are, and through the sRGB EOTF
    keep_best(lin, kKeepLinear);
    keep_best(srgb, kKeepSrgb);
    std::sort(lin.begin(), lin.end(), coarse_less);
    std::sort(srgb.begin(), srgb.end(), coarse_less);
    std::vector<Coarse> keep = lin;
    keep.insert(keep.end(), srgb.begin(), srgb.end());

    // Refinement: exact values at a larger subset, with clamp variants.
    struct Job {
        LutDescription d;
        int cost;
    };
    std::vector<Job> jobs;
    for (const Coarse& c : keep) {
        const Variant& v = variants[c.variant];
        const int s0 = c.order == 0 ? 0 : 1;
        LutDescription d;
        d.def = v.def;
        d.settings = default_settings(*v.def);
        d.settings.params = v.params;
        d.settings.axes.clear();
        if (ndim == 1) {
            d.settings.axes.push_back(cand_cache.at(std::make_tuple(v.def, 0, counts[0]))[c.c0].axis);
        } else {
            const Axis& a0 = cand_cache.at(std::make_tuple(v.def, 0, counts[s0]))[c.c0].axis;
            const Axis& a1 = cand_cache.at(std::make_tuple(v.def, 1, counts[1 - s0]))[c.c1].axis;
            d.settings.axes = s0 == 0 ? std::vector<Axis>{a0, a1} : std::vector<Axis>{a1, a0};
        }
        d.values = c.values;
        // Clamp variants at the lower domain end of each axis that reaches it.
        std::vector<std::vector<Axis>> per_axis;
        for (const Axis& a : d.settings.axes) {
            std::vector<Axis> opts{a};
            const AxisSpec* spec = nullptr;
            for (const AxisSpec& sp : v.def->axes)
                if (sp.axis.name == a.name) spec = &sp;
            if (spec && std::min(a.value(0), a.value(a.count - 1)) <= spec->domain_min && a.clamp_lo <= spec->domain_min)
                for (double frac : kEndClamps) {
                    Axis b = a;
                    b.clamp_lo = spec->domain_min + frac * std::abs(a.max - a.min);
                    opts.push_back(b);
                }
            per_axis.push_back(opts);
        }
        for (std::size_t i = 0; i < per_axis[0].size(); ++i)
            for (std::size_t k = 0; k < (ndim == 2 ? per_axis[1].size() : 1); ++k) {
                Job j{d, c.cost + (i > 0) + (k > 0)};
                j.d.settings.axes[0] = per_axis[0][i];
                if (ndim == 2) j.d.settings.axes[1] = per_axis[1][k];
                jobs.push_back(j);
            }
    }
    // Drop repeated jobs (the same description reached twice).
    {
        std::vector<Job> unique;
        std::vector<std::string> seen;
        for (Job& j : jobs) {
            const std::string key = compare_arguments(j.d, img);
            if (std::find(seen.begin(), seen.end(), key) != seen.end()) continue;
            seen.push_back(key);
            unique.push_back(std::move(j));
        }
        jobs = std::move(unique);
    }
    report.refined_candidates = jobs.size();
    const std::vector<int> rpos[2] = {subset_positions(counts[0], kRefinePerAxis),
                                      subset_positions(ndim == 2 ? counts[1] : 1, kRefinePerAxis)};
    std::vector<std::pair<int, int>> points;
    for (int y : rpos[1])
        for (int x : rpos[0]) points.push_back({x, y});
    std::vector<double> file_points;
    for (const auto& [x, y] : points)
        for (int f = 0; f < nf; ++f) file_points.push_back(pixel(img, x, y, f));
    std::vector<Refined> refined(jobs.size());
    std::vector<char> refined_ok(jobs.size(), 0);
    // One exact evaluation per (job, point), in parallel; each writes its slot.
    std::vector<std::unique_ptr<TexelEvaluator>> evaluators(jobs.size());
    std::vector<std::vector<int>> orders(jobs.size());
    parallel_for_index(jobs.size(), opt.threads, [&](std::size_t i) {
        TableSettings s = jobs[i].d.settings;
        s.quality = Quality::standard;
        try {
            validate_settings(*jobs[i].d.def, s);
            orders[i] = definition_axis_order(*jobs[i].d.def, s);
            evaluators[i] = jobs[i].d.def->prepare(s).evaluator;
        } catch (const std::exception&) {
            evaluators[i].reset();
        }
    });
    std::vector<std::vector<double>> exact(jobs.size());
    for (std::size_t i = 0; i < jobs.size(); ++i)
        if (evaluators[i]) exact[i].assign(points.size() * jobs[i].d.def->channels.size(), 0.0);
    parallel_for_index(jobs.size() * points.size(), opt.threads, [&](std::size_t k) {
        const std::size_t i = k / points.size(), p = k % points.size();
        if (!evaluators[i]) return;
        const auto& axes = jobs[i].d.settings.axes;
        double coords[3] = {0.0, 0.0, 0.0};
        const int idx[2] = {points[p].first, points[p].second};
        for (std::size_t a = 0; a < axes.size(); ++a)
            coords[orders[i][a]] = axes[a].value(idx[a]);
        const std::size_t texel = static_cast<std::size_t>(idx[1]) * static_cast<std::size_t>(counts[0]) +
                                  static_cast<std::size_t>(idx[0]);
        const TexelValue tv = evaluators[i]->evaluate(coords, texel);
        const std::size_t nc = jobs[i].d.def->channels.size();
        for (std::size_t c = 0; c < nc; ++c) exact[i][p * nc + c] = tv.value[c];
    });
    for (std::size_t i = 0; i < jobs.size(); ++i) {
        if (!evaluators[i]) continue;
        Refined& r = refined[i];
        r.d = jobs[i].d;
        r.cost = jobs[i].cost;
        choose_channels(exact[i], file_points, points.size(), static_cast<int>(r.d.def->channels.size()), nf,
                        r.d.values, r);
        refined_ok[i] = 1;
    }
    std::vector<Refined> ranked;
    for (std::size_t i = 0; i < jobs.size(); ++i)
        if (refined_ok[i]) ranked.push_back(std::move(refined[i]));
    std::stable_sort(ranked.begin(), ranked.end(), refined_less);

    // Final: the best distinct descriptions in full, scored as compare does.
    std::vector<std::string> seen;
    const Tolerance tol = default_tolerance(img);
    for (const Refined& r : ranked) {
        if (static_cast<int>(report.explanations.size()) >= opt.top) break;
        const std::string args = compare_arguments(r.d, img);
        if (std::find(seen.begin(), seen.end(), args) != seen.end()) continue;
        seen.push_back(args);
        Explanation e;
        e.description = r.d;
        e.cost = r.cost;
        GenerateOptions g;
        g.threads = opt.threads;
        Table t = generate(*r.d.def, r.d.settings, g);
        apply_value_transform(t, r.d.values);
        const CompareReport rep = compare_values(img, t, 0, tol);
        double sum_sq = 0.0;
        for (const ChannelError& c : rep.channels) {
            e.max_error = std::max(e.max_error, c.max_abs);
            sum_sq += c.rms * c.rms;
        }
        e.rms_error = std::sqrt(sum_sq / static_cast<double>(std::max<std::size_t>(rep.channels.size(), 1)));
        e.pass = rep.pass();
        e.tolerance = tol;
        e.padding = r.padding;
        e.findings = describe_findings(r.d);
        e.compare_arguments = args;
        report.explanations.push_back(std::move(e));
    }
    std::stable_sort(report.explanations.begin(), report.explanations.end(), explanation_less);
    return report;
}

// The 2-D shapes W x H (both at least kMinFactor) of a flat array of n texels.
constexpr int kMinFactor = 4;
std::vector<std::pair<int, int>> factorizations(int n) {
    std::vector<std::pair<int, int>> out;
    for (int w = kMinFactor; w <= n / kMinFactor; ++w)
        if (n % w == 0) out.emplace_back(w, n / w);
    return out;
}

}  // namespace

IdentifyReport identify(const ExrImage& img, const IdentifyOptions& opt) {
    if (opt.top < 1 || opt.top > 50)
        throw Error("--top " + std::to_string(opt.top) + " is out of range; allowed: 1 to 50");
    if (opt.threads < 0)
        throw Error("--threads " + std::to_string(opt.threads) + " is out of range; allowed: 0 (all) or more");
    const std::vector<std::pair<int, int>> shapes = is_flat(img) ? factorizations(img.width) : std::vector<std::pair<int, int>>{};
    const int ndim = img.height == 1 ? 1 : 2;
    const std::vector<Variant>* variants = nullptr;
    try {
        variants = &tabulated_variants(ndim, opt.threads);
    } catch (const RuntimeError&) {
        if (shapes.empty()) throw;
    }
    IdentifyReport report = variants == nullptr ? IdentifyReport{} : identify_shape(img, opt, *variants);
    if (shapes.empty()) return report;
    // A flat array: also each factorization of its length as a 2-D table.
    const std::vector<Variant>& variants2 = tabulated_variants(2, opt.threads);
    for (const auto& [w, h] : shapes) {
        ExrImage shaped = img;
        shaped.width = w;
        shaped.height = h;
        IdentifyReport r = identify_shape(shaped, opt, variants2);
        report.tables += r.tables;
        report.coarse_candidates += r.coarse_candidates;
        report.refined_candidates += r.refined_candidates;
        for (Explanation& e : r.explanations) {
            // compare gives a flat array the table's default counts: name others.
            const auto& axes = e.description.settings.axes;
            const auto& def = default_settings(*e.description.def).axes;
            bool own = true;
            for (std::size_t i = 0; i < axes.size(); ++i)
                for (const Axis& d : def)
                    if (d.name == axes[i].name && d.count != axes[i].count) own = false;
            if (!own) e.compare_arguments += " --size " + std::to_string(w) + "x" + std::to_string(h);
            e.flat_shape = std::to_string(w) + "x" + std::to_string(h);
            report.explanations.push_back(std::move(e));
        }
    }
    std::stable_sort(report.explanations.begin(), report.explanations.end(), explanation_less);
    if (report.explanations.size() > static_cast<std::size_t>(opt.top))
        report.explanations.resize(static_cast<std::size_t>(opt.top));
    return report;
}

}  // namespace brdflut
