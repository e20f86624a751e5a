// The axis vocabulary: warps and their inverses, reversed ranges, flips,
// clamps, storage order and channel maps, in generate, compare and sample.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "brdflut/axis.h"
#include "brdflut/catalogue.h"
#include "brdflut/error.h"
#include "brdflut/exr.h"
#include "brdflut/formats.h"
#include "brdflut/generate.h"
#include "brdflut/lut.h"
#include "test_support.h"

using namespace brdflut;
using brdflut::test::run_cli;
using brdflut::test::TempDir;
using brdflut::test::image_of;

namespace {

Table make(const std::string& id, const TableSettings& s) { return generate(find_table(id), s); }

TableSettings small(const std::string& id, int n) {
    TableSettings s = default_settings(find_table(id));
    for (Axis& a : s.axes) a.count = n;
    s.quality = Quality::draft;
    return s;
}

}  // namespace

TEST(Warps, EveryEntryHasANameAFormulaAShaderInverseAndInvertsItsValue) {
    std::set<std::string> names;
    for (const WarpDef& w : warps()) {
        EXPECT_TRUE(names.insert(w.name).second) << w.name;
        EXPECT_EQ(warp_from_string(w.name), w.warp);
        EXPECT_NE(std::string(w.formula), "");
        EXPECT_NE(std::string(w.shader_u), "");
        // A range valid for every warp, both ways round; ior_split maps both
        // sides of n = 1, so its range must contain 1 (increasing only).
        const bool split = w.warp == Warp::ior_split;
        if (split) {
            EXPECT_NE(w.range_problem(1.5, 2.5), "");
        }
        const std::vector<std::pair<double, double>> ranges =
            split ? std::vector<std::pair<double, double>>{{0.4, 2.5}, {0.25, 1.5}}
                  : std::vector<std::pair<double, double>>{{1.5, 2.5}, {2.5, 1.5}};
        for (const auto& [lo, hi] : ranges) {
            ASSERT_EQ(w.range_problem(lo, hi), "") << w.name;
            for (double u = 0.0; u <= 1.0; u += 0.125) {
                const double v = w.value(u, lo, hi);
                EXPECT_NEAR(w.u_of_value(v, lo, hi), u, 1e-12) << w.name << " u = " << u;
            }
            EXPECT_NEAR(w.value(0.0, lo, hi), lo, 1e-12) << w.name;
            EXPECT_NEAR(w.value(1.0, lo, hi), hi, 1e-12) << w.name;
        }
    }
    EXPECT_THROW(warp_from_string("cubic"), Error);
}

TEST(Axis, ReversedSquareRangeIsUniformInSqrtOneMinusCosTheta) {
    // EEVEE's split sum and Heitz's LTC rows: u = sqrt(1 - mu) at end points.
    const Axis a{"cos_theta", 1.0, 0.0, 64, Placement::endpoints, Warp::square};
    a.validate();
    for (int i = 0; i < 64; ++i) {
        const double u = i / 63.0;
        EXPECT_NEAR(a.value(i), 1.0 - u * u, 1e-15) << i;
        EXPECT_NEAR(a.position_of_value(a.value(i)), i, 1e-9) << i;
    }
    EXPECT_EQ(a.value(0), 1.0);
    EXPECT_EQ(a.value(63), 0.0);
    EXPECT_EQ(a.lowest(), 0.0);
    EXPECT_EQ(a.highest(), 1.0);
}

TEST(Axis, IorZIsCyclesIndexOfRefractionAxisWithItsClamp) {
    // Cycles: z = i/15 at end points, clamped to [1e-4, 0.99], n = (1 + z^2)/(1 - z^2).
    Axis a{"eta", 1.0, HUGE_VAL, 16, Placement::endpoints, Warp::ior_z};
    EXPECT_THROW(a.validate(), Error);  // n = inf at z = 1 needs a clamp
    auto n_of = [](double z) { return (1 + z * z) / (1 - z * z); };
    a.clamp_lo = n_of(1e-4);
    a.clamp_hi = n_of(0.99);
    a.validate();
    for (int i = 0; i < 16; ++i) {
        const double z = std::clamp(i / 15.0, 1e-4, 0.99);
        EXPECT_NEAR(a.value(i), n_of(z), 1e-12 * n_of(z)) << i;
    }
    EXPECT_NEAR(a.highest(), 99.50251256, 1e-6);
    EXPECT_NEAR(a.position_of_value(n_of(0.5)), 7.5, 1e-9);
}

TEST(Axis, SplitEndpointsWithIorSplitIsAdobesOpenPbrIndexAxis) {
    // Adobe's exact index of n (openpbr_ior_to_exact_index, table size N =
    // 32): below 1, 15 - 15 (1/n - 1)/1.5; from 1, 16 + 15 (n - 1)/1.5.
    auto adobe_index = [](double n) { return n < 1.0 ? 15.0 - 15.0 * (1.0 / n - 1.0) / 1.5 : 16.0 + 15.0 * (n - 1.0) / 1.5; };
    const Axis a{"ior", 0.4, 2.5, 32, Placement::split_endpoints, Warp::ior_split};
    a.validate();
    for (int i = 0; i < 32; ++i) {
        const double n = i < 16 ? 1.0 / (1.0 + 1.5 * (15 - i) / 15.0) : 1.0 + 1.5 * (i - 16) / 15.0;
        EXPECT_NEAR(a.value(i), n, 1e-15) << i;
        EXPECT_NEAR(a.position_of_value(n), i == 15 ? 16.0 : i, 1e-12) << i;  // n = 1 reads the upper half
    }
    for (double n : {0.4, 0.45, 0.8, 0.999, 1.0, 1.001, 1.7, 2.5})
        EXPECT_NEAR(a.position_of_value(n), adobe_index(n), 1e-12) << n;
    EXPECT_EQ(a.lowest(), 0.4);
    EXPECT_EQ(a.highest(), 2.5);
    EXPECT_EQ(placement_from_string("split_endpoints"), Placement::split_endpoints);
    EXPECT_EQ(to_string(Placement::split_endpoints), "split_endpoints");

    // Odd counts give the upper half the extra texel; a half of one texel
    // holds its outer end. The placement needs a count of at least 2, no
    // shift, and the warp a range around 1; the errors name the value and
    // what is allowed.
    auto problem = [](Axis b) {
        try {
            b.validate();
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    Axis odd = a;
    odd.count = 5;  // 0.4, 1 | 1, 1.75, 2.5
    odd.validate();
    EXPECT_NEAR(odd.value(0), 0.4, 1e-15);
    EXPECT_NEAR(odd.value(1), 1.0, 1e-15);
    EXPECT_NEAR(odd.value(2), 1.0, 1e-15);
    EXPECT_NEAR(odd.value(3), 1.75, 1e-15);
    EXPECT_NEAR(odd.position_of_value(1.375), 2.5, 1e-12);
    Axis two = a;
    two.count = 2;  // the two ends
    two.validate();
    EXPECT_EQ(two.value(0), 0.4);
    EXPECT_EQ(two.value(1), 2.5);
    Axis one = a;
    one.count = 1;
    EXPECT_NE(problem(one).find("needs a count of at least 2 (got 1)"), std::string::npos) << problem(one);
    Axis shifted = a;
    shifted.shift = 1.0;
    EXPECT_NE(problem(shifted).find("takes no shift"), std::string::npos);
    Axis above = a;
    above.min = 1.5;
    EXPECT_NE(problem(above).find("needs 0 < min < 1 < max (got 1.5:2.5)"), std::string::npos) << problem(above);
}

TEST(Axis, FlipReversesTheStoragePositionsAndClampsHoldTheParameter) {
    Axis a{"alpha", 0.0, 1.0, 8, Placement::center, Warp::square};
    Axis f = a;
    f.flip = true;
    for (int i = 0; i < 8; ++i) {
        EXPECT_EQ(f.value(i), a.value(7 - i));
        EXPECT_NEAR(f.position_of_value(a.value(i)), 7 - i, 1e-9);
    }
    Axis c = a;
    c.clamp_lo = 0.01;
    EXPECT_EQ(c.value(0), 0.01);  // 1/256 clamped up
    EXPECT_EQ(c.value(7), a.value(7));
    EXPECT_EQ(c.position_of_value(0.0), c.position_of_value(0.01));
    c.clamp_hi = 0.001;
    EXPECT_THROW(c.validate(), Error);
}

TEST(Layout, TransposedTableHoldsTheSameValuesWithAxesSwapped) {
    const TableSettings s = small("ggx_albedo", 6);
    TableSettings t = s;
    std::swap(t.axes[0], t.axes[1]);
    t.axes[0].count = 5;  // rows of alpha, 5 columns: catches a mix-up of the strides
    TableSettings s5 = s;
    s5.axes[1].count = 5;
    const Table a = make("ggx_albedo", s5), b = make("ggx_albedo", t);
    ASSERT_EQ(b.width(), 5);
    ASSERT_EQ(b.height(), 6);
    EXPECT_EQ(b.axes[0].name, "alpha");
    for (int mu = 0; mu < 6; ++mu)
        for (int al = 0; al < 5; ++al) EXPECT_EQ(b.values[static_cast<std::size_t>(mu * 5 + al)], a.values[static_cast<std::size_t>(al * 6 + mu)]);
    TableSettings bad = s;
    bad.axes[1].name = "cos_theta";
    EXPECT_THROW(validate_settings(find_table("ggx_albedo"), bad), Error);
}

TEST(Layout, ChannelMapStoresSumsOfTableChannels) {
    TableSettings s = small("ggx_dfg", 6);
    s.channel_map = {{0, 1}};  // A + B = E
    const Table sum = make("ggx_dfg", s);
    const Table e = make("ggx_albedo", small("ggx_albedo", 6));
    ASSERT_EQ(sum.channel_count(), 1);
    for (std::size_t k = 0; k < sum.values.size(); ++k) EXPECT_NEAR(sum.values[k], e.values[k], 1e-9);
    s.channel_map = {{2}};
    EXPECT_THROW(validate_settings(find_table("ggx_dfg"), s), Error);
}

TEST(Layout, MetadataCarriesTheWholeLayoutAndCompareReadsItBack) {
    TempDir dir;
    TableSettings s = small("ggx_dfg", 8);
    std::swap(s.axes[0], s.axes[1]);
    s.axes[0].flip = true;
    s.axes[1].min = 1.0;
    s.axes[1].max = 0.0;
    s.axes[1].placement = Placement::endpoints;
    s.axes[1].clamp_lo = 1e-4;
    s.channel_map = {{1}, {0, 1}};
    const Table t = make("ggx_dfg", s);
    write_exr(dir / "t.exr", t, PixelType::float32);
    const ExrImage img = read_exr(dir / "t.exr");
    const LutDescription d = describe_from_metadata(img, dir / "t.exr");
    ASSERT_EQ(d.settings.axes.size(), 2u);
    EXPECT_EQ(d.settings.axes[0].name, "alpha");
    EXPECT_TRUE(d.settings.axes[0].flip);
    EXPECT_EQ(d.settings.axes[1].min, 1.0);
    EXPECT_EQ(d.settings.axes[1].clamp_lo, 1e-4);
    EXPECT_EQ(d.settings.channel_map, s.channel_map);
    const CompareReport rep = compare_lut(img, d, 0, 3, default_tolerance(img));
    EXPECT_TRUE(rep.pass()) << rep.channels[0].max_abs;
    // Without the flip the same file fails.
    LutDescription wrong = d;
    wrong.settings.axes[0].flip = false;
    EXPECT_FALSE(compare_lut(img, wrong, 0, 3, default_tolerance(img)).pass());
}

TEST(Sample, TrilinearOverStackedSlicesMatchesALinearFunctionExactly) {
    // A 3-D table of v = x + 10 y + 100 z (storage positions) samples to the
    // same linear function between texels, and clamps to the edges.
    LutDescription d;
    d.def = &find_table("ggx_dfg");
    d.settings.axes = {Axis{"a", 0.0, 1.0, 4, Placement::center, Warp::linear},
                       Axis{"b", 0.0, 1.0, 3, Placement::endpoints, Warp::linear},
                       Axis{"c", 0.0, 1.0, 5, Placement::center, Warp::square}};
    ExrImage img;
    img.width = 4;
    img.height = 15;
    img.channel_names = {"R"};
    for (int z = 0; z < 5; ++z)
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 4; ++x) img.pixels.push_back(x + 10.0 * y + 100.0 * z);
    const auto& ax = d.settings.axes;
    for (double pa : {0.2, 0.5, 0.81})
        for (double pb : {0.0, 0.3, 0.77})
            for (double pc : {0.15, 0.4, 0.66}) {
                const double want = ax[0].position_of_value(pa) + 10 * ax[1].position_of_value(pb) +
                                    100 * ax[2].position_of_value(pc);
                EXPECT_NEAR(sample_lut(img, d, {pa, pb, pc}, 0), want, 1e-9);
            }
    EXPECT_NEAR(sample_lut(img, d, {0.0, 0.0, 0.0}, 0), 0.0, 1e-12);   // clamped to texel 0
    EXPECT_NEAR(sample_lut(img, d, {1.0, 1.0, 1.0}, 0), 423.0, 1e-12);  // the last texel
}

TEST(Compare, VerdictFailsAShiftedTableAndPassesTheRightDescription) {
    // rows one texel high, as a mis-indexed generator writes them
    TableSettings s = small("ggx_albedo", 16);
    const Table exact = make("ggx_albedo", s);
    Table shifted = exact;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            shifted.values[static_cast<std::size_t>(y * 16 + x)] = exact.values[static_cast<std::size_t>(std::min(y + 1, 15) * 16 + x)];
    const ExrImage good = image_of(exact), bad = image_of(shifted);
    const Tolerance storage = default_tolerance(good);
    EXPECT_EQ(storage.steps, 1.0);
    EXPECT_TRUE(compare_values(good, exact, 3, storage).pass());
    const CompareReport rep = compare_values(bad, exact, 3, storage);
    EXPECT_FALSE(rep.pass());
    EXPECT_GE(rep.failed_values, 14u * 16u);  // (nearly) every row but the last, which repeats
    EXPECT_LE(rep.failed_values, 15u * 16u);
    // A loose enough tolerance, absolute or relative, accepts it.
    EXPECT_TRUE(compare_values(bad, exact, 3, parse_tolerance("0.2")).pass());
    EXPECT_TRUE(compare_values(bad, exact, 3, parse_tolerance("50%")).pass());
    EXPECT_FALSE(compare_values(bad, exact, 3, parse_tolerance("0.1%")).pass());
    EXPECT_THROW(parse_tolerance("-1"), Error);
    EXPECT_THROW(parse_tolerance("abc%"), Error);
}

TEST(Compare, ExitStatusAndJsonCarryTheVerdict) {
    TempDir dir;
    ASSERT_EQ(run_cli("generate ggx_albedo --size 16 --quality draft -q -o '" + dir.path().string() + "'", dir).exit_code, 0);
    const std::string file = dir / "ggx_albedo.exr";
    auto ok = run_cli("compare '" + file + "' --json", dir);
    EXPECT_EQ(ok.exit_code, 0) << ok.err;
    const auto j = nlohmann::json::parse(ok.out);
    EXPECT_TRUE(j.at("verdict").at("pass").get<bool>());
    EXPECT_EQ(j.at("verdict").at("tolerance").at("source"), "the file's error_bound");
    // The same file described as cell centres shifted: it fails, exit 1.
    auto bad = run_cli("compare '" + file + "' --as ggx_albedo --placement alpha=endpoints", dir);
    EXPECT_EQ(bad.exit_code, 1) << bad.err;
    EXPECT_NE(bad.out.find("FAIL: "), std::string::npos) << bad.out;
    auto loose = run_cli("compare '" + file + "' --as ggx_albedo --placement alpha=endpoints --tolerance 0.5", dir);
    EXPECT_EQ(loose.exit_code, 0) << loose.err;
    EXPECT_NE(loose.out.find("PASS: "), std::string::npos) << loose.out;
    auto usage = run_cli("compare '" + file + "' --tolerance 1e-3x", dir);
    EXPECT_EQ(usage.exit_code, 2);
    EXPECT_NE(usage.err.find("--tolerance '1e-3x'"), std::string::npos) << usage.err;
}

TEST(Generate, WritesAnyDescribedLayoutThatCompareThenAccepts) {
    TempDir dir;
    const std::string layout =
        " --size 12 --order alpha,cos_theta --range cos_theta=1:0 --warp cos_theta=square --placement cos_theta=endpoints"
        " --clamp cos_theta=1e-4:1 --flip alpha --channels R=R+G";
    auto g = run_cli("generate ggx_dfg -q --quality draft -o '" + dir.path().string() + "'" + layout, dir);
    ASSERT_EQ(g.exit_code, 0) << g.err;
    const std::string file = dir / "ggx_dfg.exr";
    auto from_metadata = run_cli("compare '" + file + "'", dir);
    EXPECT_EQ(from_metadata.exit_code, 0) << from_metadata.out << from_metadata.err;
    // Described on the command line the same way, also a pass; a different
    // description of the same file fails.
    auto same = run_cli("compare '" + file + "' --as ggx_dfg --tolerance 1e-5" + layout, dir);
    EXPECT_EQ(same.exit_code, 0) << same.out << same.err;
    auto unflipped = run_cli("compare '" + file + "' --as ggx_dfg --tolerance 1e-5" +
                                 std::string(" --order alpha,cos_theta --range cos_theta=1:0 --warp cos_theta=square") +
                                 " --placement cos_theta=endpoints --clamp cos_theta=1e-4:1 --channels R=R+G",
                             dir);
    EXPECT_EQ(unflipped.exit_code, 1) << unflipped.out << unflipped.err;
}

TEST(Axis, ShiftMisplacesTheGridByTexelsAsFilamentsRowsAre) {
    // Filament's rows hold r = (j + 1.5)/h, the last clamped to r = 1.
    Axis a{"roughness", 0.0, 1.0, 8, Placement::center, Warp::linear};
    a.shift = 1.0;
    a.clamp_hi = 1.0;
    a.validate();
    for (int j = 0; j < 7; ++j) {
        EXPECT_DOUBLE_EQ(a.value(j), (j + 1.5) / 8) << j;
        EXPECT_NEAR(a.position_of_value(a.value(j)), j, 1e-12) << j;
    }
    EXPECT_EQ(a.value(7), 1.0);
    Axis wild = a;
    wild.shift = 3.0;
    EXPECT_THROW(wild.validate(), Error);
    Axis root{"alpha", 0.0, 1.0, 8, Placement::endpoints, Warp::sqrt};
    root.shift = -1.0;  // u = -1/7 at the first texel: sqrt of a negative
    EXPECT_THROW(root.validate(), Error);
}

TEST(Compare, ASourceArrayIsHeldToItsPrintedDigitsAndCyclesGgxEPassesInItsLayout) {
    TempDir dir;
    {
        std::ofstream f(dir / "t.c");
        f << "const float t[3] = {0.5000f, 0.2500, 1.0000};\n";
        f << "const float u[3] = {0.5f, 0.25, 1.0};\n";
        f << "const float w[3] = {0.5000f, 0.2500, 1.5e-3};\n";
    }
    ReadOptions o;
    o.array = "t";
    const ExrImage img = read_table_image(dir / "t.c", o);
    EXPECT_DOUBLE_EQ(img.printed_step, 1e-4);
    EXPECT_DOUBLE_EQ(storage_step(img, 0.5), 1e-4);
    o.array = "u";  // shortest digits: the values are taken as floats
    EXPECT_EQ(read_table_image(dir / "t.c", o).printed_step, 0.0);
    o.array = "w";
    EXPECT_EQ(read_table_image(dir / "t.c", o).printed_step, 0.0);
    // Cycles' ggx_E, printed with 6 decimals, read in Cycles' layout: within
    // one unit of its last digit everywhere; without the clamp of mu it fails.
    const std::string cycles = std::string(BRDFLUT_SOURCE_DIR) + "/tests/fixtures/cycles/shader.tables";
    const std::string layout = " --array table_ggx_E --shape 32x32 --as ggx_albedo --order alpha,cos_theta"
                               " --placement alpha=endpoints --placement cos_theta=endpoints";
    auto pass = run_cli("compare '" + cycles + "'" + layout + " --clamp cos_theta=1e-4:1 --json", dir);
    EXPECT_EQ(pass.exit_code, 0) << pass.out << pass.err;
    auto fail = run_cli("compare '" + cycles + "'" + layout, dir);
    EXPECT_EQ(fail.exit_code, 1) << fail.out << fail.err;
}
