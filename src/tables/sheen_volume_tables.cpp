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
#include "tables/checks.h"
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

// The discretization per quality, and the error the tests hold each to
// (tests/test_sheen_volume.cpp: against solves at twice the nodes and
// steps): directions per panel, depth refinement, absolute error.
struct Resolution {
    int nodes_per_panel;
    int depth_refine;
    double error;
};
Resolution resolution(Quality q) {
    switch (q) {
        case Quality::draft: return {8, 1, 2e-4};
        case Quality::reference: return {24, 2, 5e-6};
        default: return {12, 1, 2e-5};
    }
}

SheenVolumeOptions options_for(const Resolution& r) {
    SheenVolumeOptions o;
    o.nodes_per_panel = r.nodes_per_panel;
    o.depth_refine = r.depth_refine;
    o.cut_after = kTalkBounces;
    return o;
}

// Solves already made, one an (alpha, resolution): a solve is deterministic,
// so a kept one is what a fresh one would be. The first caller of a key
// solves; later callers wait for it.
class LayerCache {
public:
    std::shared_ptr<const SheenVolumeLayer> get(double alpha, const Resolution& r) {
        const Key key{tables::key_bits(alpha), static_cast<std::uint64_t>(r.nodes_per_panel * 16 + r.depth_refine)};
        std::shared_ptr<Slot> slot;
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            auto it = slots_.find(key);
            if (it == slots_.end()) {
                if (slots_.size() >= kMaxSlots) slots_.clear();  // bounded: beyond it, solves are redone
                it = slots_.emplace(key, std::make_shared<Slot>()).first;
            }
            slot = it->second;
        }
        std::call_once(slot->once, [&] { slot->layer = std::make_shared<const SheenVolumeLayer>(alpha, options_for(r)); });
        return slot->layer;
    }
    void clear() {
        const std::lock_guard<std::mutex> lock(mutex_);
        slots_.clear();
    }
    static LayerCache& instance() {
        static LayerCache cache;
        return cache;
    }

private:
    LayerCache() : id_(tables::register_shared_results([this] { clear(); })) {}
    using Key = std::array<std::uint64_t, 2>;
    struct Slot {
        std::once_flag once;
        std::shared_ptr<const SheenVolumeLayer> layer;
    };
    static constexpr std::size_t kMaxSlots = 128;
    std::mutex mutex_;
    std::map<Key, std::shared_ptr<Slot>> slots_;
    std::size_t id_;
};

class VolumeEvaluator final : public TexelEvaluator {
public:
    explicit VolumeEvaluator(const TableSettings& s) : resolution_(resolution(s.quality)) {}

    TexelValue evaluate(const double* c, std::uint64_t) const override {
        TexelValue out;
        const double mu = std::max(c[0], kMinMu), alpha = std::clamp(c[1], kMinAlpha, 1.0);
        try {
            const std::array<double, 3> r = LayerCache::instance().get(alpha, resolution_)->reflectances(mu);
            for (std::size_t k = 0; k < 3; ++k) {
                out.value[k] = r[k];
                out.error[k] = resolution_.error;
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
            {"abs_error", r.error},
            {"error_basis", "the largest difference from solves at finer direction and depth grids, measured by "
                            "tests/test_sheen_volume.cpp"}};
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

// R and R16 against solves on grids refined in both directions and depth
// (the reference quality's): the stated discretization error.
ClosedFormCheck refined_grid_check() {
    return {"R and R16 vs solves at 24 nodes a panel and a twice-refined depth mesh", 2e-5,
            [](const TexelEvaluator& e) {
                CheckResult worst{0.0, ""};
                const Resolution fine = resolution(Quality::reference);
                for (const auto& p : std::vector<std::array<double, 2>>{{0.02, 0.5}, {0.6, 1.0}}) {
                    const TexelValue v = e.evaluate(p.data(), 0);
                    const std::array<double, 3> fine_r = LayerCache::instance().get(p[1], fine)->reflectances(p[0]);
                    for (std::size_t k = 0; k < 2; ++k) {
                        const double err = std::abs(v.value[k] - fine_r[k]);
                        if (!(err <= worst.first))
                            worst = {err, "channel " + std::to_string(k) + " " + tables::point_text(p)};
                    }
                }
                return worst;
            }};
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
         "scattered more than 16 times (docs/engines.md)."});
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
    d.prepare = [](const TableSettings& s) {
        PreparedTable p;
        p.evaluator = std::make_unique<VolumeEvaluator>(s);
        p.model = volume_model();
        p.method = volume_method(s.quality);
        return p;
    };
    d.checks = {single_scattering_check(), refined_grid_check()};
    family.tables.push_back(std::move(d));
}

}  // namespace brdflut
