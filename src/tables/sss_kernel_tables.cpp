// Separable subsurface-scattering kernels (Jimenez et al. 2015) baked from a
// diffusion profile: the taps' offsets and per-channel weights, with the
// error of the separable approximation in the metadata; d'Eon and Luebke's
// six-Gaussian skin profile, Burley's normalized diffusion, and Unreal
// Engine's three kernels of a "Separable" subsurface profile; and the
// Burley transmission profile of Unreal's subsurface profile rows.
#include <cmath>
#include <limits>
#include <functional>
#include <memory>
#include <mutex>

#include "brdflut/burley.h"
#include "brdflut/error.h"
#include "brdflut/math.h"
#include "brdflut/separable_sss.h"
#include "tables/checks.h"
#include "tables/registry.h"

namespace brdflut {
namespace sss_kernel_family {  // this family's own names, apart from the other families' in a unity build
namespace {

constexpr tables::Tolerances kTolerances = tables::quadrature_tolerances(1e-10);

const std::vector<std::string> kChannels = {
    "R: weight of the red channel (the mirrored taps' weights add to 1)", "G: weight of the green channel",
    "B: weight of the blue channel", "A: offset of the tap from the centre, in mm"};

struct Tap {
    double offset;
    std::array<double, 3> weight, error;
};

// A value made by the first caller (thread-safe), kept for the others.
template <class T>
class Lazy {
public:
    explicit Lazy(std::function<T()> make) : make_(std::move(make)) {}
    const T& get() const {
        std::call_once(once_, [this] { value_ = make_(); });
        return value_;
    }

private:
    std::function<T()> make_;
    mutable std::once_flag once_;
    mutable T value_{};
};

class KernelEvaluator final : public TexelEvaluator {
public:
    // index_scale: the coordinate times this is the tap's index.
    KernelEvaluator(std::vector<Tap> taps, double index_scale)
        : taps_([t = std::move(taps)] { return t; }), scale_(index_scale) {}
    // The taps made on the first evaluation (a description of the table,
    // `brdflut docs` for example, does not need them).
    KernelEvaluator(std::function<std::vector<Tap>()> make_taps, double index_scale)
        : taps_(std::move(make_taps)), scale_(index_scale) {}
    TexelValue evaluate(const double* c, std::uint64_t) const override {
        TexelValue out;
        const std::vector<Tap>& taps = taps_.get();
        const double x = std::round(c[0] * scale_);
        if (!(x >= 0.0) || x >= static_cast<double>(taps.size())) {
            out.value.fill(NAN);
            return out;
        }
        const Tap& t = taps[static_cast<std::size_t>(x)];
        for (std::size_t k = 0; k < 3; ++k) {
            out.value[k] = t.weight[k];
            out.error[k] = t.error[k];
        }
        out.value[3] = t.offset;
        return out;
    }

private:
    Lazy<std::vector<Tap>> taps_;
    double scale_;
};

std::vector<Tap> taps_of(const SeparableKernel& k) {
    std::vector<Tap> out;
    for (std::size_t i = 0; i < k.offset.size(); ++i) out.push_back({k.offset[i], k.weight[i], k.error[i]});
    return out;
}

nlohmann::json error_json(const SeparableError& e, int taps, double radius) {
    return {{"one_sided_taps", taps},
            {"radius_mm", radius},
            {"misplaced", e.misplaced},
            {"misplaced_error", e.error},
            {"outside", e.outside}};
}

const char* kSeparableErrorMeaning =
    "misplaced: (1/2) sum over tap pairs (a, b) of |w_a w_b - P_ab|, P_ab the profile's mass over the "
    "product of the two taps' cells divided by its mass over the square they cover (nested adaptive "
    "Gauss-Kronrod); outside: the part of the profile's reflectance beyond that square";

// The t axis of a single kernel: tap i of n one-sided taps at t = i/(n - 1)
// (end points), offset radius t^p.
AxisSpec t_axis(int count) {
    return {Axis{"tap_t", 0.0, 1.0, count, Placement::endpoints, Warp::linear}, 0.0, 1.0,
            "t = i / (n - 1) of one-sided tap i (0: the centre), offset = radius t^spacing; the count is the "
            "number of one-sided taps n (the kernel has 2n - 1)"};
}

// Throws unless the axis is the plain t grid, whose positions are the taps.
const Axis& checked_t_axis(const TableSettings& s) {
    const Axis& a = s.axes.at(0);
    if (a.min != 0.0 || a.max != 1.0 || a.placement != Placement::endpoints || a.warp != Warp::linear ||
        a.shift != 0.0 || a.has_clamp())
        throw Error("the tap_t axis of a separable kernel is the tap index over n - 1: only its count (the "
                    "one-sided taps, 2 to 32) may change; allowed: --range tap_t=0:1, end points, linear, no "
                    "shift or clamp");
    if (a.count < 2 || a.count > 32)
        throw Error("--count tap_t=" + std::to_string(a.count) + " is out of range; allowed: 2 to 32 one-sided taps");
    return a;
}

ModelOption shape_option(std::string def) {
    return {"kernel",
            "separable kernel shape at |x|: line R(|x|) (Jimenez, Unreal's Separable profiles), radial |x| R(|x|) "
            "(Unreal's Burley kernel) or marginal, the profile projected onto a line (exact for one Gaussian)",
            std::move(def),
            {"line", "radial", "marginal"}};
}
ModelOption weights_option(std::string def) {
    return {"weights",
            "separable kernel weights: point (the tap's cell width times the shape at the tap, Unreal's rule) "
            "or cell (the shape's integral over the cell)",
            std::move(def),
            {"point", "cell"}};
}
ModelOption radius_option() {
    return {"radius", "separable kernel: offset of the outermost tap, in mm, > 0 and at most 100", "3", {}};
}
ModelOption spacing_option() {
    return {"spacing", "separable kernel: exponent p of the offsets radius t^p, 0.25 to 4 (Unreal: 2)", "2", {}};
}

struct KernelSettings {
    KernelShape shape;
    KernelWeights weights;
    double radius, spacing;
    int taps;
};

KernelSettings kernel_settings(const TableSettings& s) {
    KernelSettings k{};
    k.shape = kernel_shape_from_string(tables::param(s, "kernel"));
    k.weights = kernel_weights_from_string(tables::param(s, "weights"));
    k.radius = tables::parse_number("radius", tables::param(s, "radius"));
    if (!(k.radius > 0.0 && k.radius <= 100.0))
        throw Error("--radius " + tables::param(s, "radius") + " is out of range; allowed: > 0 to 100 (mm)");
    k.spacing = tables::parse_number("spacing", tables::param(s, "spacing"));
    if (!(k.spacing >= 0.25 && k.spacing <= 4.0))
        throw Error("--spacing " + tables::param(s, "spacing") + " is out of range; allowed: 0.25 to 4");
    k.taps = checked_t_axis(s).count;
    return k;
}

const char* kRule =
    "cell weights: adaptive Gauss-Kronrod over each tap's cell (the marginal shape by an inner adaptive "
    "integral in y = x sinh(t)); point weights: the shape at the tap times the cell's width; each channel "
    "divided by its sum over the mirrored taps";

// A table of one kernel of a profile over the t axis.
TableDefinition profile_kernel_table(std::string id, std::string description,
                                     std::function<SkinProfile(const TableSettings&)> profile,
                                     std::function<nlohmann::json(const TableSettings&)> model,
                                     std::vector<ModelOption> extra, std::string default_shape) {
    TableDefinition d;
    d.id = std::move(id);
    d.description = std::move(description);
    d.axes = {t_axis(13)};
    d.channels = kChannels;
    d.searched_by_identify = false;
    d.options = {shape_option(std::move(default_shape)), weights_option("cell"), radius_option(), spacing_option()};
    for (ModelOption& o : extra) d.options.push_back(std::move(o));
    d.prepare = [profile, model](const TableSettings& s) {
        const KernelSettings k = kernel_settings(s);
        const SkinProfile p = profile(s);
        const double tol = kTolerances.at(s.quality);
        // The kernel is made when the first texel asks for it, and its
        // separable error once every texel is filled.
        const auto kernel = std::make_shared<const Lazy<SeparableKernel>>([p, k, tol] {
            return separable_kernel(p, k.shape, k.weights, separable_tap_offsets(k.taps, k.radius, k.spacing), tol);
        });
        PreparedTable out;
        out.evaluator = std::make_unique<KernelEvaluator>([kernel] { return taps_of(kernel->get()); }, k.taps - 1);
        out.model = model(s);
        out.model["kernel"] = to_string(k.shape);
        out.model["weights"] = to_string(k.weights);
        out.model["offsets"] = "radius t^spacing mm, t = i/(n - 1); mirrored, 2n - 1 taps";
        out.model["radius_mm"] = k.radius;
        out.model["spacing"] = k.spacing;
        out.method = tables::quadrature_method(kRule, tol);
        out.finish = [kernel, p, k, tol](Table& t) {
            t.method["separable_error"] = error_json(separable_error(p, kernel->get(), tol), k.taps, k.radius);
            t.method["separable_error"]["meaning"] = kSeparableErrorMeaning;
        };
        return out;
    };
    return d;
}

// The weights of one channel at t-grid taps against expected raw weights
// (any scale), normalized over the mirrored taps; and the offsets.
tables::CheckResult compare_kernel(const TexelEvaluator& e, int taps, double radius, double spacing,
                                   const std::function<std::array<double, 3>(double, double)>& raw_of_cell) {
    const std::vector<double> o = separable_tap_offsets(taps, radius, spacing);
    const std::vector<double> u = separable_cell_edges(o);
    std::vector<std::array<double, 3>> raw(o.size());
    std::array<double, 3> sum{};
    for (std::size_t i = 0; i < o.size(); ++i) {
        raw[i] = raw_of_cell(u[i], u[i + 1]);
        for (std::size_t c = 0; c < 3; ++c) {
            if (i == 0) raw[i][c] *= 2.0;
            sum[c] += (i == 0 ? 1.0 : 2.0) * raw[i][c];
        }
    }
    tables::CheckResult r{0.0, ""};
    for (std::size_t i = 0; i < o.size(); ++i) {
        const double t = static_cast<double>(i) / (taps - 1);
        const TexelValue v = e.evaluate(&t, i);
        for (std::size_t c = 0; c < 4; ++c) {
            const double want = c < 3 ? raw[i][c] / sum[c] : o[i];
            const double err = std::abs(v.value[c] - want);
            if (!(err <= r.first) || r.second.empty())
                r = {err, "tap " + std::to_string(i) + ", channel " + "RGBA"[c]};
        }
    }
    return r;
}

// Unreal's Separable profile (SeparableSSS.cpp, SeparableSSS_Profile): the
// red channel of d'Eon and Luebke's skin fit without its narrowest Gaussian,
// the radius divided by 0.001 + falloff per channel: weight w e^(-(r/s)^2/(2 v))
// / (2 pi v) is w s^2 times a Gaussian of variance v s^2.
const std::array<std::pair<double, double>, 5> kUnrealGaussians = {
    {{0.100, 0.0484}, {0.118, 0.187}, {0.113, 0.567}, {0.358, 1.99}, {0.078, 7.41}}};

SkinProfile unreal_profile(const std::array<double, 3>& falloff) {
    std::array<std::vector<std::pair<double, double>>, 3> wv;
    for (std::size_t c = 0; c < 3; ++c) {
        const double s = 0.001 + falloff[c];
        for (const auto& [w, v] : kUnrealGaussians) wv[c].push_back({w * s * s, v * s * s});
    }
    return {RadialProfile::gaussians(wv[0]), RadialProfile::gaussians(wv[1]), RadialProfile::gaussians(wv[2])};
}

// Unreal's three kernels in one row: one-sided taps and radius (3 mm when
// the mirrored kernel has more than 20 taps, else 2).
constexpr std::array<int, 3> kUnrealTaps = {13, 9, 6};
double unreal_radius(int one_sided) { return 2 * one_sided - 1 > 20 ? 3.0 : 2.0; }

const char* kUnrealSource =
    "EpicGames/UnrealEngine Engine/Source/Runtime/Engine/Private/Rendering/SeparableSSS.cpp "
    "(ComputeMirroredSSSKernel) and Engine/Source/Runtime/Engine/Private/SubsurfaceProfile.cpp (kernel sizes "
    "13, 9, 6 after the SubsurfaceColor texel), read at the public UE4 mirror folgerwang/UnrealEngine "
    "@2b46ba7b94939f6b0e5bb2418c00222e0fc23049";

// Unreal's Burley transmission profile (ComputeTransmissionProfileBurley):
// per channel 0.25 (e^(-x) + 3 e^(-x/3)) with the albedo 1, x = s(A) (r +
// offset) / l; A = e^(-r extinction); the texel at `black_from` and beyond 0.
constexpr double kUnrealRadiusOffsetMm = 0.6;  // ProfileRadiusOffset 0.06 (cm) * 10

class TransmissionEvaluator final : public TexelEvaluator {
public:
    TransmissionEvaluator(const tables::BurleyRgb& b, double extinction, double offset, double black_from)
        : extinction_(extinction), offset_(offset), black_from_(black_from) {
        for (std::size_t c = 0; c < 3; ++c) rate_[c] = burley_scaling(b.albedo[c], b.scaling) / b.dmfp[c];
    }
    TexelValue evaluate(const double* c, std::uint64_t) const override {
        TexelValue out;
        const double r = c[0];
        if (r >= black_from_) return out;
        for (std::size_t k = 0; k < 3; ++k) {
            const double x = rate_[k] * (r + offset_);
            out.value[k] = burley_cdf_complement(x);
            out.error[k] = 4.0 * std::numeric_limits<double>::epsilon() * out.value[k];
        }
        out.value[3] = std::exp(-r * extinction_);
        out.error[3] = 2.0 * std::numeric_limits<double>::epsilon() * out.value[3];
        return out;
    }

private:
    std::array<double, 3> rate_{};
    double extinction_, offset_, black_from_;
};

const char* kUnrealTransmissionSource =
    "EpicGames/UnrealEngine Engine/Source/Runtime/Engine/Private/Rendering/BurleyNormalizedSSS.cpp "
    "(ComputeTransmissionProfileBurley, ProfileRadiusOffset 0.06, 32 samples to MaxTransmissionProfileDistance "
    "5 cm, last pixel black) and SubsurfaceScatteringMath.h (BurleyNormalized::TransmissionProfile), read at the "
    "public mirror unicorn2022/UE5.8.0 @5d9a05c15b1f8c6d7b3354b360677ce30d688149";

}  // namespace
}  // namespace sss_kernel_family

void register_sss_kernel_family(FamilyEntries& family) {
    using namespace sss_kernel_family;
    family.families.push_back(
        {"", "Separable subsurface kernels",
         "Jimenez et al. 2015's separable subsurface scattering blurs the diffuse light in screen space with "
         "one 1-D kernel along x and then along y, so the 2-D blur is k(x) k(y). The kernel is 2n - 1 taps at "
         "offsets radius t^p (t = i/(n - 1), mirrored), each with a weight per colour channel; the weights "
         "of a channel add to 1 over the mirrored taps. Each tap stands for a cell, from the midpoint to its "
         "inner neighbour to the midpoint to its outer one (the outermost ends at its tap). The shape of k: "
         "`line`, the profile along a line, R(|x|), as Jimenez and Unreal's Separable profiles; `radial`, "
         "|x| R(|x|), which Unreal's Burley kernel samples; `marginal`, the profile projected onto a line, "
         "the integral of R(sqrt(x^2 + y^2)) dy, which blurs a straight light edge exactly and, for a single "
         "Gaussian, makes k(x) k(y) the profile itself. Weights: `point`, the cell width times the shape at "
         "the tap (Unreal's rule), or `cell`, the shape's integral over the cell. A table stores the "
         "one-sided taps, the centre first (Unreal's layout): R, G, B the weights, A the offset in mm. Its "
         "metadata reports the separable error per channel (method.separable_error): the misplaced energy, "
         "the total-variation distance between the 2-D kernel the two passes apply, w_a w_b, and the "
         "profile's own mass over each pair of cells, and the outside energy, the part of the profile "
         "beyond the taps' reach. The family also holds the other table of Unreal's subsurface profile rows, "
         "the 32-sample Burley transmission profile (unreal_sss_transmission)."});
    std::vector<TableDefinition>& out = family.tables;
    {
        TableDefinition d = profile_kernel_table(
            "sss_kernel_gaussians",
            "Separable subsurface kernel of d'Eon and Luebke's six-Gaussian skin profile, per channel",
            [](const TableSettings&) { return deon_skin_profile(); },
            [](const TableSettings&) {
                nlohmann::json g = nlohmann::json::array();
                for (const SkinGaussian& x : deon_skin_gaussians())
                    g.push_back({{"variance_mm2", x.variance}, {"weight_rgb", x.weight}});
                return nlohmann::json{
                    {"profile", "sum of Gaussians e^(-r^2/(2v)) / (2 pi v) (d'Eon and Luebke 2007, skin)"},
                    {"gaussians", g}};
            },
            {}, "marginal");
        // The marginal of a Gaussian is a 1-D Gaussian: the cell weights are
        // differences of erf.
        d.checks.push_back({"weights vs the erf closed form of the Gaussians' marginal", 1e-10,
                            [](const TexelEvaluator& e) {
                                return compare_kernel(e, 13, 3.0, 2.0, [](double a, double b) {
                                    std::array<double, 3> w{};
                                    for (const SkinGaussian& g : deon_skin_gaussians()) {
                                        const double s = std::sqrt(2.0 * g.variance);
                                        const double m = 0.5 * (std::erf(b / s) - std::erf(a / s));
                                        for (std::size_t c = 0; c < 3; ++c) w[c] += g.weight[c] * m;
                                    }
                                    return w;
                                });
                            }});
        out.push_back(std::move(d));
    }
    {
        std::vector<ModelOption> burley = tables::burley_rgb_options();
        TableDefinition d = profile_kernel_table(
            "sss_kernel_burley", "Separable subsurface kernel of Burley's normalized diffusion, per channel",
            [](const TableSettings& s) { return tables::burley_rgb_profile(tables::burley_rgb(s)); },
            [](const TableSettings& s) { return tables::burley_rgb_model(tables::burley_rgb(s)); },
            std::move(burley), "marginal");
        const tables::BurleyRgb defaults = tables::burley_rgb(default_settings(d));
        // Burley's marginal is A s (K0(s x) + K0(s x / 3)) / (4 pi), s = 1/d:
        // its cell integrals by composite Gauss-Legendre on panels graded
        // geometrically towards x = 0 (K0's logarithm).
        d.checks.push_back(
            {"weights vs Burley's Bessel K0 marginal by graded Gauss-Legendre", 1e-10,
             [defaults](const TexelEvaluator& e) {
                 const SkinProfile p = tables::burley_rgb_profile(defaults);
                 return compare_kernel(e, 13, 3.0, 2.0, [&](double a, double b) {
                     std::array<double, 3> w{};
                     for (std::size_t c = 0; c < 3; ++c) {
                         const double s = 1.0 / p[c].scale();
                         const double A = defaults.albedo[c];
                         auto f = [&](double x) {
                             return std::array<double, 1>{
                                 A * s * (std::cyl_bessel_k(0.0, s * x) + std::cyl_bessel_k(0.0, s * x / 3.0)) /
                                 (4.0 * kPi)};
                         };
                         double lo = a, sum = 0.0;
                         if (a == 0.0) {
                             // [b 2^-(k+1), b 2^-k] for k = 0 .. 59, then the rest.
                             double hi = b;
                             for (int k = 0; k < 60; ++k) {
                                 sum += integrate_gauss<1>(f, 0.5 * hi, hi, 20)[0];
                                 hi *= 0.5;
                             }
                             lo = b;
                         }
                         if (b > lo) sum += integrate_gauss<1>(f, lo, b, 40)[0];
                         w[c] = sum;
                     }
                     return w;
                 });
             }});
        out.push_back(std::move(d));
    }
    {
        TableDefinition d;
        d.id = "unreal_sss_kernel";
        d.description =
            "UE SSProfiles row, texels 1-28: the three kernels (13, 9, 6 taps) of a Separable subsurface profile";
        d.preset = "unreal_sss";
        d.engine_source = kUnrealSource;
        d.axes = {{Axis{"tap", 0.0, 27.0, 28, Placement::endpoints, Warp::linear}, 0.0, 27.0,
                   "texel index along the row after the SubsurfaceColor texel (a coordinate between texels takes "
                   "the nearest): 0-12 kernel 0 (13 one-sided taps, 3 mm), 13-21 kernel 1 (9, 2 mm), 22-27 "
                   "kernel 2 (6, 2 mm); each kernel's centre first"}};
        d.channels = {"R: weight of the red channel (each kernel's mirrored taps add to 1)",
                      "G: weight of the green channel", "B: weight of the blue channel",
                      "A: offset in mm (Unreal stores A / 3 * ScatterRadius / SUBSURFACE_RADIUS_SCALE)"};
        d.searched_by_identify = false;
        d.options = {{"falloff", "unreal_sss_kernel: Unreal's FalloffColor, r,g,b in [0.009, 1] (the engine's clamp)",
                      "1.0,0.37,0.3", {}},
                     {"kernel-rule",
                      "unreal_sss_kernel: engine (Unreal's rule: the line shape R(|x|) at each tap times its cell "
                      "width) or exact (the marginal shape integrated over each cell)",
                      "engine",
                      {"engine", "exact"}}};
        d.prepare = [](const TableSettings& s) {
            const std::array<double, 3> falloff =
                tables::parse_rgb("falloff", tables::param(s, "falloff"), 0.009, false, 1.0, "three numbers in "
                                                                                              "[0.009, 1]");
            const bool engine = tables::param(s, "kernel-rule") == "engine";
            const KernelShape shape = engine ? KernelShape::line : KernelShape::marginal;
            const KernelWeights weights = engine ? KernelWeights::point : KernelWeights::cell;
            const SkinProfile p = unreal_profile(falloff);
            const double tol = kTolerances.at(s.quality);
            std::vector<Tap> taps;
            PreparedTable out;
            out.method = tables::quadrature_method(kRule, tol);
            nlohmann::json errors = nlohmann::json::array();
            for (int n : kUnrealTaps) {
                const SeparableKernel k =
                    separable_kernel(p, shape, weights, separable_tap_offsets(n, unreal_radius(n), 2.0), tol);
                for (const Tap& t : taps_of(k)) taps.push_back(t);
                errors.push_back(error_json(separable_error(p, k, tol), n, unreal_radius(n)));
            }
            out.evaluator = std::make_unique<KernelEvaluator>(std::move(taps), 1.0);
            nlohmann::json g = nlohmann::json::array();
            for (const auto& [w, v] : kUnrealGaussians) g.push_back({{"variance_mm2", v}, {"weight", w}});
            out.model = {{"profile", "Unreal's SeparableSSS_Profile: five Gaussians w e^(-(r/s)^2/(2v)) / (2 pi v), "
                                     "s = 0.001 + falloff per channel"},
                         {"gaussians", g},
                         {"falloff", falloff},
                         {"kernel_rule", engine ? "engine" : "exact"},
                         {"kernel", to_string(shape)},
                         {"weights", to_string(weights)},
                         {"offsets", "radius t^2 mm, t = i/(n - 1); radius 3 mm when 2n - 1 > 20, else 2"},
                         {"strength", "SubsurfaceColor is applied in the shader, not in these weights"},
                         {"preset", "unreal_sss"},
                         {"engine_source", kUnrealSource}};
            out.method["separable_error"] = errors;
            out.method["separable_error_meaning"] = kSeparableErrorMeaning;
            return out;
        };
        // Unreal's formula evaluated directly (its 2 * 3.14 normalization
        // is common to every Gaussian and cancels).
        d.checks.push_back(
            {"each kernel vs Unreal's point rule on its five Gaussians, offsets radius (i/(n-1))^2",
             1e-12, [](const TexelEvaluator& e) {
                 const std::array<double, 3> f = {1.0, 0.37, 0.3};
                 tables::CheckResult r{0.0, ""};
                 double base = 0.0;
                 for (int n : kUnrealTaps) {
                     const double R = unreal_radius(n);
                     std::vector<double> o(static_cast<std::size_t>(n));
                     for (int i = 0; i < n; ++i) o[static_cast<std::size_t>(i)] = R * std::pow(i / (n - 1.0), 2.0);
                     std::vector<std::array<double, 3>> w(o.size());
                     std::array<double, 3> sum{};
                     for (std::size_t i = 0; i < o.size(); ++i) {
                         const double left = i > 0 ? o[i] - o[i - 1] : o[1];
                         const double right = i + 1 < o.size() ? o[i + 1] - o[i] : 0.0;
                         const double area = 0.5 * (left + right);
                         for (std::size_t c = 0; c < 3; ++c) {
                             double prof = 0.0;
                             for (const auto& [wk, v] : kUnrealGaussians) {
                                 const double rr = o[i] / (0.001 + f[c]);
                                 prof += wk * std::exp(-rr * rr / (2.0 * v)) / (2.0 * 3.14 * v);
                             }
                             w[i][c] = area * prof;
                             sum[c] += (i == 0 ? 1.0 : 2.0) * w[i][c];
                         }
                     }
                     for (std::size_t i = 0; i < o.size(); ++i) {
                         const double x = base + static_cast<double>(i);
                         const TexelValue v = e.evaluate(&x, 0);
                         for (std::size_t c = 0; c < 4; ++c) {
                             const double want = c < 3 ? w[i][c] / sum[c] : o[i];
                             const double err = std::abs(v.value[c] - want);
                             if (!(err <= r.first) || r.second.empty())
                                 r = {err, "texel " + std::to_string(static_cast<int>(x)) + ", channel " + "RGBA"[c]};
                         }
                     }
                     base += n;
                 }
                 return r;
             }});
        out.push_back(std::move(d));
    }
    {
        TableDefinition d;
        d.id = "unreal_sss_transmission";
        d.description = "UE SSProfiles Burley transmission profile: 32 distances to 50 mm, per channel, and the shadow "
                        "term";
        d.preset = "unreal_sss";
        d.engine_source = kUnrealTransmissionSource;
        d.axes = {{Axis{"distance", 0.0, 48.4375, 32, Placement::endpoints, Warp::linear}, 0.0, 1e4,
                   "distance through the object in mm: Unreal's i/32 of 50 mm (i = 0..31) at world unit scale 0.1"}};
        d.channels = {"R: transmission A (e^(-x)/4 + 3 e^(-x/3)/4) at A = 1, x = s(A) (r + offset) / l, red",
                      "G: green", "B: blue", "A: exp(-r * extinction scale), the shadow term"};
        d.searched_by_identify = false;
        d.options = tables::burley_rgb_options();
        d.options.push_back({"extinction-scale", "unreal_sss_transmission: Unreal's ExtinctionScale, per mm, 0 to 100",
                             "1", {}});
        d.options.push_back({"transmission-rule",
                             "unreal_sss_transmission: engine (Unreal's: evaluated at r + 0.6 mm, its "
                             "ProfileRadiusOffset, and the last texel set to 0) or exact (at r itself)",
                             "engine",
                             {"engine", "exact"}});
        d.prepare = [](const TableSettings& s) {
            const tables::BurleyRgb b = tables::burley_rgb(s);
            const double extinction = tables::parse_number("extinction-scale", tables::param(s, "extinction-scale"));
            if (!(extinction >= 0.0 && extinction <= 100.0))
                throw Error("--extinction-scale " + tables::param(s, "extinction-scale") +
                            " is out of range; allowed: 0 to 100 (per mm)");
            const bool engine = tables::param(s, "transmission-rule") == "engine";
            PreparedTable out;
            out.evaluator = std::make_unique<TransmissionEvaluator>(b, extinction, engine ? kUnrealRadiusOffsetMm : 0.0,
                                                                    engine ? s.axes.at(0).highest() : HUGE_VAL);
            out.model = tables::burley_rgb_model(b);
            out.model["surface_albedo_in_profile"] = "1 (Unreal leaves the albedo to the recombine pass)";
            out.model["extinction_scale_per_mm"] = extinction;
            out.model["transmission_rule"] = engine ? "engine" : "exact";
            out.model["radius_offset_mm"] = engine ? kUnrealRadiusOffsetMm : 0.0;
            out.model["last_texel"] = engine ? "0 (Unreal's bMakeLastPixelBlack)" : "computed";
            out.model["tint"] = "TransmissionTintColor is white here";
            out.model["preset"] = "unreal_sss";
            out.model["engine_source"] = kUnrealTransmissionSource;
            out.method = {{"name", "closed_form"},
                          {"formula", "(e^(-x)/4 + 3 e^(-x/3)/4), the complement of Burley's CDF, in exponentials"}};
            return out;
        };
        d.checks.push_back(
            {"transmission vs quadrature of Burley's radial density beyond s (r + 0.6) / l; shadow; last texel 0", 1e-12,
             [](const TexelEvaluator& e) {
                 const std::array<double, 3> A = {0.8, 0.5, 0.3}, l = {1.0, 0.5, 0.25};
                 tables::CheckResult r{0.0, ""};
                 for (double mm : {0.0, 0.4, 1.5625, 7.0, 30.0}) {
                     const TexelValue v = e.evaluate(&mm, 0);
                     for (std::size_t c = 0; c < 4; ++c) {
                         double want = std::exp(-mm);
                         if (c < 3) {
                             const double x = burley_scaling(A[c], BurleyScaling::dmfp) * (mm + 0.6) / l[c];
                             AdaptiveOptions opt{1e-15, 400};
                             want = integrate_adaptive<1>(
                                        [](double t) { return std::array<double, 1>{burley_radial_density(t)}; }, x,
                                        x + 300.0, opt)
                                        .value[0];
                         }
                         const double err = std::abs(v.value[c] - want);
                         if (!(err <= r.first) || r.second.empty())
                             r = {err, std::to_string(mm) + " mm, channel " + "RGBA"[c]};
                     }
                 }
                 const double last = 48.4375;
                 const TexelValue v = e.evaluate(&last, 31);
                 for (double x : v.value)
                     if (x != 0.0) return tables::CheckResult{std::abs(x), "the last texel is not 0"};
                 return r;
             }});
        out.push_back(std::move(d));
    }
}

}  // namespace brdflut
