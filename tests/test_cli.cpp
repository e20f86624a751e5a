// The command-line tool, run as a user would.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "brdflut/exr.h"
#include "test_support.h"

using brdflut::test::run_cli;
using brdflut::test::TempDir;

TEST(Cli, ListShowsEveryTableWithAxesAndChannels) {
    TempDir dir;
    const auto r = run_cli("list", dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    for (const char* id : {"ggx_dfg", "ggx_albedo", "ggx_albedo_avg"})
        EXPECT_NE(r.out.find(id), std::string::npos) << id;
    EXPECT_NE(r.out.find("cos_theta [0, 1] 128 center linear"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("alpha [0, 1] 128 center square"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("R: A:"), std::string::npos) << r.out;
}

TEST(Cli, GenerateWritesTheTableIntoANewFolder) {
    TempDir dir;
    const auto r = run_cli("generate ggx_dfg ggx_albedo_avg --size 16 -o '" + (dir / "out/sub") + "' --visibility separable", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto img = brdflut::read_exr(dir / "out/sub/ggx_dfg.exr");
    EXPECT_EQ(img.width, 16);
    EXPECT_EQ(img.height, 16);
    EXPECT_EQ(img.metadata.at("model").at("visibility"), "separable");
    const auto avg = brdflut::read_exr(dir / "out/sub/ggx_albedo_avg.exr");
    EXPECT_EQ(avg.width, 16);
    EXPECT_EQ(avg.height, 1);
    EXPECT_NE(r.out.find("ggx_dfg.exr"), std::string::npos);
}

TEST(Cli, QualityIsRecordedInTheMetadata) {
    TempDir dir;
    const auto r = run_cli("generate ggx_albedo_avg --size 4 --quality draft -q -o '" + dir.path().string() + "'", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto img = brdflut::read_exr(dir / "ggx_albedo_avg.exr");
    EXPECT_EQ(img.metadata.at("method").at("quality"), "draft");
    EXPECT_EQ(img.metadata.at("method").at("abs_tolerance"), 1e-5);
}

TEST(Cli, InspectPrintsOneMetadataMemberByJsonPointer) {
    TempDir dir;
    ASSERT_EQ(run_cli("generate ggx_albedo_avg --size 4 -q -o '" + dir.path().string() + "'", dir).exit_code, 0);
    std::string file = dir / "ggx_albedo_avg.exr";
    file.insert(0, 1, '\'').push_back('\'');
    const auto table = run_cli("inspect " + file + " --metadata /table", dir);
    EXPECT_EQ(table.exit_code, 0) << table.err;
    EXPECT_EQ(table.out, "\"ggx_albedo_avg\"\n");
    // Arrays of numbers or strings print on one line.
    const auto axes = run_cli("inspect " + file + " --metadata /axes/0", dir);
    EXPECT_EQ(axes.exit_code, 0) << axes.err;
    EXPECT_NE(axes.out.find("\"name\": \"alpha\""), std::string::npos) << axes.out;
    const auto channels = run_cli("inspect " + file + " --metadata /channels", dir);
    EXPECT_EQ(channels.out.find('\n'), channels.out.size() - 1) << channels.out;
    const auto missing = run_cli("inspect " + file + " --metadata /nope", dir);
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_NE(missing.err.find("no such member; its top level: axes"), std::string::npos) << missing.err;
    const auto bad = run_cli("inspect " + file + " --metadata nope", dir);
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("is not a JSON pointer"), std::string::npos) << bad.err;
}

TEST(Cli, GenerateWithHalfPixelsAndNonSquareSize) {
    TempDir dir;
    const auto r = run_cli("generate ggx_albedo --size 8x4 --pixel half -q -o '" + dir.path().string() + "'", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(r.out.empty());
    const auto img = brdflut::read_exr(dir / "ggx_albedo.exr");
    EXPECT_EQ(img.width, 8);
    EXPECT_EQ(img.height, 4);
    EXPECT_EQ(img.pixel, brdflut::PixelType::half);
}

TEST(Cli, BadValuesGiveAClearErrorAndNonZeroExit) {
    TempDir dir;
    struct Case {
        std::string args, expect;
    };
    const Case cases[] = {
        {"generate ggx_dfg --size 0", "--size '0'"},
        {"generate ggx_dfg --size abc", "allowed: N or NxM"},
        {"generate ggx_dfg --size 8x8x8", "more counts than any requested table has axes"},
        {"generate ggx_albedo ggx_albedo_avg --channels R=G", "names a channel that no requested table has"},
        {"generate nope", "table 'nope' is not known; allowed: ggx_dfg"},
        {"generate ggx_dfg --pixel double", "allowed: half, float"},
        {"generate ggx_dfg --visibility smooth", "allowed: height_correlated, separable"},
        {"generate ggx_dfg --range alpha=0.5:0.5", "min and max must differ"},
        {"generate ggx_dfg --clamp alpha=0.5:0.2", "LO <= HI"},
        {"generate ggx_dfg --order alpha,alpha", "not an order of any requested table"},
        {"generate fresnel_dielectric_avg --range eta=1:inf", "range must be finite"},
        {"generate fresnel_dielectric_avg --range eta=1:inf --warp eta=ior_z", "clamp it to a finite one"},
        {"generate ggx_dfg --range alpha=0:2", "outside the model's domain"},
        {"generate ggx_dfg --count eta=4", "no requested table has an axis named 'eta'"},
        {"generate ggx_dfg --method mc --samples 0", "--samples 0"},
        {"generate ggx_dfg --quality best", "allowed: draft, default, reference"},
        {"generate ggx_dfg --threads -1", "--threads -1"},
        {"generate", "no table given"},
        {"frobnicate", "frobnicate"},
    };
    for (const Case& c : cases) {
        const auto r = run_cli(c.args + " -o '" + (dir / "o") + "'", dir);
        EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.expect), std::string::npos) << c.args << "\n" << r.err;
        EXPECT_EQ(r.err.rfind("brdflut: error: ", 0), 0u) << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "o/ggx_dfg.exr"));
}

TEST(Cli, GenerateAllTakesEveryOptionWhereItMeansSomething) {
    // Each model option of the default set, and the layout options that
    // only some tables can take, applied with --all: it applies to the
    // tables that have it and the others are written as they are. Options
    // that do not exclude each other share a run (each run generates the
    // whole default set). The same through a TOML config.
    TempDir dir;
    const char* options[] = {"--metal copper --material skin2 --eta 1.4 --fdr exact --visibility schlick_smith "
                             "--channels R=B --order alpha,cos_theta",
                             "--metal-eta 0.2,0.9,1.3 --metal-k 3.5,2.6,2 --sigma-s 1,2,3 --sigma-a 0.1,0.2,0.3 "
                             "--visibility separable --fresnel approx --range ior=1:2",
                             "--size 3x2x2"};
    for (const char* option : options) {
        const std::string out = dir / "out";
        const std::string size = std::string(option).find("--size") == std::string::npos ? "--size 2 " : "";
        const auto r =
            run_cli("generate --all -q --quality draft " + size + option + " -o '" + out + "'", dir);
        EXPECT_EQ(r.exit_code, 0) << option << "\n" << r.err;
        EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(out) / "ggx_dfg.exr")) << option;
        std::filesystem::remove_all(out);
    }
    std::ofstream(dir / "all.toml") << "all = true\nsize = \"2\"\nquality = \"draft\"\nmetal = \"copper\"\n"
                                       "material = \"skin2\"\nvisibility = \"schlick_smith\"\n";
    const auto r = run_cli("generate --config '" + (dir / "all.toml") + "' -q -o '" + (dir / "toml") + "'", dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(Cli, HelpIsAvailableOnEverySubcommand) {
    TempDir dir;
    for (const char* sub : {"", "list ", "generate "}) {
        const auto r = run_cli(std::string(sub) + "--help", dir);
        EXPECT_EQ(r.exit_code, 0) << sub;
        EXPECT_NE(r.out.find("--help"), std::string::npos) << sub;
    }
    const auto g = run_cli("generate --help", dir);
    EXPECT_NE(g.out.find("--visibility"), std::string::npos);
    EXPECT_NE(g.out.find("--method"), std::string::npos);
}

TEST(Cli, UnwritableOutputFolderIsARuntimeFailure) {
    TempDir dir;
    std::filesystem::create_directories(dir / "ro");
    {
        std::ofstream f(dir / "ro/file");
    }
    // A path whose parent is a regular file can never be created, even as root.
    const auto r = run_cli("generate ggx_albedo_avg --size 4 -o '" + (dir / "ro/file/sub") + "'", dir);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("cannot create output folder"), std::string::npos) << r.err;
}
