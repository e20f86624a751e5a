// The benchmark figures of docs/performance.md are rendered from the
// benchmarks' output by bench/update_readme.sh. Without timing anything,
// check that the block is exactly what the renderer writes from the output
// it quotes (so no figure was typed in or edited by hand), that it sits in
// the Performance page,
// that it names only tables the catalogue has, that its ratios are those of
// its times, and that its deterministic figure (ggx_dfg's evaluations per
// texel) is what the code does today.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "brdflut/catalogue.h"
#include "brdflut/error.h"
#include "brdflut/generate.h"
#include "readme_figures.h"
#include "test_support.h"

using namespace brdflut;

namespace {

std::string source_file(const std::string& path) {
    std::ifstream in(std::string(BRDFLUT_SOURCE_DIR) + "/" + path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}
// The page that holds the benchmark figures.
std::string readme() { return source_file("docs/performance.md"); }

const bench::Record& find(const std::vector<bench::Record>& rs, const std::string& kind, const std::string& key,
                          const std::string& value) {
    for (const bench::Record& r : rs)
        if (r.kind == kind && r.has(key) && r.at(key) == value) return r;
    throw std::runtime_error("no '" + kind + "' line with " + key + "=" + value);
}

}  // namespace

TEST(ReadmeFigures, BlockIsWhatTheRendererWritesFromTheOutputItQuotes) {
    const std::string text = readme();
    ASSERT_FALSE(text.empty());
    std::size_t begin = 0;
    const std::string block = bench::extract_block(text, &begin);
    // On the Performance page, before its first section.
    EXPECT_EQ(text.compare(0, 14, "# Performance\n"), 0) << "the figures are not on the Performance page";
    EXPECT_EQ(text.rfind("\n## ", begin), std::string::npos) << "the figures are not in the page's introduction";
    const std::vector<bench::Record> records = bench::parse_records(block);
    ASSERT_FALSE(records.empty());
    EXPECT_EQ(bench::render_block(records), block);
}

TEST(ReadmeFigures, RendererRejectsMissingAndMalformedFigures) {
    EXPECT_THROW(bench::render_block(bench::parse_records("time program=ggx_dfg threads=1 median_s=0.1\n")),
                 std::runtime_error);
    EXPECT_THROW(bench::parse_records("table id=ggx_dfg wall_s\n"), std::runtime_error);
    const std::vector<bench::Record> r = bench::parse_records("table id=ggx_dfg wall_s=0.1x\n");
    EXPECT_THROW(r.at(0).number("wall_s"), std::runtime_error);
    EXPECT_THROW(bench::extract_block("no markers here"), std::runtime_error);
}

TEST(ReadmeFigures, NameOnlyCatalogueTablesAndKeepTheirArithmetic) {
    const std::vector<bench::Record> records = bench::parse_records(bench::extract_block(readme()));
    for (const bench::Record& r : records) {
        if (r.kind == "table") {
            EXPECT_NO_THROW(find_table(r.at("id"))) << r.line();
        }
        if (r.kind == "race") {
            EXPECT_NO_THROW(find_table(r.at("table"))) << r.line();
        }
    }
    for (const char* threads : {"1", "2"}) {
        double quad = 0.0, karis = 0.0;
        for (const bench::Record& r : records)
            if (r.kind == "time" && r.at("threads") == threads) {
                if (r.at("program") == "ggx_dfg") quad = r.number("median_s");
                if (r.at("program") == "karis_float") karis = r.number("median_s");
                EXPECT_LE(r.number("min_s"), r.number("median_s")) << r.line();
                EXPECT_LE(r.number("median_s"), r.number("max_s")) << r.line();
            }
        ASSERT_GT(quad, 0.0) << threads;
        ASSERT_GT(karis, 0.0) << threads;
        const double ratio = find(records, "ratio", "threads", threads).number("ggx_dfg_over_karis_float");
        EXPECT_NEAR(ratio, quad / karis, 0.01 * ratio + 1e-3) << "threads " << threads;
    }
    // The claim of the table: every stored ggx_dfg value within 1e-7.
    EXPECT_LE(find(records, "accuracy", "program", "ggx_dfg").number("max_error"), 1e-7);
}

TEST(ReadmeFigures, GgxDfgEvaluationsPerTexelAreTheCodesOwn) {
    // Deterministic, so a change of the quadrature that leaves the README's
    // figures behind fails here.
    const std::vector<bench::Record> records = bench::parse_records(bench::extract_block(readme()));
    const bench::Record& race = find(records, "race", "table", "ggx_dfg");
    const TableDefinition& def = find_table("ggx_dfg");
    TableSettings s = default_settings(def);
    s.quality = quality_from_string(race.at("quality"));
    ASSERT_EQ(race.at("size"), std::to_string(s.axes[0].count) + "x" + std::to_string(s.axes[1].count));
    clear_shared_results();
    const Table t = generate(def, s);
    const double per_texel = static_cast<double>(t.evaluations) / static_cast<double>(t.texel_count());
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.0f", per_texel);
    EXPECT_EQ(find(records, "accuracy", "program", "ggx_dfg").at("evaluations_per_texel"), std::string(buf));
}

// The README's picture is what the command it names writes. (Its command
// lines, like those of docs/, run in tests/doc_commands.cpp.)
TEST(Readme, PictureIsWhatItsCommandWrites) {
    const std::string readme_text = source_file("README.md");
    const std::string command = "./build/brdflut furnace ggx --plot docs/images";
    ASSERT_NE(readme_text.find(command), std::string::npos) << "the README no longer names the picture's command";
    test::TempDir dir;
    const test::CliResult r = test::run_cli("furnace ggx --plot '" + (dir / "images") + "'", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(test::read_file(dir / "images/furnace_ggx.png"),
              source_file("docs/images/furnace_ggx.png"))
        << "regenerate the picture: " << command;
}
