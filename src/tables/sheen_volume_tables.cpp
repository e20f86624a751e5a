// The simulated layer of Zeltner, Burley and Chiang 2022 (sheen_volume.h):
// its directional albedo, computed deterministically, three ways: the
// layer's own (every scattering order), the talk's random walk cut after 16
// scatterings (what the shipped tables hold), and its single scattering.
// One solve serves every mu of one alpha, so the evaluator keeps the solves
// it has made.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>

#include "brdflut/sheen_volume.h"
#include "brdflut/zeltner_sheen.h"
#include "brdflut/ltc_fit.h"
#include "tables/checks.h"
#include "tables/ltc_tables.h"
#include "tables/registry.h"
#include "tables/shared_results.h"

namespace brdflut {
namespace sheen_volume_family {  // this family's own names, apart from the other families' in a unity build
namespace {

constexpr double kMinAlpha = 0.01;
constexpr double kMinMu = 0.01;
// The talk's walk: 16 scatterings (tizian/ltc-sheen
// fitting/python/precompute_brdf_values_sheen_volume.py, maxBounces).
constexpr int kTalkBounces = 16;

// The discretization per quality: directions per panel, depth refinement,
// an absolute error floor, and the directions per panel of the coarser
// companion solve. The error stated for each value is the larger of the
// floor and the value's difference from the companion's (value_errors):
// the direction grid's error falls about fourfold from 8 to 12 nodes a
// panel, so the difference is about three times the finer solve's own
// error where the grid matters (small alpha and grazing light: 5.7e-5 at
// alpha = 0.047, cos(theta) = 0.047 for 12 nodes against a solve at 32
// nodes and a twice-refined depth mesh), and the floor, which solves on
// finer grids confirm at moderate alpha (tests/test_sheen_volume.cpp),
// holds elsewhere.
struct Resolution {
    int nodes_per_panel;
    int depth_refine;
    double error;
    int coarse_nodes;
};
Resolution resolution(Quality q) {
    switch (q) {
        case Quality::draft: return {8, 1, 2e-4, 6};
        case Quality::reference: return {24, 2, 5e-6, 16};
        default: return {12, 1, 2e-5, 8};
    }
}
// The companion solve of a resolution.
Resolution coarse(const Resolution& r) { return {r.coarse_nodes, r.depth_refine, r.error, r.coarse_nodes}; }

// every_order: the layer's own albedo too (a BiCGSTAB solve, most of the
// cost); without it, the single scattering and the talk's cut walk only.
SheenVolumeOptions options_for(const Resolution& r, bool every_order) {
    SheenVolumeOptions o;
    o.nodes_per_panel = r.nodes_per_panel;
    o.depth_refine = r.depth_refine;
    o.cut_after = kTalkBounces;
    o.every_order = every_order;
    return o;
}

// Values already made, one a key (a layer solve, a lobe's doubling): each is
// deterministic, so a kept one is what a fresh one would be. The first
// caller of a key makes it; later callers wait for it.
template <class Value>
class OnceCache {
public:
    using Key = std::array<std::uint64_t, 2>;
    template <class Make>
    std::shared_ptr<const Value> get(const Key& key, Make&& make) {
        std::shared_ptr<Slot> slot;
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            auto it = slots_.find(key);
            if (it == slots_.end()) {
                if (slots_.size() >= kMaxSlots) slots_.clear();  // bounded: beyond it, values are remade
                it = slots_.emplace(key, std::make_shared<Slot>()).first;
            }
            slot = it->second;
        }
        std::call_once(slot->once, [&] { slot->value = make(); });
        return slot->value;
    }
    // Whether a value of the key is made or being made.
    bool contains(const Key& key) {
        const std::lock_guard<std::mutex> lock(mutex_);
        return slots_.count(key) != 0;
    }
    static OnceCache& instance() {
        static OnceCache cache;
        return cache;
    }

private:
    OnceCache() : id_(tables::register_shared_results([this] { clear(); })) {}
    void clear() {
        const std::lock_guard<std::mutex> lock(mutex_);
        slots_.clear();
    }
    struct Slot {
        std::once_flag once;
        std::shared_ptr<const Value> value;
    };
    static constexpr std::size_t kMaxSlots = 128;
    std::mutex mutex_;
    std::map<Key, std::shared_ptr<Slot>> slots_;
    std::size_t id_;
};

// every_order false: the cut walk and the single scattering only, unless
// the every-order layer at (alpha, r) is already made, which holds them too
// (the same values: they are computed alike with or without the solve).
std::shared_ptr<const SheenVolumeLayer> layer_at(double alpha, const Resolution& r, bool every_order = true) {
    OnceCache<SheenVolumeLayer>& cache = OnceCache<SheenVolumeLayer>::instance();
    auto key = [&](bool every) -> OnceCache<SheenVolumeLayer>::Key {
        return {tables::key_bits(alpha),
                static_cast<std::uint64_t>((r.nodes_per_panel * 16 + r.depth_refine) * 2 + (every ? 1 : 0))};
    };
    if (!every_order && cache.contains(key(true))) every_order = true;
    return cache.get(key(every_order),
                     [&] { return std::make_shared<const SheenVolumeLayer>(alpha, options_for(r, every_order)); });
}

// The stated error of the reflectances at (mu, alpha) on resolution r:
// per channel, the larger of r's floor and the difference from the coarser
// companion solve (the every-order channel only when every_order).
std::array<double, 3> value_errors(double alpha, double mu, const Resolution& r, bool every_order,
                                   const std::array<double, 3>& values) {
    const std::array<double, 3> c = layer_at(alpha, coarse(r), every_order)->reflectances(mu);
    std::array<double, 3> e;
    for (std::size_t k = 0; k < 3; ++k)
        e[k] = k == 0 && !every_order ? HUGE_VAL : std::max(r.error, std::abs(values[k] - c[k]));
    return e;
}

std::shared_ptr<const SheenVolumeLobe> lobe_at(double alpha) {
    return OnceCache<SheenVolumeLobe>::instance().get({tables::key_bits(alpha), 0},
                                                      [&] { return std::make_shared<const SheenVolumeLobe>(alpha); });
}

class VolumeEvaluator final : public TexelEvaluator {
public:
    explicit VolumeEvaluator(const TableSettings& s) : resolution_(resolution(s.quality)) {}

    TexelValue evaluate(const double* c, std::uint64_t) const override {
        TexelValue out;
        const double mu = std::max(c[0], kMinMu), alpha = std::clamp(c[1], kMinAlpha, 1.0);
        try {
            const std::array<double, 3> r = layer_at(alpha, resolution_)->reflectances(mu);
            const std::array<double, 3> e = value_errors(alpha, mu, resolution_, true, r);
            for (std::size_t k = 0; k < 3; ++k) {
                out.value[k] = r[k];
                out.error[k] = e[k];
            }
        } catch (const std::exception&) {
            out.value.fill(std::nan(""));
            out.error.fill(HUGE_VAL);
        }
        return out;
    }

private:
    Resolution resolution_;
};

nlohmann::json volume_model() {
    return {{"brdf",
             "Zeltner, Burley and Chiang 2022 volumetric sheen, the simulated layer (the talk's \"volume\" table): "
             "directional albedo, no Fresnel"},
            {"layer", "unit thickness and density, single-scattering albedo 1, nothing below; SGGX S = diag(1, 1, "
                      "sigma^2), sigma = alpha^2, specular microflake phase function"},
            {"channels", "R: every scattering order; R16: the talk's random walk, cut after 16 scatterings, a walk "
                         "still inside then counted when its direction points up; R_ss: single scattering"},
            {"roughness", "alpha, the talk's roughness (sigma = alpha^2), linear on the axis as in its tables"},
            {"source", "tizian/ltc-sheen fitting/src/bsdfs/sheen_volume.h and "
                       "fitting/python/precompute_brdf_values_sheen_volume.py @92624114a8ffc433389256f79a10332e54ba17f6"}};
}

nlohmann::json volume_method(Quality q) {
    const Resolution r = resolution(q);
    return {{"rule",
             "deterministic plane-parallel transport (sheen_volume.h): azimuthally averaged phase function in closed "
             "form; direction cosines on Gauss-Legendre panels graded towards the horizon, scattering by product "
             "integration against the local cubic; depth mesh graded towards both faces, exponential transport "
             "integrated exactly against the local cubic; every order by BiCGSTAB to a residual of 1e-14; alpha "
             "below 0.01 computed at 0.01, cos_theta below 0.01 at 0.01"},
            {"nodes_per_panel", r.nodes_per_panel},
            {"depth_refine", r.depth_refine},
            {"abs_error_floor", r.error},
            {"coarse_nodes_per_panel", r.coarse_nodes},
            {"error_basis", "per value, the larger of abs_error_floor and the difference from a solve at "
                            "coarse_nodes_per_panel direction nodes a panel (the direction grid's error falls about "
                            "fourfold from 8 to 12 nodes); the table's checks and tests/test_sheen_volume.cpp hold "
                            "values to solves at finer direction and depth grids within it"}};
}

// ---------------------------------------------------------------------------
// Checks.

using CheckResult = tables::CheckResult;

// The single scattering of the talk's analytic sheen, f_ss, is the exact
// single scattering of this layer: its albedo through the generic lobe path
// (adaptive quadrature over the hemisphere of the BRDF) is a second route.
class SingleScatteringLobe final : public GenericLobe {
public:
    explicit SingleScatteringLobe(double alpha) : lobe_(alpha) {}
    double f(const Vec3& wo, const Vec3& wi) const override { return lobe_.terms(wo, wi)[0]; }
    bool has_sampler() const override { return true; }
    LobeSample sample(const Vec3& wo, double u1, double u2) const override { return lobe_.sample(wo, u1, u2); }

private:
    ZeltnerApproxSheenLobe lobe_;
};

ClosedFormCheck single_scattering_check() {
    return {"R_ss vs the albedo of the analytic sheen's single-scattering term f_ss (generic lobe path)", 2e-5,
            [](const TexelEvaluator& e) {
                const std::vector<std::array<double, 2>> pts = {{0.05, 0.9}, {0.3, 0.2}, {0.7, 0.6}, {0.5, 0.1}, {1.0, 0.4}};
                return tables::worst_over(e, pts, 2, [](const auto& p) {
                    GenericOptions opt;
                    opt.abs_tol = 1e-9;
                    return generic_albedo(SingleScatteringLobe(p[1]), p[0], opt).value[0];
                });
            }};
}

// Each value against a solve on a finer grid, as a multiple of the value's
// stated error (value_errors; at most 1). The points: grazing light at
// alpha = 0.047, where the direction grid matters most of the table's
// texels (the standard grid is 5.4e-5 off there, above its floor), and
// moderate alpha at grazing and normal light. The finer solve: 24 nodes a
// panel, the standard depth mesh (a twice-refined one moves these values by
// less than 4e-6, and costs twice as much).
constexpr Resolution kCheckResolution{24, 1, 0.0, 24};
std::vector<std::array<double, 2>> refined_check_points() {
    return {{0.046875, 0.046875}, {0.02, 0.5}, {0.6, 1.0}};
}
CheckResult against_refined(const TexelEvaluator& e, const std::vector<std::size_t>& channels, bool every_order,
                            std::size_t layer_channel_of_first) {
    CheckResult worst{0.0, ""};
    for (const auto& p : refined_check_points()) {
        const TexelValue v = e.evaluate(p.data(), 0);
        const std::array<double, 3> fine = layer_at(p[1], kCheckResolution, every_order)->reflectances(p[0]);
        for (std::size_t i = 0; i < channels.size(); ++i) {
            const std::size_t k = channels[i];
            const double ratio = std::abs(v.value[k] - fine[layer_channel_of_first + i]) / v.error[k];
            if (!(ratio <= worst.first)) worst = {ratio, "channel " + std::to_string(k) + " " + tables::point_text(p)};
        }
    }
    return worst;
}

ClosedFormCheck refined_grid_check() {
    return {"R and R16 vs solves at 24 nodes a panel: the difference as a multiple of each value's stated error", 1.0,
            [](const TexelEvaluator& e) { return against_refined(e, {0, 1}, true, 0); }};
}

// ---------------------------------------------------------------------------
// The talk's LTC as Cycles ships it (table_sheen_ltc): the layer's BRDF
// (SheenVolumeLobe) fitted in the talk's two-parameter form, with the
// layer's albedo.

constexpr double kLtcNormTolerance = 1e-7;
constexpr const char* kCyclesSheenSource =
    "blender/cycles src/scene/shader.tables table_sheen_ltc @97dbe6f57cdf4ede2d2b75ebdda507c8712edb7a (three planes "
    "A, B, R of [alpha][mu]), from tizian/ltc-sheen fitting/python/fit_ltc_sheen_volume.py "
    "@92624114a8ffc433389256f79a10332e54ba17f6";

int fit_level(Quality q) { return q == Quality::draft ? 0 : q == Quality::reference ? 2 : 1; }

// The lobe at a texel, its norm known: the single scattering's albedo is the
// layer's R_ss, the multiple scattering's the interpolant's own integral
// (no quadrature of f over the hemisphere, which cost most of a fit).
LtcLobe volume_ltc_lobe(double mu, double alpha) {
    const std::shared_ptr<const SheenVolumeLobe> lobe = lobe_at(alpha);
    const Resolution r = resolution(Quality::standard);
    LtcLobe l(lobe, mu, alpha, ltc_lobe_key("sheen_volume"), kLtcNormTolerance);
    l.known_n0 = layer_at(alpha, r, false)->reflectances(l.mu_o)[2] + lobe->multiple_scattering_albedo(l.mu_o);
    l.known_n0_error = r.error;
    return l;
}

LtcFitOptions volume_fit_options(Quality q) {
    LtcFitOptions o = ltc_fit_options(fit_level(q));
    o.two_parameter = true;
    return o;
}

// Which albedo the LTC's magnitude R is (`--sheen_orders`).
ModelOption orders_option() {
    return {"sheen_orders",
            "albedo of the Zeltner 2022 sheen layer: talk (the talk's random walk cut after 16 scatterings, a walk "
            "still inside then counted when it points up: what Cycles and Adobe ship) or all (every scattering order, "
            "the layer's own)",
            "talk",
            {"talk", "all"}};
}

class CyclesLtcEvaluator final : public TexelEvaluator {
public:
    explicit CyclesLtcEvaluator(const TableSettings& s)
        : quality_(s.quality), resolution_(resolution(s.quality)), talk_(tables::param(s, "sheen_orders") == "talk") {}

    TexelValue evaluate(const double* c, std::uint64_t) const override {
        TexelValue out;
        const double mu = std::max(c[0], kMinMu), alpha = std::clamp(c[1], kMinAlpha, 1.0);
        try {
            const LtcFit fit = fit_ltc(volume_ltc_lobe(mu, alpha), volume_fit_options(quality_));
            const Mat3 m = fit.minv.matrix();
            out.value[0] = m.m[0][0] / m.m[2][2];
            out.value[1] = m.m[0][2] / m.m[2][2];
            const std::array<double, 3> r = layer_at(alpha, resolution_, !talk_)->reflectances(mu);
            const std::size_t k = talk_ ? 1 : 0;
            out.value[2] = r[k];
            out.error[2] = value_errors(alpha, mu, resolution_, !talk_, r)[k];
            out.evaluations = fit.evaluations;
        } catch (const std::exception&) {
            out.value.fill(std::nan(""));
            out.error.fill(HUGE_VAL);
        }
        return out;
    }

private:
    Quality quality_;
    Resolution resolution_;
    bool talk_;
};

AxisSpec talk_axis(AxisSpec a) {
    a.axis.placement = Placement::endpoints;
    a.axis.clamp_lo = 0.01;
    a.axis.clamp_hi = a.axis.max;
    a.meaning += "; at least 0.01 (the talk's grid: max(0.01, i/31))";
    return a;
}

// R (the talk's cut walk, the default) against a solve on a finer grid, as
// a multiple of its stated error.
ClosedFormCheck ltc_albedo_check() {
    return {"R vs a solve at 24 nodes a panel: the difference as a multiple of its stated error", 1.0,
            [](const TexelEvaluator& e) { return against_refined(e, {2}, false, 1); }};
}

// Each stored (A, B) is a local minimum of the two-parameter objective: the
// largest relative drop of the objective when ln(1/A) or B moves by 1e-3.
ClosedFormCheck ltc_minimum_check() {
    return {"(A, B) is a local minimum of the fit's two-parameter objective (largest relative drop)", 1e-6,
            [](const TexelEvaluator& e) {
                CheckResult worst{0.0, ""};
                for (const auto& p : std::vector<std::array<double, 2>>{{0.3, 0.5}, {0.9, 0.5}}) {
                    const TexelValue v = e.evaluate(p.data(), 0);
                    LtcFit fit;
                    fit.params = {0.0, -std::log(v.value[0]), -std::log(v.value[0]), -v.value[1]};
                    const double drop = std::max(
                        0.0, ltc_local_minimum_drop(volume_ltc_lobe(p[0], p[1]), fit, volume_fit_options(Quality::standard)));
                    if (!(drop <= worst.first)) worst = {drop, tables::point_text(p)};
                }
                return worst;
            }};
}

// The BRDF the fit uses against the layer: its albedo (the generic path's
// quadrature of f) against R, relative. The multiple scattering is
// reconstructed from the discrete layer's masses, least accurately near the
// normal: 0.34 % at cos(theta) = 1, alpha = 0.5.
ClosedFormCheck ltc_lobe_check() {
    return {"albedo of the fitted BRDF (generic lobe path) vs the layer's (every order), relative", 0.01,
            [](const TexelEvaluator&) {
                CheckResult worst{0.0, ""};
                for (const auto& p : std::vector<std::array<double, 2>>{{0.3, 0.5}, {1.0, 0.5}, {0.05, 0.5}}) {
                    GenericOptions opt;
                    opt.abs_tol = 1e-7;
                    const double albedo = generic_albedo(*lobe_at(p[1]), p[0], opt).value[0];
                    // Against the layer's albedo (every order), which the BRDF is.
                    const double layer = layer_at(p[1], resolution(Quality::standard))->reflectances(p[0])[0];
                    const double err = std::abs(albedo - layer) / layer;
                    if (!(err <= worst.first)) worst = {err, tables::point_text(p)};
                }
                return worst;
            }};
}

TableDefinition cycles_sheen_ltc() {
    TableDefinition d;
    d.id = "cycles_sheen_ltc";
    d.description = "Cycles table_sheen_ltc: Zeltner 2022 sheen LTC of the simulated layer, M^-1 = [[A, 0, B], [0, A, "
                    "0], [0, 0, 1]], and the layer's albedo R";
    d.axes = {talk_axis(tables::cos_theta_axis(32)),
              talk_axis({Axis{"alpha", 0.0, 1.0, 32, Placement::endpoints, Warp::linear}, 0.0, 1.0,
                         "alpha, the roughness of Zeltner et al. 2022 (SGGX fibre cross-section sigma = alpha^2)"})};
    d.channels = {"A: aInv, M^-1[0][0] = M^-1[1][1] of the fitted LTC (M^-1[2][2] = 1)", "B: bInv, M^-1[0][2]",
                  "R: the layer's albedo (--sheen_orders: the talk's cut walk, sheen_volume_albedo R16, by default; "
                  "every order, R, with all)"};
    d.options = {orders_option()};
    d.preset = "cycles";
    d.engine_source = kCyclesSheenSource;
    d.supports_monte_carlo = false;
    d.searched_by_identify = false;  // a fit a texel
    d.solve_per_parameter = true;  // a layer and a BRDF an alpha
    d.prepare = [](const TableSettings& s) {
        PreparedTable p;
        p.evaluator = std::make_unique<CyclesLtcEvaluator>(s);
        p.model = volume_model();
        p.model["preset"] = "cycles";
        p.model["engine_source"] = kCyclesSheenSource;
        p.model["albedo"] = tables::param(s, "sheen_orders") == "talk"
                                ? "R: the talk's random walk cut after 16 scatterings (its expectation)"
                                : "R: every scattering order";
        p.model["fit"] =
            "the layer's BRDF: the exact single scattering (f_ss of the analytic sheen) plus the multiple scattering "
            "of the discrete layer by doubling, per azimuthal mode (SheenVolumeLobe); fitted by brdflut's LTC fitter "
            "(ltc_fit.h) in the talk's two-parameter form (no rotation, m22 = m11): Heitz's error measure plus 0.3 "
            "times the triangular discrimination, by quadrature, no light term";
        p.model["layout"] = "the talk's and Cycles' grid; Cycles' source array stores the three channels as planes "
                            "(read it with --shape 32x32:3p)";
        p.method = volume_method(s.quality);
        p.method["fit_quality"] = fit_level(s.quality);
        return p;
    };
    d.checks = {ltc_albedo_check(), ltc_minimum_check(), ltc_lobe_check()};
    return d;
}

}  // namespace
}  // namespace sheen_volume_family

void register_sheen_volume_family(FamilyEntries& family) {
    using namespace sheen_volume_family;
    family.families.push_back(
        {"", "Volumetric sheen, the simulated layer (Zeltner, Burley and Chiang 2022)",
         "The layer that Zeltner, Burley and Chiang 2022 simulate and whose albedo their shipped LTC table holds "
         "(the \"volume\" table: Cycles, Unreal, OSL, Babylon.js and Adobe's OpenPBR ship it): a unit-thickness, "
         "unit-density, non-absorbing slab of fibre-like SGGX microflakes standing along the normal (cross-section "
         "sigma = alpha^2, specular phase function), nothing below. The talk estimated its albedo with 2e6 seeded "
         "random walks a texel, cut after 16 scatterings. Here the transport is solved deterministically "
         "(sheen_volume.h): the albedo only needs the azimuthally averaged phase function, which has a closed "
         "form, so the problem is one-dimensional in depth and in the direction cosine. The table holds the "
         "layer's albedo with every order, the talk's cut walk, and the single scattering; the checks hold the "
         "single scattering to the analytic sheen's f_ss by quadrature over the hemisphere, and the solve to "
         "finer grids. The cut matters: at low roughness and grazing light most of what the layer reflects has "
         "scattered more than 16 times (docs/engines.md). The layer's BRDF (the exact single scattering and the "
         "multiple scattering of the discrete layer by doubling, per azimuthal mode) fitted in the talk's "
         "two-parameter LTC form, with the albedo of the talk's walk (or the layer's, --sheen_orders all), is "
         "cycles_sheen_ltc, in Cycles' layout (the cycles preset)."});
    TableDefinition d;
    d.id = "sheen_volume_albedo";
    d.description = "Zeltner 2022 sheen layer (simulated): albedo R, the talk's 16-scattering walk R16, and R_ss";
    d.axes = {tables::cos_theta_axis(32),
              {Axis{"alpha", 0.0, 1.0, 32, Placement::center, Warp::linear}, 0.0, 1.0,
               "alpha, the roughness of Zeltner et al. 2022 (SGGX fibre cross-section sigma = alpha^2); below 0.01 "
               "computed at 0.01"}};
    d.channels = {"R: fraction of the light leaving through the top, every scattering order",
                  "R16: the same for the talk's walk, cut after 16 scatterings (a walk still inside counted when it "
                  "points up)",
                  "R_ss: the single-scattering part"};
    d.supports_monte_carlo = false;  // the random walk is a test (tests/test_sheen_volume.cpp)
    d.searched_by_identify = false;  // a solve an alpha: seconds
    d.solve_per_parameter = true;
    d.prepare = [](const TableSettings& s) {
        PreparedTable p;
        p.evaluator = std::make_unique<VolumeEvaluator>(s);
        p.model = volume_model();
        p.method = volume_method(s.quality);
        return p;
    };
    d.checks = {single_scattering_check(), refined_grid_check()};
    family.tables.push_back(std::move(d));
    family.tables.push_back(cycles_sheen_ltc());
}

}  // namespace brdflut
