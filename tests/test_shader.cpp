// The shader writer without a GPU: its command-line option and what it
// writes. tests/gpu/ runs the functions on lavapipe.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "brdflut/catalogue.h"
#include "brdflut/error.h"
#include "brdflut/ltc.h"
#include "brdflut/ltc_compare.h"
#include "brdflut/ltc_fit.h"
#include "brdflut/shader.h"
#include "tables/ltc_tables.h"
#include "test_support.h"

namespace brdflut {
namespace {

using test::TempDir;

std::size_t occurrences(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

TEST(ShaderWriter, UnknownLanguageIsAUsageErrorNamingTheAllowedOnes) {
    TempDir dir;
    const auto r = test::run_cli("generate ggx_albedo_avg --size 8 --shader wgsl -o '" + dir / "out" + "'", dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("'wgsl'"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("allowed: glsl, hlsl"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out/ggx_albedo_avg.exr"));
    EXPECT_THROW(shader_language_from_string("GLSL"), Error);
}

TEST(ShaderWriter, WritesOneFunctionPerTableBesideIt) {
    TempDir dir;
    const auto r = test::run_cli("generate ggx_dfg fresnel_dielectric_avg --size 8 --format dds --shader glsl "
                                 "--shader hlsl -q -o '" + dir / "out" + "'", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* id : {"ggx_dfg", "fresnel_dielectric_avg"})
        for (const char* ext : {"glsl", "hlsl"}) {
            const std::string text = test::read_file(dir / ("out/" + std::string(id) + "." + ext));
            ASSERT_FALSE(text.empty()) << id << "." << ext;
            EXPECT_EQ(occurrences(text, " brdflut_" + std::string(id) + "("), 1u) << text;
            EXPECT_NE(text.find("table '" + std::string(id) + "'"), std::string::npos);
            EXPECT_NE(text.find("metadata fnv1a64 "), std::string::npos);
        }
    // The channels by name, the parameters by axis name.
    const std::string dfg = test::read_file(dir / "out/ggx_dfg.glsl");
    EXPECT_NE(dfg.find("(sampler2D lut, float cos_theta, float alpha)"), std::string::npos) << dfg;
    EXPECT_NE(dfg.find("result.A = texel.r;"), std::string::npos);
    EXPECT_NE(dfg.find("result.B = texel.g;"), std::string::npos);
    const std::string avg = test::read_file(dir / "out/fresnel_dielectric_avg.hlsl");
    EXPECT_NE(avg.find("(Texture2D<float4> lut, SamplerState lut_sampler, float eta)"), std::string::npos) << avg;
    EXPECT_NE(avg.find("result.F_avg_eta = texel.r;"), std::string::npos);
    EXPECT_NE(avg.find("result.F_avg_1_eta = texel.g;"), std::string::npos);
}

TEST(ShaderWriter, TransposedTableKeepsTheSignatureAndReadsItsFirstStoredAxisAsX) {
    TempDir dir;
    const auto r = test::run_cli("generate ggx_dfg --size 8x4 --order alpha,cos_theta --flip alpha --shader glsl -q -o '" +
                                 dir / "out" + "'", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string text = test::read_file(dir / "out/ggx_dfg.glsl");
    EXPECT_NE(text.find("(sampler2D lut, float cos_theta, float alpha)"), std::string::npos) << text;
    const std::size_t x = text.find("// x: alpha, 8 texels"), y = text.find("// y: cos_theta, 4 texels");
    EXPECT_NE(x, std::string::npos) << text;
    EXPECT_NE(y, std::string::npos) << text;
    EXPECT_NE(text.find("x = 1.0 - x;"), std::string::npos) << "alpha is stored flipped";
    EXPECT_EQ(text.find("y = 1.0 - y;"), std::string::npos);
}

// The LTC matrix tables return M^-1 built from the filtered texel in their
// documented packing. Heitz's ltc_1 as three.js and EEVEE unpack it:
// mat3(vec3(R, 0, G), vec3(0, 1, 0), vec3(B, 0, A)), GLSL's columns; HLSL's
// float3x3 constructor takes rows, so the same matrix reads transposed.
// HDRP's channels are invM._m00_m02_m11_m20 of the transpose (invM._m22 =
// 1): by rows M^-1 = [[R, 0, A], [0, B, 0], [G, 0, 1]].
TEST(ShaderWriter, LtcMatrixTablesBuildTheInverseMatrixFromTheirDocumentedPacking) {
    TempDir dir;
    const auto r = test::run_cli("generate ltc_1 ltc_2 ltc_ggx_error hdrp_ltc_ggx --size 4x4 --quality draft "
                                 "--shader glsl --shader hlsl -q -o '" + dir / "out" + "'", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string heitz_glsl = test::read_file(dir / "out/ltc_1.glsl");
    EXPECT_NE(heitz_glsl.find("    mat3 inverse_matrix;\n"), std::string::npos) << heitz_glsl;
    EXPECT_NE(heitz_glsl.find("result.inverse_matrix = mat3(vec3(texel.r, 0.0, texel.g), vec3(0.0, 1.0, 0.0), "
                              "vec3(texel.b, 0.0, texel.a));"),
              std::string::npos) << heitz_glsl;
    EXPECT_NE(heitz_glsl.find("inverse_matrix * v"), std::string::npos);
    EXPECT_NE(heitz_glsl.find("constructor takes columns"), std::string::npos);
    const std::string heitz_hlsl = test::read_file(dir / "out/ltc_1.hlsl");
    EXPECT_NE(heitz_hlsl.find("    float3x3 inverse_matrix;\n"), std::string::npos) << heitz_hlsl;
    EXPECT_NE(heitz_hlsl.find("result.inverse_matrix = float3x3(float3(texel.r, 0.0, texel.b), float3(0.0, 1.0, 0.0), "
                              "float3(texel.g, 0.0, texel.a));"),
              std::string::npos) << heitz_hlsl;
    EXPECT_NE(heitz_hlsl.find("mul(inverse_matrix, v)"), std::string::npos);
    EXPECT_NE(heitz_hlsl.find("constructor takes rows"), std::string::npos);
    const std::string hdrp_glsl = test::read_file(dir / "out/hdrp_ltc_ggx.glsl");
    EXPECT_NE(hdrp_glsl.find("result.inverse_matrix = mat3(vec3(texel.r, 0.0, texel.g), vec3(0.0, texel.b, 0.0), "
                             "vec3(texel.a, 0.0, 1.0));"),
              std::string::npos) << hdrp_glsl;
    const std::string hdrp_hlsl = test::read_file(dir / "out/hdrp_ltc_ggx.hlsl");
    EXPECT_NE(hdrp_hlsl.find("result.inverse_matrix = float3x3(float3(texel.r, 0.0, texel.a), "
                             "float3(0.0, texel.b, 0.0), float3(texel.g, 0.0, 1.0));"),
              std::string::npos) << hdrp_hlsl;
    // The norms and the error report keep their channels by name alone.
    for (const char* id : {"ltc_2", "ltc_ggx_error"})
        for (const char* ext : {"glsl", "hlsl"}) {
            const std::string text = test::read_file(dir / ("out/" + std::string(id) + "." + ext));
            ASSERT_FALSE(text.empty()) << id << "." << ext;
            EXPECT_EQ(text.find("inverse_matrix"), std::string::npos) << id << "." << ext;
            EXPECT_NE(text.find(" = texel.a;"), std::string::npos) << text;
        }
}

// A file storing sums of channels (a channel map) does not hold the matrix's
// elements: the function returns the channels and says why there is no matrix.
TEST(ShaderWriter, LtcMatrixTableWithAChannelMapReturnsItsChannelsOnly) {
    TempDir dir;
    const auto r = test::run_cli("generate ltc_1 --size 4x4 --quality draft --channels R=R+G,G=B "
                                 "--shader glsl -q -o '" + dir / "out" + "'", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string text = test::read_file(dir / "out/ltc_1.glsl");
    EXPECT_EQ(text.find("mat3 inverse_matrix;"), std::string::npos) << text;
    EXPECT_NE(text.find("no inverse_matrix"), std::string::npos) << text;
    EXPECT_NE(text.find(" = texel.g;"), std::string::npos) << text;
    Table t;
    t.id = "ltc_1";
    Axis a;
    a.count = 4;
    t.axes = {a, a};
    t.channels = {"", ""};
    t.channel_map = {{0, 1}, {2}};
    EXPECT_EQ(shader_interface(t).matrix, "");
    t.channel_map.clear();
    t.channels.assign(4, "");
    EXPECT_EQ(shader_interface(t).matrix, "inverse_matrix");
}

// The catalogue's packing of each LTC matrix table (shader_matrix) unpacks
// what its evaluator stores to the fitted M^-1, up to the scale the tables
// divide by (the LTC does not change when M^-1 is scaled).
TEST(ShaderWriter, LtcShaderMatrixUnpacksTheFittedInverseTheEvaluatorStores) {
    int tables = 0;
    for (const TableDefinition& def : catalogue()) {
        if (def.shader_result != "ltc_inverse") continue;
        SCOPED_TRACE(def.id);
        ++tables;
        TableSettings s = default_settings(def);
        s.quality = Quality::draft;
        const PreparedTable p = def.prepare(s);
        for (const double r : {0.35, 0.8})
            for (const double mu : {0.25, 0.9}) {
                const double coords[2] = {r, mu};  // (roughness, cos_theta), the definition's order
                const TexelValue v = p.evaluator->evaluate(coords, 0);
                const Mat3 m = stored_ltc_inverse(def, v.value.data());
                const Mat3 fit = fit_ltc(ltc_table_lobe(def, r, mu), ltc_fit_options(0)).minv.matrix();
                ASSERT_GT(std::abs(m.m[1][1]), 0.0);
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j)
                        EXPECT_NEAR(m.m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] / m.m[1][1],
                                    fit.m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)], 1e-12)
                            << "M^-1[" << i << "][" << j << "] at roughness " << r << ", cos_theta " << mu;
            }
    }
    EXPECT_GT(tables, 0) << "no LTC matrix table in the catalogue";
}

}  // namespace
}  // namespace brdflut
