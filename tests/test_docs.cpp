// The reference pages in docs/reference are what `brdflut docs` renders from
// the catalogue today (regenerate them with `brdflut docs`), every family
// describes itself, and `brdflut list --json` holds the whole catalogue.
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "brdflut/catalogue.h"
#include "test_support.h"

using namespace brdflut;

TEST(Docs, ReferencePagesAreUpToDate) {
    test::TempDir dir;
    const std::string pages = std::string(BRDFLUT_SOURCE_DIR) + "/docs/reference";
    const test::CliResult r = test::run_cli("docs --check -o '" + pages + "'", dir);
    EXPECT_EQ(r.exit_code, 0) << r.err << "\nregenerate: ./build/brdflut docs -o docs/reference";
}

TEST(Docs, CheckNamesAStalePageAndWriteRestoresIt) {
    test::TempDir dir;
    const std::string out = dir / "reference";
    ASSERT_EQ(test::run_cli("docs -o '" + out + "'", dir).exit_code, 0);
    {
        std::ofstream f(dir / "reference/tables.md", std::ios::app);
        f << "a hand edit\n";
    }
    const test::CliResult stale = test::run_cli("docs --check -o '" + out + "'", dir);
    EXPECT_EQ(stale.exit_code, 1);
    EXPECT_NE(stale.err.find("tables.md"), std::string::npos) << stale.err;
    ASSERT_EQ(test::run_cli("docs -o '" + out + "'", dir).exit_code, 0);
    EXPECT_EQ(test::run_cli("docs --check -o '" + out + "'", dir).exit_code, 0);
}

TEST(Docs, EveryFamilyDescribesItselfAndOwnsItsTables) {
    std::set<std::string> names;
    for (const TableFamily& f : table_families()) {
        EXPECT_TRUE(names.insert(f.name).second) << f.name;
        EXPECT_FALSE(f.title.empty() || f.title == f.name) << "family " << f.name << " gives no title";
        EXPECT_GE(f.summary.size(), 100u) << "family " << f.name << " gives no summary";
    }
    for (const TableDefinition& d : catalogue()) EXPECT_EQ(names.count(d.family), 1u) << d.id << ": " << d.family;
}

TEST(Docs, ListJsonHoldsEveryTableAndPreset) {
    test::TempDir dir;
    const test::CliResult r = test::run_cli("list --json", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j.at("tables").size(), catalogue().size());
    for (std::size_t i = 0; i < catalogue().size(); ++i) {
        const TableDefinition& d = catalogue()[i];
        const nlohmann::json& t = j.at("tables")[i];
        EXPECT_EQ(t.at("id"), d.id);
        EXPECT_EQ(t.at("axes").size(), d.axes.size()) << d.id;
        EXPECT_EQ(t.at("channels").size(), d.channels.size()) << d.id;
        EXPECT_EQ(t.at("checks").size(), d.checks.size()) << d.id;
        EXPECT_EQ(t.at("engine_storage"), d.engine_storage ? std::string(to_string(*d.engine_storage)) : "") << d.id;
    }
    EXPECT_EQ(j.at("presets").size(), presets().size());
}

TEST(Docs, ListNamesTheEngineStorageOfThePresetTablesThatHaveOne) {
    // unreal_dfg is G16R16 UNORM in Unreal, gltf_ggx an RGBA8 PNG, babylon_brdf
    // RGBD in RGBA8; ggx_dfg, no engine's, has none.
    test::TempDir dir;
    const test::CliResult all = test::run_cli("list", dir), presets_only = test::run_cli("list --presets", dir);
    ASSERT_EQ(all.exit_code, 0) << all.err;
    ASSERT_EQ(presets_only.exit_code, 0) << presets_only.err;
    const std::string text = "\n" + all.out;
    auto section = [&](const std::string& id) {  // from the table's id line to the blank line after it
        std::size_t at = text.find("\n" + id + "\n");
        if (at == std::string::npos) at = text.find("\n" + id + " [");
        if (at == std::string::npos) return std::string();
        return text.substr(at + 1, text.find("\n\n", at + 1) - at - 1);
    };
    for (const auto& [id, storage] :
         {std::pair{"unreal_dfg", "unorm16"}, {"gltf_ggx", "unorm8"}, {"babylon_brdf", "rgbd"}}) {
        EXPECT_NE(section(id).find(std::string("  engine storage: ") + storage), std::string::npos) << id;
        EXPECT_NE(presets_only.out.find(std::string(id) + " [engine: " + storage + "]"), std::string::npos) << id;
    }
    ASSERT_FALSE(section("ggx_dfg").empty());
    EXPECT_EQ(section("ggx_dfg").find("engine storage"), std::string::npos);
}

TEST(Docs, ListPresetsJsonHoldsOnlyThePresets) {
    test::TempDir dir;
    const test::CliResult r = test::run_cli("list --presets --json", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_FALSE(j.contains("tables"));
    ASSERT_EQ(j.at("presets").size(), presets().size());
    for (std::size_t i = 0; i < presets().size(); ++i) {
        EXPECT_EQ(j.at("presets")[i].at("name"), presets()[i].name);
        EXPECT_EQ(j.at("presets")[i].at("tables").size(), preset_tables(presets()[i].name).size());
    }
}
