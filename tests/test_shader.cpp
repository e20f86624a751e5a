// The shader writer without a GPU: its command-line option and what it
// writes. tests/gpu/ runs the functions on lavapipe.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "brdflut/error.h"
#include "brdflut/shader.h"
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

}  // namespace
}  // namespace brdflut
