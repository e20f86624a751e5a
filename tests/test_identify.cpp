// brdflut identify: a table written in each convention of the axis
// vocabulary is identified in that convention first, the printed compare
// command passes on it, and the known bug patterns are named.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>

#include "brdflut/catalogue.h"
#include "brdflut/error.h"
#include "brdflut/exr.h"
#include "brdflut/generate.h"
#include "brdflut/identify.h"
#include "brdflut/lut.h"
#include <cmath>
#include "test_support.h"

using namespace brdflut;
using brdflut::test::run_cli;
using brdflut::test::TempDir;
using brdflut::test::image_of;

namespace {

// A table in a layout given as the generate options spell it (--size,
// --range, --placement, --warp, --order, --flip, --clamp, --shift,
// --channels and model options), parsed here into TableSettings.
Table make(const std::string& id, const std::string& args) {
    const TableDefinition& def = find_table(id);
    TableSettings s = default_settings(def);
    std::vector<std::string> words;
    std::string w;
    for (char c : args + " ") {
        if (c != ' ') {
            w += c;
        } else if (!w.empty()) {
            words.push_back(w);
            w.clear();
        }
    }
    auto axis = [&](const std::string& name) -> Axis& {
        for (Axis& a : s.axes)
            if (a.name == name) return a;
        throw Error("no axis " + name);
    };
    auto split = [](const std::string& v, char sep) {
        const std::size_t at = v.find(sep);
        return std::pair{v.substr(0, at), v.substr(at + 1)};
    };
    auto number = [](const std::string& v) { return v == "inf" ? HUGE_VAL : std::stod(v); };
    for (std::size_t i = 0; i + 1 < words.size(); i += 2) {
        const std::string& k = words[i];
        const std::string& v = words[i + 1];
        const auto [name, value] = split(v, '=');
        if (k == "--size") {
            const auto [x, y] = split(v, 'x');
            for (std::size_t a = 0; a < s.axes.size(); ++a) s.axes[a].count = std::stoi(a == 0 || v.find('x') == std::string::npos ? x : y);
        } else if (k == "--range") {
            const auto [lo, hi] = split(value, ':');
            axis(name).min = number(lo);
            axis(name).max = number(hi);
        } else if (k == "--placement") {
            axis(name).placement = placement_from_string(value);
        } else if (k == "--warp") {
            axis(name).warp = warp_from_string(value);
        } else if (k == "--order") {
            const auto [first, second] = split(v, ',');
            if (s.axes[0].name != first) std::swap(s.axes[0], s.axes[1]);
        } else if (k == "--flip") {
            axis(v).flip = true;
        } else if (k == "--clamp") {
            const auto [lo, hi] = split(value, ':');
            axis(name).clamp_lo = number(lo);
            axis(name).clamp_hi = number(hi);
        } else if (k == "--shift") {
            axis(name).shift = std::stod(value);
        } else if (k == "--channels") {
            s.channel_map = parse_channel_map(v, static_cast<int>(def.channels.size()));
        } else {
            s.params[k.substr(2)] = v;
        }
    }
    return generate(def, s);
}

bool has_finding(const Explanation& e, const std::string& words) {
    return std::any_of(e.findings.begin(), e.findings.end(),
                       [&](const std::string& f) { return f.find(words) != std::string::npos; });
}

std::string findings_of(const Explanation& e) {
    std::string s = e.description.def->id + " " + e.compare_arguments + "\n";
    for (const auto& f : e.findings) s += "  " + f + "\n";
    return s;
}

struct Case {
    std::string id, args;
    std::set<std::string> tables;  // acceptable ids: the table, or one with identical values
    std::string finding;           // words the first explanation must state ("" : none required)
};

// Checks that identify puts a description reproducing the image first (its
// figures are compare_values' over every texel) and returns it.
Explanation identified_first(const ExrImage& img, const Case& c) {
    const IdentifyReport rep = identify(img, {1, 0});
    EXPECT_EQ(rep.explanations.size(), 1u);
    if (rep.explanations.empty()) return {};
    const Explanation& e = rep.explanations.front();
    EXPECT_TRUE(c.tables.count(e.description.def->id)) << c.id << " " << c.args << " -> " << findings_of(e);
    EXPECT_TRUE(e.pass) << findings_of(e) << e.max_error;
    EXPECT_LT(e.max_error, 1e-6) << findings_of(e);
    if (!c.finding.empty()) {
        EXPECT_TRUE(has_finding(e, c.finding)) << c.finding << "\n" << findings_of(e);
    }
    return e;
}

}  // namespace

TEST(Identify, EveryConventionOfTheVocabularyIsFoundFirstAndNamed) {
    const std::set<std::string> split_sum{"ggx_dfg", "gltf_ggx", "godot_mobile_dfg", "bevy_dfg"};
    const std::vector<Case> cases = {
        // The default layout, and each field of the vocabulary on its own.
        {"ggx_dfg", "--size 16", split_sum, ""},
        {"ggx_albedo", "--size 16 --warp alpha=linear", {"ggx_albedo"}, "linear in alpha where the table is indexed by roughness"},
        {"fresnel_dielectric", "--size 16 --warp eta=ior_z", {"fresnel_dielectric"}, "warp ior_z"},
        {"fresnel_dielectric", "--size 16 --warp eta=sqrt", {"fresnel_dielectric"}, "warp sqrt"},
        {"dipole_profile", "--size 16", {"dipole_profile"}, ""},
        {"ggx_dfg", "--size 16 --range cos_theta=1:0 --warp cos_theta=square --placement cos_theta=endpoints",
         split_sum, "uniform in sqrt(1 - cos_theta)"},
        {"ggx_albedo", "--size 16 --flip alpha", {"ggx_albedo"}, "rows are flipped"},
        {"ggx_albedo", "--size 16 --order alpha,cos_theta", {"ggx_albedo"}, "axes transposed"},
        {"ggx_albedo", "--size 16 --placement alpha=endpoints", {"ggx_albedo"}, "cell centres described as end points"},
        {"cycles_ggx_e", "--size 16 --placement cos_theta=center", {"cycles_ggx_e"}, "end points described as cell centres"},
        {"ggx_albedo", "--size 16 --placement cos_theta=endpoints --clamp cos_theta=1e-3:1", {"ggx_albedo"},
         "cos_theta clamped to [0.001"},
        {"ggx_dfg", "--size 16 --channels R=R+G,G=G", split_sum, "R holds R + G"},
        {"ggx_albedo", "--size 16 --shift alpha=1 --clamp alpha=0:1", {"ggx_albedo"}, "(j + 1.5)/h: one texel high"},
        {"ggx_albedo", "--size 16 --shift cos_theta=-0.5 --clamp cos_theta=0:1", {"ggx_albedo"}, "half a texel low"},
        {"ggx_albedo", "--size 16 --visibility separable", {"ggx_albedo"}, "separable Smith G where height-correlated is usual"},
        {"ggx_albedo_avg", "--size 16 --flip alpha", {"ggx_albedo_avg"}, "texels are flipped"},
    };
    for (const Case& c : cases) identified_first(image_of(make(c.id, c.args)), c);
}

TEST(Identify, FilamentsOneTexelHighRowsAreNamedAsSuch) {
    // Filament's DFG rows hold r = (j + 1.5)/h, clamped at 1.
    identified_first(image_of(make("ggx_albedo", "--size 16x24 --shift alpha=1 --clamp alpha=0:1")),
                     {"ggx_albedo", "", {"ggx_albedo"}, "rows hold alpha at u = (j + 1.5)/h: one texel high"});
    const Explanation e = identified_first(
        image_of(make("filament_dfg", "--size 16 --shift roughness=1 --clamp roughness=0:1")),
        {"filament_dfg", "", {"filament_dfg"}, "rows hold roughness (j + 1.5)/h: one texel high"});
    EXPECT_NE(e.compare_arguments.find("--shift roughness=1 --clamp roughness=0:1"), std::string::npos) << e.compare_arguments;
}

TEST(Identify, ATableDecodedAsSrgbIsNamedAndComparePassesWithTransform) {
    Table t = make("ggx_dfg", "--size 16");
    apply_value_transform(t, ValueTransform::srgb);
    const Explanation e = identified_first(image_of(t), {"ggx_dfg", "", {"ggx_dfg", "gltf_ggx", "godot_mobile_dfg", "bevy_dfg"}, "values decoded as sRGB"});
    EXPECT_EQ(e.description.values, ValueTransform::srgb);
    EXPECT_NE(e.compare_arguments.find("--transform srgb"), std::string::npos);
    // Without the transform the same table is far off.
    const IdentifyReport linear = identify(image_of(make("ggx_dfg", "--size 16")), {1, 0});
    ASSERT_EQ(linear.explanations.size(), 1u);
    EXPECT_EQ(linear.explanations[0].description.values, ValueTransform::none);
}

TEST(Identify, PaddingChannelsAreNotComparedAndNamed) {
    const Table t = make("ggx_dfg", "--size 16");
    ExrImage img;
    img.width = img.height = 16;
    img.channel_names = {"R", "G", "B", "A"};
    for (std::size_t k = 0; k < t.texel_count(); ++k)
        for (double v : {t.at(k, 0), t.at(k, 1), 0.0, 1.0}) img.pixels.push_back(static_cast<float>(v));
    const IdentifyReport rep = identify(img, {1, 0});
    ASSERT_EQ(rep.explanations.size(), 1u);
    const Explanation& e = rep.explanations[0];
    EXPECT_TRUE(e.pass) << findings_of(e);
    EXPECT_EQ(e.padding, (std::vector<std::string>{"B = 0", "A = 1"}));
}

TEST(Identify, TheSameReportWhateverTheThreadCount) {
    const ExrImage img = image_of(make("ggx_albedo", "--size 16x12 --order alpha,cos_theta --flip cos_theta"));
    const IdentifyReport one = identify(img, {3, 1}), two = identify(img, {3, 2});
    ASSERT_EQ(one.explanations.size(), two.explanations.size());
    EXPECT_EQ(one.coarse_candidates, two.coarse_candidates);
    EXPECT_EQ(one.refined_candidates, two.refined_candidates);
    for (std::size_t i = 0; i < one.explanations.size(); ++i) {
        EXPECT_EQ(one.explanations[i].compare_arguments, two.explanations[i].compare_arguments);
        EXPECT_EQ(one.explanations[i].max_error, two.explanations[i].max_error);
        EXPECT_EQ(one.explanations[i].rms_error, two.explanations[i].rms_error);
    }
}

TEST(Identify, PrintedCompareCommandsPassOrFailAsIdentifySays) {
    // A transposed, flipped, separable table with a summed channel, written
    // as generate writes it; every printed command is run.
    TempDir dir;
    auto g = run_cli("generate ggx_dfg --size 16x12 -q -o '" + dir.path().string() +
                         "' --order alpha,cos_theta --flip cos_theta --channels R=R+G,G=G --visibility separable",
                     dir);
    ASSERT_EQ(g.exit_code, 0) << g.err;
    auto id = run_cli("identify '" + (dir / "ggx_dfg.exr") + "' --top 3 --json", dir);
    ASSERT_EQ(id.exit_code, 0) << id.err;
    const auto j = nlohmann::json::parse(id.out);
    const auto& list = j.at("explanations");
    ASSERT_EQ(list.size(), 3u);
    EXPECT_TRUE(list[0].at("pass").get<bool>());
    const std::string findings = list[0].at("findings").dump();
    EXPECT_NE(findings.find("axes transposed"), std::string::npos) << findings;
    EXPECT_NE(findings.find("rows are flipped"), std::string::npos) << findings;
    EXPECT_NE(findings.find("separable Smith G"), std::string::npos) << findings;
    for (const auto& e : list) {
        std::string cmd = e.at("compare").get<std::string>();
        ASSERT_EQ(cmd.rfind("brdflut compare ", 0), 0u) << cmd;
        auto r = run_cli(cmd.substr(8), dir);
        EXPECT_EQ(r.exit_code, e.at("pass").get<bool>() ? 0 : 1) << cmd << "\n" << r.out << r.err;
    }
    auto text = run_cli("identify '" + (dir / "ggx_dfg.exr") + "' --top 1", dir);
    EXPECT_EQ(text.exit_code, 0);
    EXPECT_NE(text.out.find("passes compare"), std::string::npos) << text.out;
    EXPECT_EQ(run_cli("identify '" + (dir / "ggx_dfg.exr") + "' --top 0", dir).exit_code, 2);
    EXPECT_EQ(run_cli("identify '" + (dir / "missing.exr") + "'", dir).exit_code, 1);
}

TEST(Identify, CyclesGgxEFromBlendersSourceIsItsPresetWithItsOwnClamps) {
    // tests/fixtures/cycles: table_ggx_E as Blender ships it (6 printed digits).
    TempDir dir;
    const std::string file = std::string("'") + BRDFLUT_SOURCE_DIR + "/tests/fixtures/cycles/shader.tables'";
    auto id = run_cli("identify " + file + " --array table_ggx_E --shape 32x32 --top 2 --json", dir);
    ASSERT_EQ(id.exit_code, 0) << id.err;
    const auto j = nlohmann::json::parse(id.out);
    const auto& best = j.at("explanations").at(0);
    EXPECT_EQ(best.at("table"), "cycles_ggx_e");
    EXPECT_LT(best.at("max_error").get<double>(), 1.5e-6);
    // The preset clamps mu to [1e-4, 1] as Cycles' generator does, so its
    // compare line needs no layout option.
    const std::string cmd = best.at("compare").get<std::string>();
    EXPECT_NE(cmd.find("--array table_ggx_E --shape 32x32 --as cycles_ggx_e"), std::string::npos) << cmd;
    EXPECT_EQ(cmd.find("--clamp"), std::string::npos) << cmd;
    // Its 6-digit values pass one unit of their last printed digit, and
    // compare says the same; unclamped, grazing rows are 2% off.
    EXPECT_TRUE(best.at("pass").get<bool>());
    EXPECT_EQ(run_cli(cmd.substr(8), dir).exit_code, 0);
    auto unclamped = run_cli("compare " + file +
                                 " --array table_ggx_E --shape 32x32 --as cycles_ggx_e --clamp cos_theta=0:1 --tolerance 1e-2",
                             dir);
    EXPECT_EQ(unclamped.exit_code, 1) << unclamped.out;
}

// A flat array: identify tries its 1-D reading and every factorization of
// its length, and with no shape given names Cycles' table in its 32x32
// layout; the compare line it prints passes.
TEST(Identify, CyclesFlatArrayWithNoShapeIsItsPreset) {
    TempDir dir;
    const std::string file = std::string("'") + BRDFLUT_SOURCE_DIR + "/tests/fixtures/cycles/shader.tables'";
    auto id = run_cli("identify " + file + " --array table_ggx_E --top 2 --json", dir);
    ASSERT_EQ(id.exit_code, 0) << id.err;
    const auto j = nlohmann::json::parse(id.out);
    const auto& best = j.at("explanations").at(0);
    EXPECT_EQ(best.at("table"), "cycles_ggx_e") << best.dump(2);
    EXPECT_EQ(best.at("flat_shape"), "32x32");
    EXPECT_LT(best.at("max_error").get<double>(), 1.5e-6);
    EXPECT_TRUE(best.at("pass").get<bool>());
    const std::string cmd = best.at("compare").get<std::string>();
    EXPECT_EQ(cmd.find("--size"), std::string::npos) << cmd;  // 32x32 is the preset's own
    EXPECT_EQ(run_cli(cmd.substr(8), dir).exit_code, 0) << cmd;
}

// compare --as on a flat array takes the shape from the table's layout.
TEST(Identify, CompareGivesAFlatArrayTheShapeOfTheTable) {
    TempDir dir;
    const std::string file = std::string("'") + BRDFLUT_SOURCE_DIR + "/tests/fixtures/cycles/shader.tables'";
    auto r = run_cli("compare " + file + " --array table_ggx_E --as cycles_ggx_e --clamp cos_theta=0.0001:inf --json", dir);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    // A layout whose texel count is not the array's length is refused, naming both.
    r = run_cli("compare " + file + " --array table_ggx_E --as cycles_ggx_e --size 16x16", dir);
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.err.find("flat array of 1024 numbers"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("16x16 texels"), std::string::npos) << r.err;
}

// The done condition of issue 33: Cycles' file as shipped, with no layout
// option, passes against cycles_ggx_e. It needs the preset to carry Cycles'
// clamp cos_theta >= 1e-4 (added with the presets' recipes).
TEST(Identify, CyclesFileAsShippedPassesCompareAgainstItsPreset) {
    TempDir dir;
    const std::string file = std::string("'") + BRDFLUT_SOURCE_DIR + "/tests/fixtures/cycles/shader.tables'";
    auto r = run_cli("compare " + file + " --array table_ggx_E --as cycles_ggx_e", dir);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

// Heitz's ltc_2 (three.js's copy): identify searches the LTC norm tables and
// names ltc_2 first, on its own axes in its own order (roughness columns,
// rows sqrt(1 - cos theta), end points, theta clamped to 1.57 inside the
// lobe), not cell-centred rows, and with no clamp of its own: Heitz's
// grazing n0 is about 6 % low, and a view-cosine clamp at the grid end trims
// the largest error from 6.55e-2 to 6.50e-2, too little to pay for an extra
// field of the description.
TEST(Identify, HeitzLtc2IsNamedAsHisLayout) {
    std::ifstream in(std::string(BRDFLUT_SOURCE_DIR) + "/tests/fixtures/ltc/three_ltc_2.txt");
    ExrImage img;
    img.width = 64;
    img.height = 64;
    img.channel_names = {"R", "G", "B", "A"};
    double x;
    while (in >> x) img.pixels.push_back(x);
    ASSERT_EQ(img.pixels.size(), 64u * 64u * 4u);
    const IdentifyReport rep = identify(img, {3, 0});
    ASSERT_FALSE(rep.explanations.empty());
    const Explanation& e = rep.explanations.front();
    EXPECT_EQ(e.description.def->id, "ltc_2") << findings_of(e);
    const TableSettings own = default_settings(find_table("ltc_2"));
    ASSERT_EQ(e.description.settings.axes.size(), own.axes.size());
    for (std::size_t a = 0; a < own.axes.size(); ++a) {
        const Axis& got = e.description.settings.axes[a];
        const Axis& want = own.axes[a];
        EXPECT_EQ(got.name, want.name);
        EXPECT_EQ(got.placement, Placement::endpoints);
        EXPECT_EQ(got.warp, want.warp);
        EXPECT_EQ(got.min, want.min);
        EXPECT_EQ(got.max, want.max);
        EXPECT_EQ(got.shift, 0.0);
        EXPECT_FALSE(got.flip);
        EXPECT_EQ(got.clamp_lo, want.clamp_lo) << got.name << findings_of(e);
        EXPECT_EQ(got.clamp_hi, want.clamp_hi) << got.name << findings_of(e);
    }
    EXPECT_EQ(e.cost, 0) << findings_of(e);
    const std::vector<std::vector<int>> own_channels{{0}, {1}, {2}, {3}};
    const auto& map = e.description.settings.channel_map;
    EXPECT_TRUE(map.empty() || map == own_channels) << findings_of(e);
}
