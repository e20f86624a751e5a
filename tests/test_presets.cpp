// Engine presets: each writes its tables in the engine's layout, the
// metadata describes that layout, and every value is a core integral at the
// texel's coordinates converted to the model's.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "brdflut/catalogue.h"
#include "brdflut/error.h"
#include "brdflut/exr.h"
#include "brdflut/generate.h"
#include "brdflut/ggx_integrals.h"
#include "brdflut/lobe_integrals.h"
#include "brdflut/microfacet.h"
#include "brdflut/sheen_integrals.h"
#include "test_support.h"

using namespace brdflut;
using brdflut::test::run_cli;
using brdflut::test::TempDir;

namespace {
Table small(const std::string& id, int n) {
    const TableDefinition& def = find_table(id);
    TableSettings s = default_settings(def);
    for (Axis& a : s.axes) a.count = n;
    return generate(def, s);
}
// The stored value is the integral: within the table's error estimate and
// the reference's (both honest, tests/test_ggx.cpp and the others).
void expect_within(const Table& t, std::size_t texel, int channel, double value, double error) {
    const std::size_t k = texel * t.channels.size() + static_cast<std::size_t>(channel);
    EXPECT_NEAR(t.values[k], value, t.errors[k] + error + 1e-15)
        << t.id << " texel " << texel << " channel " << channel;
}
}  // namespace

TEST(Presets, EveryPresetWritesItsTablesWithTheirLayoutInTheMetadata) {
    TempDir dir;
    for (const Preset& p : presets()) {
        const auto r = run_cli("generate --preset " + p.name + " --size 4 -q -o '" + (dir / p.name) + "'", dir);
        ASSERT_EQ(r.exit_code, 0) << p.name << ": " << r.err;
        const auto tables = preset_tables(p.name);
        ASSERT_FALSE(tables.empty()) << p.name;
        for (const TableDefinition* def : tables) {
            const ExrImage img = read_exr(dir / (p.name + "/" + def->id + ".exr"));
            ASSERT_TRUE(img.has_metadata) << def->id;
            const auto& m = img.metadata;
            EXPECT_EQ(m["table"], def->id);
            EXPECT_EQ(m["model"]["preset"], p.name) << def->id;
            EXPECT_EQ(m["pixel"], std::string(to_string(p.pixel))) << def->id;
            EXPECT_EQ(img.pixel, p.pixel) << def->id;
            ASSERT_EQ(m["axes"].size(), def->axes.size()) << def->id;
            for (std::size_t i = 0; i < def->axes.size(); ++i) {
                const Axis& a = def->axes[i].axis;
                EXPECT_EQ(m["axes"][i]["name"], a.name) << def->id;
                EXPECT_EQ(m["axes"][i]["placement"], std::string(to_string(a.placement))) << def->id;
                EXPECT_EQ(m["axes"][i]["warp"], std::string(to_string(a.warp))) << def->id;
                EXPECT_EQ(m["axes"][i]["count"], 4) << def->id;
            }
            EXPECT_EQ(img.channel_names.size(), def->channels.size()) << def->id;
        }
    }
}

TEST(Presets, TheirLayoutsAreTheEnginesOwn) {
    auto axis = [](const std::string& id, int i) { return find_table(id).axes[static_cast<std::size_t>(i)].axis; };
    // Filament: 128 x 128 cell centres, perceptual roughness rows.
    EXPECT_EQ(axis("filament_dfg", 0).count, 128);
    EXPECT_EQ(axis("filament_dfg", 1).name, "roughness");
    EXPECT_EQ(axis("filament_dfg", 1).placement, Placement::center);
    // Unreal: 128 x 32.
    EXPECT_EQ(axis("unreal_dfg", 1).count, 32);
    // HDRP: 64 x 64 end points with x = sqrt(NdotV).
    const Axis h = axis("hdrp_fgd", 0);
    EXPECT_EQ(h.count, 64);
    EXPECT_EQ(h.placement, Placement::endpoints);
    EXPECT_DOUBLE_EQ(h.value(32), std::pow(32.0 / 63.0, 2));
    // Cycles: x = sqrt(alpha) at end points, then mu.
    const Axis c = axis("cycles_ggx_e", 0);
    EXPECT_EQ(c.name, "alpha");
    EXPECT_EQ(c.count, 32);
    EXPECT_DOUBLE_EQ(std::sqrt(c.value(10)), 10.0 / 31.0);
    EXPECT_EQ(axis("cycles_ggx_e", 1).name, "cos_theta");
    EXPECT_DOUBLE_EQ(axis("cycles_ggx_e", 1).value(31), 1.0);
}

TEST(Presets, FilamentValuesAreTheCoreIntegralsAtAlphaRoughnessSquared) {
    const Table t = small("filament_dfg", 5);
    for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 5; ++i) {
            const double mu = (i + 0.5) / 5, r = (j + 0.5) / 5, alpha = r * r;
            const std::size_t texel = static_cast<std::size_t>(j * 5 + i);
            const Estimate<2> s = ggx_split_sum(mu, alpha, Visibility::height_correlated);
            const Estimate<1> cloth = sheen_charlie_albedo(mu, alpha);
            expect_within(t, texel, 0, s.value[1], s.error[1]);
            expect_within(t, texel, 1, s.value[0] + s.value[1], s.error[0] + s.error[1]);
            expect_within(t, texel, 2, cloth.value[0], cloth.error[0]);
        }
}

TEST(Presets, UnrealUsesSchlickSmithAndGodotGltfUseHeightCorrelatedScaleAndBias) {
    const Table u = small("unreal_dfg", 4), g = small("godot_dfg", 4), l = small("gltf_ggx", 4);
    for (std::size_t texel : {0u, 5u, 10u, 15u}) {
        const double mu = (static_cast<double>(texel % 4) + 0.5) / 4, r = (static_cast<double>(texel / 4) + 0.5) / 4;
        const Estimate<2> s = ggx_split_sum(mu, r * r, Visibility::schlick_smith);
        const Estimate<2> hc = ggx_split_sum(mu, r * r, Visibility::height_correlated);
        for (int c = 0; c < 2; ++c) {
            expect_within(u, texel, c, s.value[c], s.error[c]);
            expect_within(g, texel, c, hc.value[c], hc.error[c]);
            expect_within(l, texel, c, hc.value[c], hc.error[c]);
        }
    }
    const Table ch = small("gltf_charlie", 3);
    EXPECT_EQ(ch.at(4, 0), 0.0);
    EXPECT_EQ(ch.at(4, 1), 0.0);
    const Estimate<1> cloth = sheen_charlie_albedo(0.5, 0.25);
    expect_within(ch, 4, 2, cloth.value[0], cloth.error[0]);
}

TEST(Presets, HdrpStoresSquaredCosineColumnsAndDiffuseMinusOneHalf) {
    const Table t = small("hdrp_fgd", 4);
    for (int j = 0; j < 4; ++j)
        for (int i = 1; i < 4; ++i) {
            const double mu = std::pow(i / 3.0, 2), r = j / 3.0;
            const std::size_t texel = static_cast<std::size_t>(j * 4 + i);
            const Estimate<2> s = ggx_split_sum(mu, r * r, Visibility::height_correlated);
            const Estimate<1> d = lobe_albedo(Lobe::disney_diffuse, mu, r);
            expect_within(t, texel, 0, s.value[1], s.error[1]);
            expect_within(t, texel, 1, s.value[0] + s.value[1], s.error[0] + s.error[1]);
            expect_within(t, texel, 2, d.value[0] - 0.5, d.error[0]);
        }
}

TEST(Presets, CyclesSwapsTheAxesAndStoresTheGrazingLimit) {
    const Table t = small("cycles_ggx_e", 5);
    for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 5; ++i) {
            const double alpha = std::pow(i / 4.0, 2), mu = j / 4.0;
            const std::size_t texel = static_cast<std::size_t>(j * 5 + i);
            const double v = t.at(texel, 0);
            const Estimate<2> s = ggx_split_sum(mu, alpha, Visibility::height_correlated);
            if (j > 0) expect_within(t, texel, 0, s.value[0] + s.value[1], s.error[0] + s.error[1]);
            // mu = 0: the limit mu -> 0+, which is 1 for every alpha (not the 0 of the 0/0 point).
            else EXPECT_NEAR(v, 1.0, 1e-9) << i;
        }
    // alpha = 1: E(mu) = 1 - mu ln(1 + 1/mu).
    EXPECT_NEAR(t.at(2 * 5 + 4, 0), 1.0 - 0.5 * std::log(3.0), 1e-9);
    const Table avg = small("cycles_ggx_e_avg", 3);
    EXPECT_NEAR(avg.at(2, 0), 4.0 / 3.0 * (1.0 - std::log(2.0)), 1e-9);
}

TEST(Presets, UnknownPresetNamesTheKnownOnes) {
    EXPECT_THROW(find_preset("nope"), Error);
    TempDir dir;
    const auto r = run_cli("generate --preset nope -o '" + (dir / "x") + "'", dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("filament"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("cycles"), std::string::npos) << r.err;
    const auto both = run_cli("generate --preset cycles ggx_dfg -o '" + (dir / "x") + "'", dir);
    EXPECT_EQ(both.exit_code, 2);
}

TEST(Presets, ExplicitPixelTypeOverridesThePresets) {
    TempDir dir;
    const auto r = run_cli("generate --preset unreal --pixel half --size 3 -q -o '" + (dir / "u") + "'", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(read_exr(dir / "u/unreal_dfg.exr").pixel, PixelType::half);
}

TEST(Presets, AllGeneratesTheDefaultSetOnlyAndListTagsPresets) {
    TempDir dir;
    const auto r = run_cli("generate --all --size 2 -q -o '" + (dir / "all") + "'", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "all/sheen_charlie_albedo.exr"));
    EXPECT_TRUE(std::filesystem::exists(dir / "all/ggx_dfg.exr"));
    for (const TableDefinition& d : catalogue()) {
        if (!d.preset.empty()) {
            EXPECT_FALSE(std::filesystem::exists(dir / ("all/" + d.id + ".exr"))) << d.id;
        }
    }

    const auto list = run_cli("list", dir);
    EXPECT_NE(list.out.find("filament_dfg [preset: filament]"), std::string::npos);
    const auto names = run_cli("list --presets", dir);
    for (const Preset& p : presets()) EXPECT_NE(names.out.find(p.name + "\n"), std::string::npos) << p.name;
}
