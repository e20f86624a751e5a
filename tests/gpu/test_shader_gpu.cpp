// The generated GLSL and HLSL lookup functions, run on Mesa's lavapipe.
//
// For each table configuration: `brdflut generate --format ktx2 --shader glsl
// --shader hlsl`, upload the KTX2 file as a texture (linear filter, clamp to
// edge, no mips), call the generated functions at a few thousand random
// points and compare with sample_lut() (what `brdflut sample` prints) and
// with the exact values of the model.
//
// lavapipe's filter, measured by LavapipeFilter.* below: for the 16- and
// 32-bit float formats brdflut writes, llvmpipe computes the texel position
// u * count - 0.5 and the linear weights in 32-bit float, with no sub-texel
// quantisation: the filtered value of a texture holding 0 and 1 equals
// frac(u * 2 - 0.5) computed in float exactly (0 difference at 100,000 random
// coordinates; 65,536 evenly spaced offsets give 65,536 distinct weights).
// Desktop GPUs instead quantise the weight to 8 fractional bits (Direct3D
// requires at least 8 bits of sub-texel precision); the tolerance below uses
// the measured weight error, so the same test would fail there by design.
//
// Tolerance against sample_lut (double arithmetic on the same stored texels),
// per point and channel, from 32-bit float arithmetic in the shader and filter:
//   sum over axes of (e_w + e_p count_a) * d_a + 4 eps max|texel|,
// eps = 2^-24, e_w the measured weight error (at least eps), e_p = 8 eps the
// error of the inverse warp in float (u in [0, 1], a few roundings of sqrt,
// log or a division), d_a the largest difference between neighbouring texels
// of the cell along axis a.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <array>
#include <random>
#include <set>
#include <sstream>

#include "brdflut/catalogue.h"
#include "brdflut/formats.h"
#include "brdflut/ltc.h"
#include "brdflut/lut.h"
#include "brdflut/shader.h"
#include "../test_support.h"
#include "vk_compute.h"

namespace brdflut {
namespace {

using test::TempDir;
constexpr double kEps = 1.0 / (1 << 24);  // float32 unit roundoff

gpu::Runner& runner() {
    static gpu::Runner r;  // throws with a clear message when lavapipe is missing
    return r;
}

const char* kGlslPrologue = R"(#version 450
layout(local_size_x = 64) in;
layout(binding = 0) uniform %SAMPLER% lut;
layout(std430, binding = 1) readonly buffer Points { float points[]; };
layout(std430, binding = 2) writeonly buffer Results { float results[]; };
layout(push_constant) uniform Count { uint count; };
)";

const char* kHlslPrologue = R"([[vk::binding(3)]] %TEXTURE%<float4> lut;
[[vk::binding(4)]] SamplerState lut_sampler;
[[vk::binding(1)]] StructuredBuffer<float> points;
[[vk::binding(2)]] RWStructuredBuffer<float> results;
struct Count { uint count; };
[[vk::push_constant]] Count pc;
)";

std::string replace(std::string s, const std::string& from, const std::string& to) {
    const std::size_t at = s.find(from);
    if (at != std::string::npos) s.replace(at, from.size(), to);
    return s;
}

// A compute shader that calls `function` (the generated source) once per
// point and writes its channels (4 floats a point) or, with `matrix`, the
// 3x3 matrix of member si.matrix as the evaluation applies it to column
// vectors (GLSL m * v, HLSL mul(m, v)): m e_j is column j, written to
// output 3 row + j (9 floats a point, by rows).
std::string compute_shader(const ShaderInterface& si, const std::string& function, bool hlsl, bool matrix = false) {
    std::ostringstream o;
    const std::size_t np = si.parameters.size();
    if (hlsl)
        o << replace(kHlslPrologue, "%TEXTURE%", si.dimensions == 3 ? "Texture3D" : "Texture2D");
    else
        o << replace(kGlslPrologue, "%SAMPLER%", si.dimensions == 3 ? "sampler3D" : "sampler2D");
    o << "\n" << function << "\n";
    if (hlsl)
        o << "[numthreads(64, 1, 1)]\nvoid main(uint3 id : SV_DispatchThreadID)\n{\n    uint i = id.x;\n"
          << "    if (i >= pc.count) return;\n";
    else
        o << "void main()\n{\n    uint i = gl_GlobalInvocationID.x;\n    if (i >= count) return;\n";
    o << "    " << si.result_type << " r = " << si.function << (hlsl ? "(lut, lut_sampler" : "(lut");
    for (std::size_t p = 0; p < np; ++p) o << ", points[i * " << np << "u + " << p << "u]";
    o << ");\n";
    if (matrix) {
        const char* basis[3] = {"1.0, 0.0, 0.0", "0.0, 1.0, 0.0", "0.0, 0.0, 1.0"};
        for (int j = 0; j < 3; ++j) {
            o << "    " << (hlsl ? "float3" : "vec3") << " column" << j << " = "
              << (hlsl ? "mul(r." + si.matrix + ", float3(" : "r." + si.matrix + " * vec3(") << basis[j]
              << (hlsl ? "));\n" : ");\n");
            for (int row = 0; row < 3; ++row)
                o << "    results[i * 9u + " << 3 * row + j << "u] = column" << j << "[" << row << "];\n";
        }
    } else {
        for (std::size_t c = 0; c < si.fields.size(); ++c)
            o << "    results[i * 4u + " << c << "u] = r." << si.fields[c] << ";\n";
    }
    o << "}\n";
    return o.str();
}

std::string glslang() {
    const std::string path = BRDFLUT_GLSLANG;
    if (path.empty() || !std::filesystem::exists(path))
        throw std::runtime_error("glslangValidator not found (install glslang-tools and re-run cmake)");
    return path;
}

// --- lavapipe's filter -----------------------------------------------------

// Largest |filtered - frac(u * 2 - 0.5)| over random u on a 2-texel texture
// holding 0 and 1 of the given format; *distinct: distinct weights among
// 65,536 evenly spaced offsets within one texel.
double measure_weight_error(std::uint32_t vk_format, std::size_t* distinct) {
    gpu::Texture t;
    t.vk_format = vk_format;
    t.width = 2;
    if (vk_format == 100) {  // VK_FORMAT_R32_SFLOAT
        const float v[2] = {0.0f, 1.0f};
        t.texels.resize(8);
        std::memcpy(t.texels.data(), v, 8);
    } else {  // VK_FORMAT_R16_SFLOAT: half 0 and 1 (0x3C00)
        const std::uint16_t v[2] = {0x0000, 0x3C00};
        t.texels.resize(4);
        std::memcpy(t.texels.data(), v, 4);
    }
    const std::string src = R"(#version 450
layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2D lut;
layout(std430, binding = 1) readonly buffer Points { float points[]; };
layout(std430, binding = 2) writeonly buffer Results { float results[]; };
layout(push_constant) uniform Count { uint count; };
void main()
{
    uint i = gl_GlobalInvocationID.x;
    if (i < count) results[i] = textureLod(lut, vec2(points[i], 0.5), 0.0).r;
}
)";
    TempDir dir;
    const auto spv = gpu::compile_compute(glslang(), src, false, dir.path().string());
    const int even = 65536, random = 100000;
    std::vector<float> u;
    for (int k = 0; k < even; ++k) u.push_back(static_cast<float>((0.5 + static_cast<double>(k) / even) / 2.0));
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> dist(0.25f, 0.75f);  // between the two texel centres
    for (int k = 0; k < random; ++k) u.push_back(dist(rng));
    const std::vector<float> w = runner().run(t, spv, u, static_cast<std::uint32_t>(u.size()), 1);
    *distinct = std::set<float>(w.begin(), w.begin() + even).size();
    double worst = 0.0;
    for (std::size_t k = 0; k < u.size(); ++k) {
        const float want = u[k] * 2.0f - 0.5f;  // the weight of texel 1, in float
        worst = std::max(worst, std::abs(static_cast<double>(w[k]) - want));
    }
    return worst;
}

// The weight error used by every tolerance: measured on R32 and R16 textures.
double weight_error() {
    static const double e = [] {
        std::size_t d32 = 0, d16 = 0;
        const double e32 = measure_weight_error(100, &d32), e16 = measure_weight_error(76, &d16);
        return std::max({e32, e16, kEps});
    }();
    return e;
}

TEST(LavapipeFilter, FloatTexturesUseFloat32WeightsWithoutSubTexelQuantisation) {
    EXPECT_NE(runner().device_name().find("llvmpipe"), std::string::npos) << runner().device_name();
    for (const std::uint32_t format : {100u, 76u}) {
        std::size_t distinct = 0;
        const double err = measure_weight_error(format, &distinct);
        // 8 fractional bits would give 256 distinct weights and errors up to 1/512.
        EXPECT_EQ(distinct, 65536u) << "VkFormat " << format << ": weights are quantised";
        EXPECT_LE(err, kEps) << "VkFormat " << format << ": weight differs from the float32 computation";
        std::printf("lavapipe, VkFormat %u: %zu distinct weights of 65536 offsets; max |w - float32 w| = %.3g\n",
                    format, distinct, err);
    }
}

// --- the generated functions ---------------------------------------------

struct Config {
    std::string name;
    std::string args;  // brdflut generate arguments, before --format/--shader/-o
};

// Texel value of a file channel at storage indices (ix, iy, iz), clamped.
// Texel (i[0], i[1], i[2]) of channel c, each index clamped to its axis (a
// 3-D table's slices are stacked as rows: row = z * count_y + y).
double texel(const ExrImage& img, const std::vector<Axis>& axes, const std::array<int, 3>& i, int c) {
    std::array<std::size_t, 3> k{0, 0, 0};
    for (std::size_t a = 0; a < axes.size(); ++a)
        k[a] = static_cast<std::size_t>(std::clamp(i[a], 0, axes[a].count - 1));
    const std::size_t ny = axes.size() > 1 ? static_cast<std::size_t>(axes[1].count) : 1;
    const std::size_t nc = img.channel_names.size();
    return img.pixels[((k[2] * ny + k[1]) * static_cast<std::size_t>(img.width) + k[0]) * nc + static_cast<std::size_t>(c)];
}

// The parameter the texels cover nearest to v (the axis' range and clamps).
double covered(const Axis& a, double v) { return std::clamp(v, a.lowest(), a.highest()); }

// Storage position of a parameter on an axis, clamped to the grid as
// sample_lut clamps it.
double position(const Axis& a, double v) {
    return std::clamp(a.position_of_value(covered(a, v)), 0.0, static_cast<double>(a.count - 1));
}

// The interface of a file's function as the library describes it, for the
// wrapper shader.
ShaderInterface interface_of(const LutDescription& d) {
    Table shape;
    shape.id = d.def->id;
    shape.axes = d.settings.axes;
    shape.channels = d.def->channels;
    shape.channel_map = d.settings.channel_map;
    if (!shape.channel_map.empty()) shape.channels.assign(shape.channel_map.size(), "");
    return shader_interface(shape);
}

// `points` parameter points in the function's order (si.parameters), 10%
// beyond each end of the range to exercise the clamps; axis_of_param[p] is
// the storage axis of parameter p (-1: no axis of that name).
std::vector<float> random_points(const std::vector<Axis>& axes, const ShaderInterface& si, int points,
                                 std::uint32_t seed, std::vector<int>& axis_of_param) {
    axis_of_param.clear();
    for (const std::string& p : si.parameters) {
        int found = -1;
        for (std::size_t a = 0; a < axes.size(); ++a)
            if (axes[a].name == p) found = static_cast<int>(a);
        axis_of_param.push_back(found);
        if (found < 0) return {};
    }
    std::mt19937 rng(seed);
    const std::size_t np = si.parameters.size();
    std::vector<float> in(static_cast<std::size_t>(points) * np);
    for (int k = 0; k < points; ++k)
        for (std::size_t p = 0; p < np; ++p) {
            const Axis& a = axes[static_cast<std::size_t>(axis_of_param[p])];
            const double lo = std::min(a.min, a.max), hi = std::max(a.min, a.max), span = hi - lo;
            // A log axis is drawn uniform in log, an axis that reaches
            // infinity (ior to inf) uniform in its warp's coordinate, the rest
            // uniform in value.
            double v;
            if (!std::isfinite(span)) {
                std::uniform_real_distribution<double> t(-0.1, 1.0);
                const double u = t(rng);
                v = u >= 0.0 ? a.value_at_u(u) : lo + u * (a.value_at_u(0.1) - lo);
            } else if (a.warp == Warp::log) {
                std::uniform_real_distribution<double> t(-0.1, 1.1);
                v = lo * std::pow(hi / lo, t(rng));
            } else {
                std::uniform_real_distribution<double> t(lo - 0.1 * span, hi + 0.1 * span);
                v = t(rng);
            }
            in[static_cast<std::size_t>(k) * np + p] = static_cast<float>(v);
        }
    return in;
}

// The parameters (storage order) of point k of `in`.
std::vector<double> point_params(const std::vector<float>& in, const std::vector<int>& axis_of_param, int k) {
    const std::size_t np = axis_of_param.size();
    std::vector<double> params(np);
    for (std::size_t p = 0; p < np; ++p)
        params[static_cast<std::size_t>(axis_of_param[p])] = in[static_cast<std::size_t>(k) * np + p];
    return params;
}

// The tolerance of the header comment (against sample) for file channel ci at storage
// parameters `params`, from the cell around the point and its neighbours;
// and the interpolation error bound of the exact check.
struct Tolerance {
    double tol = 0, interp = 0;
    double d1[3] = {0, 0, 0}, d2[3] = {0, 0, 0};  // first and second neighbour differences per axis
};
Tolerance filter_tolerance(const ExrImage& img, const std::vector<Axis>& axes, const std::vector<double>& params,
                           int ci, double we) {
    const std::size_t na = axes.size();
    std::array<int, 3> base{0, 0, 0};
    for (std::size_t a = 0; a < na; ++a) base[a] = static_cast<int>(std::floor(position(axes[a], params[a])));
    Tolerance t;
    double vmax = 0;
    // The cell's corners and one texel beyond them on every side: 4 per axis.
    const int span[3] = {4, na > 1 ? 4 : 1, na > 2 ? 4 : 1};
    for (int k = 0; k < span[2]; ++k)
        for (int j = 0; j < span[1]; ++j)
            for (int i = 0; i < span[0]; ++i) {
                std::array<int, 3> at = base;
                const int off[3] = {i - 1, j - 1, k - 1};
                for (std::size_t a = 0; a < na; ++a) at[a] += off[a];
                const double t0 = texel(img, axes, at, ci);
                vmax = std::max(vmax, std::abs(t0));
                for (std::size_t a = 0; a < na; ++a) {
                    std::array<int, 3> up = at, down = at;
                    ++up[a];
                    --down[a];
                    const double tu = texel(img, axes, up, ci), td = texel(img, axes, down, ci);
                    t.d1[a] = std::max(t.d1[a], std::abs(tu - t0));
                    t.d2[a] = std::max(t.d2[a], std::abs(tu - 2 * t0 + td));
                }
            }
    t.tol = 4 * kEps * vmax;
    for (std::size_t a = 0; a < na; ++a) {
        t.tol += (we + 8 * kEps * axes[a].count) * t.d1[a];
        // Linear interpolation error h^2 |f''| / 8 with h^2 f'' ~ the
        // second difference; twice that for the variation of f''
        // across the cell.
        t.interp += 0.25 * t.d2[a];
        // A cell at the edge of the range may hold a singular
        // derivative (sqrt-like at mu = 0, alpha = 0, albedo = 1):
        // linear interpolation of t^p over one cell errs by at most
        // half the difference across it, for any 0 < p.
        const int i0 = base[a];
        if (i0 <= 0 || i0 + 1 >= axes[a].count - 1) t.interp += 0.5 * t.d1[a];
    }
    return t;
}

struct Errors {
    double vs_sample = 0, vs_sample_tol = 0;  // worst |gpu - sample| and the tolerance at that point
    double worst_ratio_sample = 0;            // max |gpu - sample| / tolerance
    double worst_ratio_exact = 0;             // max |gpu - exact| / (bound + interpolation error)
    double vs_exact = 0;
    int points = 0;
    int sample_failures = 0;  // points whose |gpu - sample| exceeds the tolerance
};

// Generates cfg's tables and checks their functions. With `shaders_from`,
// the functions come from a generate run with those arguments instead (a
// mismatched pair of table and function), and must then be caught: most
// points must exceed the tolerance against sample.
void check_config(const Config& cfg, int points, std::uint32_t seed, const std::string& shaders_from = "") {
    TempDir dir;
    const bool expect_match = shaders_from.empty();
    const std::string out = (dir.path() / "luts").string(), other = (dir.path() / "other").string();
    const auto r = test::run_cli("generate " + cfg.args + " --format ktx2 --shader glsl --shader hlsl -q -o '" + out + "'", dir);
    ASSERT_EQ(r.exit_code, 0) << cfg.args << "\n" << r.err;
    if (!expect_match) {
        const auto r2 = test::run_cli("generate " + shaders_from + " --format ktx2 --shader glsl --shader hlsl -q -o '" + other + "'", dir);
        ASSERT_EQ(r2.exit_code, 0) << shaders_from << "\n" << r2.err;
    }
    const double we = weight_error();
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(out)) {
        if (entry.path().extension() != ".ktx2") continue;
        ++files;
        const std::string ktx = entry.path().string();
        SCOPED_TRACE(cfg.name + ": " + entry.path().filename().string());
        const ExrImage img = read_table_image(ktx);
        const LutDescription d = describe_from_metadata(img, ktx);
        const auto& axes = d.settings.axes;
        const gpu::Texture tex = gpu::read_ktx2(ktx);

        // The generated sources name the file's metadata hash.
        const std::filesystem::path shader_dir = expect_match ? entry.path().parent_path() : std::filesystem::path(other);
        const std::string glsl = test::read_file(shader_dir / (entry.path().stem().string() + ".glsl"));
        const std::string hlsl = test::read_file(shader_dir / (entry.path().stem().string() + ".hlsl"));
        ASSERT_FALSE(glsl.empty());
        ASSERT_FALSE(hlsl.empty());
        ASSERT_FALSE(tex.metadata.empty());
        const std::string hash_line = "metadata fnv1a64 " + gpu::fnv1a64_hex(tex.metadata);
        EXPECT_EQ(glsl.find(hash_line) != std::string::npos, expect_match)
            << "the GLSL file's hash and the KTX2 file's metadata hash " << hash_line;
        EXPECT_EQ(hlsl.find(hash_line) != std::string::npos, expect_match);

        const ShaderInterface si = interface_of(d);
        std::vector<int> axis_of_param;
        const std::vector<float> in = random_points(axes, si, points, seed, axis_of_param);
        ASSERT_FALSE(in.empty()) << "a parameter without an axis of its name";
        const std::size_t np = si.parameters.size();

        // The exact model, for the second check.
        const PreparedTable prepared = d.def->prepare(d.settings);
        const double bound = img.metadata.at("error_bound").get<double>();

        // Exact values at the clamped parameters (coordinates in the
        // definition's order), once per point for both languages.
        // (The first kExactPoints points: the quadrature of an average table
        // takes milliseconds per point.)
        // Tables that solve per roughness (seconds each): 4 points.
        constexpr int kExactPoints = 1000;
        const int exact_points =
            expect_match ? std::min(points, d.def->solve_per_parameter ? 4 : kExactPoints) : 0;
        std::vector<TexelValue> exact_values(static_cast<std::size_t>(exact_points));
        for (int k = 0; k < exact_points; ++k) {
            std::vector<double> coords(axes.size());
            for (std::size_t p = 0; p < np; ++p) {
                const Axis& a = axes[static_cast<std::size_t>(axis_of_param[p])];
                coords[p] = covered(a, in[static_cast<std::size_t>(k) * np + p]);
            }
            exact_values[static_cast<std::size_t>(k)] = prepared.evaluator->evaluate(coords.data(), 0);
        }

        for (const bool use_hlsl : {false, true}) {
            SCOPED_TRACE(use_hlsl ? "HLSL" : "GLSL");
            const auto spv = gpu::compile_compute(glslang(), compute_shader(si, use_hlsl ? hlsl : glsl, use_hlsl),
                                                  use_hlsl, dir.path().string());
            const std::vector<float> res = runner().run(tex, spv, in, static_cast<std::uint32_t>(points), 4);
            Errors e;
            for (int k = 0; k < points; ++k) {
                const std::vector<double> params = point_params(in, axis_of_param, k);
                std::vector<double> pos(axes.size());
                for (std::size_t a = 0; a < axes.size(); ++a) pos[a] = position(axes[a], params[a]);
                const bool has_exact = k < exact_points;
                const TexelValue exact = has_exact ? exact_values[static_cast<std::size_t>(k)] : TexelValue{};
                // Beyond the first or last texel centre (center placement) the
                // filter holds the edge texel: that is not an approximation of
                // the model there, so the exact check covers the points between
                // the outermost texel centres (sample and the shader are
                // compared everywhere).
                bool inside = has_exact;
                for (std::size_t a = 0; a < axes.size(); ++a) {
                    const double raw = axes[a].position_of_value(covered(axes[a], params[a]));
                    if (!(raw >= -1e-9 && raw <= axes[a].count - 1 + 1e-9)) inside = false;
                }
                for (std::size_t c = 0; c < si.fields.size(); ++c) {
                    const int ci = static_cast<int>(c);
                    const double gpu_v = res[static_cast<std::size_t>(k) * 4 + c];
                    const double cpu_v = sample_lut(img, d, params, ci);
                    const Tolerance tt = filter_tolerance(img, axes, params, ci, we);
                    const double tol = tt.tol, interp = tt.interp;
                    const double diff = std::abs(gpu_v - cpu_v);
                    if (!(diff <= tol)) ++e.sample_failures;
                    if (!expect_match) break;
                    if (!(diff <= tol)) {
                        ADD_FAILURE() << si.function << " field " << si.fields[c] << " at point " << k << ": gpu "
                                      << gpu_v << ", sample " << cpu_v << ", |diff| " << diff << " > tolerance " << tol
                                      << "; params " << params[0] << ", " << params.back();
                        return;
                    }
                    e.worst_ratio_sample = std::max(e.worst_ratio_sample, tol > 0 ? diff / tol : 0.0);
                    e.vs_sample = std::max(e.vs_sample, diff);
                    // File channel c holds the sum of table channels channel_map[c].
                    double want = 0;
                    if (d.settings.channel_map.empty())
                        want = exact.value[c];
                    else
                        for (const int t : d.settings.channel_map[c]) want += exact.value[static_cast<std::size_t>(t)];
                    const double ex_tol = bound + interp + tol + 1e-12;
                    const double ex = std::abs(gpu_v - want);
                    if (!inside) continue;
                    ++e.points;
                    if (!(ex <= ex_tol)) {
                        ADD_FAILURE() << si.function << " field " << si.fields[c] << " at point " << k << ": gpu "
                                      << gpu_v << ", exact " << want << ", |diff| " << ex << " > error bound "
                                      << bound << " + interpolation " << interp << "; params " << params[0] << ", "
                                      << params.back() << " pos " << pos[0] << ", " << pos.back() << " d2 " << tt.d2[0]
                                      << ", " << tt.d2[1] << ", " << tt.d2[2];
                        return;
                    }
                    e.vs_exact = std::max(e.vs_exact, ex);
                    e.worst_ratio_exact = std::max(e.worst_ratio_exact, ex / ex_tol);
                }
            }
            if (expect_match)
                std::printf("%-26s %s %s: %d points, max |gpu - sample| %.2e (%.2f of tolerance); %d inside, "
                        "max |gpu - exact| %.2e (%.2f of bound + interpolation)\n",
                        cfg.name.c_str(), use_hlsl ? "HLSL" : "GLSL", si.function.c_str(), points, e.vs_sample,
                        e.worst_ratio_sample, e.points / static_cast<int>(si.fields.size()), e.vs_exact,
                        e.worst_ratio_exact);
            if (expect_match) {
                EXPECT_GT(e.points, 0) << "no point inside the texel centres";
            } else {
                std::printf("mismatched function: %d of %d points outside the tolerance\n", e.sample_failures, points);
                EXPECT_GT(e.sample_failures, points / 2) << "a function for another layout went unnoticed";
            }
        }
    }
    EXPECT_GT(files, 0) << "no KTX2 file written";
}

const std::vector<Config>& configs() {
    static const std::vector<Config> c = {
        {"ggx_dfg half center", "ggx_dfg --size 32 --pixel half"},
        {"ggx_dfg float endpoints", "ggx_dfg --size 17x9 --placement cos_theta=endpoints --placement alpha=endpoints"},
        {"ggx_albedo_avg sqrt", "ggx_albedo_avg --size 48 --warp alpha=sqrt --pixel half"},
        {"fresnel_conductor 1-D rgb", "fresnel_conductor --size 40"},
        {"fresnel_dielectric", "fresnel_dielectric --size 24x20 --range eta=1.1:2.5"},
        {"dipole_profile log", "dipole_profile --size 40x16 --range radius=0.01:16"},
        {"preset hdrp", "--preset hdrp --size 24"},
        {"preset cycles", "--preset cycles --size 16"},
        {"reversed square range", "ggx_dfg --size 24 --range cos_theta=1:0 --warp cos_theta=square --pixel half"},
        {"transposed and flipped", "ggx_dfg --size 20x12 --order alpha,cos_theta --flip alpha"},
        {"clamps", "ggx_albedo --size 16x12 --clamp cos_theta=0.15:0.85 --clamp alpha=0.2:1 --pixel half"},
        {"ior_z warp", "fresnel_dielectric --size 16x24 --range eta=1.05:3 --warp eta=ior_z"},
        {"split index axis", "adobe_openpbr_opaque_dielectric_avg_energy_complement --size 24x16 --pixel float"},
        {"channel map", "ggx_dfg --size 16 --channels R=R+G,G=G"},
        {"shifted grids", "ggx_dfg --size 16x12 --shift alpha=1 --clamp alpha=0:1 --placement cos_theta=endpoints "
                          "--shift cos_theta=-0.5 --clamp cos_theta=0:1"},
    };
    return c;
}

class ShaderLookup : public ::testing::TestWithParam<std::size_t> {};

TEST_P(ShaderLookup, GlslAndHlslMatchSampleAndExactValuesOnLavapipe) {
    const Config& cfg = configs()[GetParam()];
    check_config(cfg, 3000, static_cast<std::uint32_t>(17 + GetParam()));
}

// The check can fail: a function written for one layout, used on a texture
// of another, differs from sample at most points.
TEST(ShaderLookupMismatch, FunctionOfAnEndpointsTableOnACenterTextureIsCaught) {
    check_config({"center texture, endpoints function", "ggx_dfg --size 16"}, 1000, 3,
                 "ggx_dfg --size 16 --placement cos_theta=endpoints --placement alpha=endpoints");
}

TEST(ShaderLookupMismatch, FunctionOfASquareWarpOnALinearTextureIsCaught) {
    check_config({"linear texture, square function", "ggx_albedo_avg --size 32 --warp alpha=linear"}, 1000, 4,
                 "ggx_albedo_avg --size 32 --warp alpha=square");
}

// The LTC matrix tables: each function's inverse_matrix, applied to the
// basis vectors as the evaluation applies it to light vertices
// (inverse_matrix * v in GLSL, mul(inverse_matrix, v) in HLSL), equals
// element by element the matrix M^-1 built on the CPU from sample_lut's
// filtered channels in the table's documented packing (ltc.h, ltc_tables.cpp;
// Heitz's ltc_1 as three.js unpacks it, mat3(vec3(R, 0, G), vec3(0, 1, 0),
// vec3(B, 0, A)) by columns; HDRP's loaded as the transpose,
// invM._m00_m02_m11_m20 = RGBA, invM._m22 = 1, for mul(v, invM)). Each
// element within the tolerance against sample of the channel it holds (the
// header comment's), the constant elements exactly.
//
// The packing applied to channel values ch, with `one` for the constant 1
// element: with the channels' tolerances and one = 0 it gives each
// element's tolerance.
Mat3 documented_inverse(const std::string& id, const double* ch, double one) {
    if (id == "ltc_1") {
        Mat3 m = LtcInverse{ch[0], ch[2], ch[1], ch[3]}.matrix();  // (a, c, b, d) = RGBA
        m.m[1][1] *= one;
        return m;
    }
    if (id == "hdrp_ltc_ggx") {
        const Mat3 hdrp_inv_m{{{{ch[0], 0, ch[1]}, {0, ch[2], 0}, {ch[3], 0, one}}}};  // HDRP's invM
        Mat3 m;
        for (std::size_t r = 0; r < 3; ++r)
            for (std::size_t c = 0; c < 3; ++c) m.m[r][c] = hdrp_inv_m.m[c][r];
        return m;
    }
    throw std::runtime_error("no documented LTC packing for table '" + id + "'");
}

TEST(ShaderLookupLtc, InverseMatrixEqualsTheMatrixOfTheSampledChannelsOnLavapipe) {
    TempDir dir;
    const std::string out = (dir.path() / "luts").string();
    const auto r = test::run_cli("generate ltc_1 hdrp_ltc_ggx --size 16x16 --quality draft --pixel half --format ktx2 "
                                 "--shader glsl --shader hlsl -q -o '" + out + "'", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const double we = weight_error();
    const int points = 2000;
    for (const std::string id : {"ltc_1", "hdrp_ltc_ggx"}) {
        SCOPED_TRACE(id);
        const std::string ktx = out + "/" + id + ".ktx2";
        const ExrImage img = read_table_image(ktx);
        const LutDescription d = describe_from_metadata(img, ktx);
        const auto& axes = d.settings.axes;
        const gpu::Texture tex = gpu::read_ktx2(ktx);
        const ShaderInterface si = interface_of(d);
        ASSERT_EQ(si.matrix, "inverse_matrix");
        std::vector<int> axis_of_param;
        const std::vector<float> in = random_points(axes, si, points, 29, axis_of_param);
        ASSERT_FALSE(in.empty());
        for (const bool hlsl : {false, true}) {
            SCOPED_TRACE(hlsl ? "HLSL" : "GLSL");
            const std::string src = test::read_file(out + "/" + id + (hlsl ? ".hlsl" : ".glsl"));
            const auto spv = gpu::compile_compute(glslang(), compute_shader(si, src, hlsl, true), hlsl,
                                                  dir.path().string());
            const std::vector<float> res = runner().run(tex, spv, in, points, 9);
            double worst_ratio = 0;
            for (int k = 0; k < points; ++k) {
                const std::vector<double> params = point_params(in, axis_of_param, k);
                double ch[4], tol[4];
                for (int c = 0; c < 4; ++c) {
                    ch[c] = sample_lut(img, d, params, c);
                    tol[c] = filter_tolerance(img, axes, params, c, we).tol;
                }
                const Mat3 want = documented_inverse(id, ch, 1.0), allowed = documented_inverse(id, tol, 0.0);
                for (std::size_t e = 0; e < 9; ++e) {
                    const double w = want.m[e / 3][e % 3], a = allowed.m[e / 3][e % 3];
                    const double got = res[static_cast<std::size_t>(k) * 9 + e];
                    ASSERT_LE(std::abs(got - w), a)
                        << "M^-1[" << e / 3 << "][" << e % 3 << "] at point " << k << " (" << params[0] << ", "
                        << params[1] << "): gpu " << got << ", from sampled channels " << w;
                    if (a > 0) worst_ratio = std::max(worst_ratio, std::abs(got - w) / a);
                }
            }
            std::printf("%-13s %s inverse_matrix: %d points, max |gpu - sampled M^-1| / tolerance %.2f\n",
                        id.c_str(), hlsl ? "HLSL" : "GLSL", points, worst_ratio);
        }
    }
}

// A 3-axis table: its KTX2 file is a real 3-D texture (depth = the z count),
// which uploaded as it is gives what the generated sampler3D / Texture3D
// function reads. Smooth synthetic values on center, endpoints and flipped
// log axes; compared with sample_lut's trilinear filter at random points.
TEST(ShaderLookup3D, A3DKtx2TextureMatchesTrilinearSample) {
    Table t;
    t.id = "synthetic_3d";
    Axis x, y, z;
    x.name = "cos_theta", x.min = 0, x.max = 1, x.count = 9;
    y.name = "alpha", y.min = 0, y.max = 1, y.count = 7, y.placement = Placement::endpoints, y.warp = Warp::square;
    z.name = "radius", z.min = 0.1, z.max = 10, z.count = 5, z.warp = Warp::log, z.flip = true;
    t.axes = {x, y, z};
    t.channels = {"F: test values", "G: more test values"};
    for (int k = 0; k < z.count; ++k)
        for (int j = 0; j < y.count; ++j)
            for (int i = 0; i < x.count; ++i) {
                const double a = x.value(i), b = y.value(j), c = std::log(z.value(k));
                t.values.push_back(std::sin(2 * a) * (1 + b) + 0.1 * c);
                t.values.push_back(std::cos(a + b * c));
            }
    t.errors.assign(t.values.size(), 0.0);
    TempDir dir;
    const std::string path = dir / "synthetic_3d.ktx2";
    write_table(path, t, PixelType::float32, Format::ktx2);
    const gpu::Texture tex = gpu::read_ktx2(path);
    ASSERT_TRUE(tex.is_3d);
    ASSERT_EQ(tex.height, static_cast<std::uint32_t>(y.count));
    ASSERT_EQ(tex.depth, static_cast<std::uint32_t>(z.count));
    const ExrImage img = read_table_image(path);
    LutDescription d;
    d.settings.axes = t.axes;

    const ShaderInterface si = shader_interface(t);
    ASSERT_EQ(si.dimensions, 3);
    const int points = 2000;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> ux(-0.1, 1.1), ur(-1.2, 1.2);
    std::vector<float> in;
    for (int k = 0; k < points; ++k) {
        in.push_back(static_cast<float>(ux(rng)));
        in.push_back(static_cast<float>(ux(rng)));
        in.push_back(static_cast<float>(std::pow(10.0, ur(rng))));
    }
    // Largest neighbour differences per axis, over the whole table.
    double d1[3] = {0, 0, 0}, vmax = 0;
    const int nx = x.count, ny = y.count;
    auto at = [&](int i, int j, int k, int c) {
        return t.values[static_cast<std::size_t>(((k * ny + j) * nx + i) * 2 + c)];
    };
    for (int k = 0; k < z.count; ++k)
        for (int j = 0; j < y.count; ++j)
            for (int i = 0; i < x.count; ++i)
                for (int c = 0; c < 2; ++c) {
                    vmax = std::max(vmax, std::abs(at(i, j, k, c)));
                    if (i + 1 < nx) d1[0] = std::max(d1[0], std::abs(at(i + 1, j, k, c) - at(i, j, k, c)));
                    if (j + 1 < ny) d1[1] = std::max(d1[1], std::abs(at(i, j + 1, k, c) - at(i, j, k, c)));
                    if (k + 1 < z.count) d1[2] = std::max(d1[2], std::abs(at(i, j, k + 1, c) - at(i, j, k, c)));
                }
    double tol = 4 * kEps * vmax;
    for (int a = 0; a < 3; ++a) tol += (weight_error() + 8 * kEps * t.axes[static_cast<std::size_t>(a)].count) * d1[a];

    for (const bool hlsl : {false, true}) {
        SCOPED_TRACE(hlsl ? "HLSL" : "GLSL");
        const std::string src = shader_source(t, Storage::float32, hlsl ? ShaderLanguage::hlsl : ShaderLanguage::glsl);
        ASSERT_NE(src.find(hlsl ? "Texture3D<float4> lut" : "sampler3D lut"), std::string::npos);
        const auto spv = gpu::compile_compute(glslang(), compute_shader(si, src, hlsl), hlsl, dir.path().string());
        const std::vector<float> res = runner().run(tex, spv, in, points, 4);
        double worst = 0;
        for (int k = 0; k < points; ++k) {
            const std::vector<double> params = {in[3 * static_cast<std::size_t>(k)], in[3 * static_cast<std::size_t>(k) + 1],
                                                in[3 * static_cast<std::size_t>(k) + 2]};
            for (int c = 0; c < 2; ++c) {
                const double want = sample_lut(img, d, params, c);
                const double got = res[static_cast<std::size_t>(k) * 4 + static_cast<std::size_t>(c)];
                ASSERT_LE(std::abs(got - want), tol) << "point " << k << " (" << params[0] << ", " << params[1]
                                                     << ", " << params[2] << ") channel " << c;
                worst = std::max(worst, std::abs(got - want));
            }
        }
        std::printf("3-D %s: %d points, max |gpu - sample| %.2e (tolerance %.2e)\n", hlsl ? "HLSL" : "GLSL", points,
                    worst, tol);
    }
}

INSTANTIATE_TEST_SUITE_P(Tables, ShaderLookup, ::testing::Range<std::size_t>(0, configs().size()),
                         [](const ::testing::TestParamInfo<std::size_t>& i) {
                             std::string n = configs()[i.param].name;
                             for (char& ch : n)
                                 if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                             return n;
                         });

}  // namespace
}  // namespace brdflut
