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
    ASSERT_EQ(test::run_cli("docs --check -o '" + out + "'", dir).exit_code, 0);
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
    }
    EXPECT_EQ(j.at("presets").size(), presets().size());
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
