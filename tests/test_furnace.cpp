// White-furnace report: the models meant to conserve energy do, and the
// report finds the models that gain energy.
#include <gtest/gtest.h>

#include "brdflut/error.h"
#include "brdflut/furnace.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include "test_support.h"

using namespace brdflut;

namespace {
FurnaceOptions small() {
    FurnaceOptions o;
    o.size = 16;
    return o;
}
}  // namespace

TEST(Furnace, GgxWithKullaContyReturnsOneWithin1e4Everywhere) {
    const FurnaceReport r = run_furnace(find_furnace_model("ggx_kulla_conty"), small());
    EXPECT_TRUE(r.pass);
    for (double e : r.albedo) EXPECT_NEAR(e, 1.0, 1e-4);
    for (double a : r.averages) EXPECT_NEAR(a, 1.0, 1e-4);
    // Without the lobe the same grid loses energy.
    const FurnaceReport ss = run_furnace(find_furnace_model("ggx"), small());
    EXPECT_GT(ss.worst_loss.value, 0.3);
    EXPECT_LE(ss.max_excess.value, 0.0);
}

TEST(Furnace, EonReturnsOneWithin1e6Everywhere) {
    const FurnaceReport r = run_furnace(find_furnace_model("eon"), small());
    EXPECT_TRUE(r.pass);
    for (double e : r.albedo) EXPECT_NEAR(e, 1.0, 1e-6);
    for (double a : r.averages) EXPECT_NEAR(a, 1.0, 1e-6);
}

TEST(Furnace, FindsWhereBurleyDiffuseExceedsOne) {
    const FurnaceReport r = run_furnace(find_furnace_model("disney_diffuse"), small());
    EXPECT_GT(r.max_excess.value, 0.4);
    ASSERT_EQ(r.max_excess.params.size(), 2u);
    EXPECT_LT(r.max_excess.params[0], 0.1);  // grazing
    EXPECT_GT(r.max_excess.params[1], 0.9);  // rough
    EXPECT_TRUE(r.pass);                     // not meant to conserve: reported, not failed
}

TEST(Furnace, AConservingModelFailsATighterTolerance) {
    FurnaceOptions o = small();
    o.tolerance = 1e-12;
    EXPECT_FALSE(run_furnace(find_furnace_model("ggx_kulla_conty"), o).pass);
}

TEST(Furnace, EveryModelReportsFiniteAlbedosOverItsGrid) {
    for (const FurnaceModel& m : furnace_models()) {
        FurnaceOptions o = small();
        o.size = 8;
        const FurnaceReport r = run_furnace(m, o);
        EXPECT_FALSE(r.albedo.empty()) << m.id;
        for (double e : r.albedo) EXPECT_TRUE(std::isfinite(e) && e >= 0.0) << m.id;
        EXPECT_LE(r.min.value, r.max.value) << m.id;
        EXPECT_FALSE(r.averages.empty()) << m.id;
    }
}

TEST(Furnace, UnknownModelListsTheKnownOnes) {
    try {
        find_furnace_model("phong");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("ggx_kulla_conty"), std::string::npos);
    }
}

TEST(CliFurnace, ExitCodeFollowsTheConservingModels) {
    test::TempDir dir;
    const auto ok = test::run_cli("furnace eon disney_diffuse --size 8", dir);
    EXPECT_EQ(ok.exit_code, 0) << ok.err;
    EXPECT_NE(ok.out.find("exceeds 1"), std::string::npos) << ok.out;
    const auto bad = test::run_cli("furnace ggx_kulla_conty --size 8 --tolerance 1e-12 --json", dir);
    EXPECT_EQ(bad.exit_code, 1) << bad.err;
    EXPECT_FALSE(nlohmann::json::parse(bad.out).at("pass").get<bool>());
}

TEST(CliFurnace, PlotWritesOnePngPerModel) {
    test::TempDir dir;
    const auto r = test::run_cli("furnace eon disney_sheen --size 8 --plot '" + (dir / "plots") + "'", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* f : {"plots/furnace_eon.png", "plots/furnace_disney_sheen.png"})
        EXPECT_EQ(test::read_file(dir / f).substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8)) << f;
}
