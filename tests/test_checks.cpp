// The checking tools: verify rows, LUT comparison, sampling, and input that
// is not what we expect.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>

#include "brdflut/catalogue.h"
#include "brdflut/error.h"
#include "brdflut/exr.h"
#include "brdflut/furnace.h"
#include "brdflut/generate.h"
#include "brdflut/lut.h"
#include "brdflut/verify.h"
#include "test_support.h"

using namespace brdflut;
using brdflut::test::run_cli;
using brdflut::test::TempDir;

namespace {
Table small_table(const std::string& id, int n, Placement p = Placement::center) {
    TableSettings s = default_settings(find_table(id));
    for (Axis& a : s.axes) {
        a.count = n;
        a.placement = p;
    }
    return generate(find_table(id), s);
}
}  // namespace

TEST(Verify, EveryClosedFormAndMonteCarloCheckOfTheCataloguePasses) {
    for (const TableDefinition& d : catalogue()) {
        const std::vector<CheckRow> rows = verify_table(d);
        for (const CheckRow& r : rows)
            EXPECT_TRUE(r.pass) << r.table << ": " << r.check << ": error " << r.max_error << " > " << r.tolerance
                                << " " << r.where;
    }
}

TEST(Verify, TexelSpreadIncludesTheGridCorners) {
    const auto texels = verify_texels(find_table("ggx_dfg"));
    EXPECT_EQ(texels.size(), 9u);
    bool grazing_smallest = false, normal_roughest = false;
    for (const auto& t : texels) {
        grazing_smallest = grazing_smallest || (t[0] == 0 && t[1] == 0);
        normal_roughest = normal_roughest || (t[0] == 127 && t[1] == 127);
    }
    EXPECT_TRUE(grazing_smallest);
    EXPECT_TRUE(normal_roughest);
}

TEST(Verify, EveryTableHasAnIndependentCheckThatAWrongTableFails) {
    // A table whose every channel is 0.5 everywhere: each table of the
    // catalogue has at least one check of its own (not Monte Carlo, which
    // verify adds for the tables that have it), and one of them fails it.
    class Wrong final : public TexelEvaluator {
        TexelValue evaluate(const double*, std::uint64_t) const override {
            TexelValue v;
            v.value = {0.5, 0.5, 0.5, 0.5};
            return v;
        }
    } wrong;
    for (const TableDefinition& d : catalogue()) {
        ASSERT_FALSE(d.checks.empty()) << d.id << " has no check of its own";
        EXPECT_EQ(&closed_form_checks(d.id), &d.checks) << d.id;
        bool caught = false;
        for (const ClosedFormCheck& c : d.checks) {  // until one fails it
            const auto [err, where] = c.run(wrong);
            caught = !(err <= c.tolerance);
            if (caught) break;
        }
        EXPECT_TRUE(caught) << d.id << ": no check fails a table of 0.5 everywhere";
    }
}

TEST(Catalogue, IdsAreUniqueAndPresetsAndFurnaceModelsNameItsTables) {
    std::set<std::string> ids;
    for (const TableDefinition& d : catalogue()) {
        EXPECT_TRUE(ids.insert(d.id).second) << "duplicate id " << d.id;
        if (!d.preset.empty()) {
            EXPECT_NO_THROW(find_preset(d.preset)) << d.id;
        }
    }
    for (const Preset& p : presets()) EXPECT_FALSE(preset_tables(p.name).empty()) << p.name;
    std::set<std::string> models;
    for (const FurnaceModel& m : furnace_models()) {
        EXPECT_TRUE(models.insert(m.id).second) << "duplicate furnace model " << m.id;
        ASSERT_TRUE(ids.count(m.albedo_table)) << m.id << ": " << m.albedo_table;
        EXPECT_LT(m.channel, static_cast<int>(find_table(m.albedo_table).channels.size())) << m.id;
        if (!m.average_table.empty()) {
            EXPECT_TRUE(ids.count(m.average_table)) << m.id << ": " << m.average_table;
        }
    }
    EXPECT_THROW(closed_form_checks("no_such_table"), Error);
}

TEST(Compare, ABrdflutFileMatchesWithinItsErrorBound) {
    TempDir dir;
    const Table t = small_table("ggx_dfg", 16);
    write_exr(dir / "t.exr", t, PixelType::float32);
    const ExrImage img = read_exr(dir / "t.exr");
    const LutDescription d = describe_from_metadata(img, dir / "t.exr");
    const CompareReport rep = compare_lut(img, d, 0, 5, default_tolerance(img));
    EXPECT_TRUE(rep.pass());
    EXPECT_EQ(rep.failed_values, 0u);
    ASSERT_EQ(rep.channels.size(), 2u);
    const double bound = img.metadata.at("error_bound").get<double>();
    for (const auto& c : rep.channels) {
        EXPECT_LE(c.max_abs, bound) << c.channel;
        EXPECT_LE(c.rms, c.max_abs);
    }
    ASSERT_EQ(rep.worst.size(), 5u);
    EXPECT_GE(std::abs(rep.worst[0].error), std::abs(rep.worst[4].error));
}

TEST(Compare, CatchesAnAxisShiftedByHalfATexelAndAFlippedAxis) {
    TempDir dir;
    // Written with end-point placement, described as cell centres.
    const Table t = small_table("ggx_albedo", 16, Placement::endpoints);
    write_exr(dir / "t.exr", t, PixelType::float32);
    const ExrImage img = read_exr(dir / "t.exr");
    LutDescription d;
    d.def = &find_table("ggx_albedo");
    d.settings = default_settings(*d.def);
    for (Axis& a : d.settings.axes) a.count = 16;
    const Tolerance tol = parse_tolerance("1e-6");
    const CompareReport shifted = compare_lut(img, d, 0, 1, tol);
    EXPECT_GT(shifted.channels[0].max_abs, 1e-3);
    EXPECT_FALSE(shifted.pass());
    // Described correctly it matches; flipped it does not.
    for (Axis& a : d.settings.axes) a.placement = Placement::endpoints;
    const CompareReport right = compare_lut(img, d, 0, 1, tol);
    EXPECT_LT(right.channels[0].max_abs, 1e-6);
    EXPECT_TRUE(right.pass());
    d.settings.axes[1].flip = true;
    const CompareReport flipped = compare_lut(img, d, 0, 1, tol);
    EXPECT_GT(flipped.channels[0].max_abs, 1e-2);
    EXPECT_FALSE(flipped.pass());
    EXPECT_GT(flipped.failed_values, 100u);
}

TEST(Compare, ChannelMapSumsTableChannels) {
    EXPECT_EQ(parse_channel_map("R=G,G=R+G", 2), (std::vector<std::vector<int>>{{1}, {0, 1}}));
    EXPECT_THROW(parse_channel_map("R=B", 2), Error);
    EXPECT_THROW(parse_channel_map("G=R", 2), Error);
    EXPECT_THROW(parse_channel_map("R=", 2), Error);
}

TEST(Sample, BilinearLikeAGpuWithClampToEdge) {
    TempDir dir;
    const Table t = small_table("ggx_dfg", 8);
    write_exr(dir / "t.exr", t, PixelType::float32);
    const ExrImage img = read_exr(dir / "t.exr");
    const LutDescription d = describe_from_metadata(img, dir / "t.exr");
    const Axis &x = t.axes[0], &y = t.axes[1];
    auto stored = [&](int i, int j, int c) { return img.pixels[(static_cast<std::size_t>(j) * 8 + static_cast<std::size_t>(i)) * 2 + static_cast<std::size_t>(c)]; };
    // At a texel's parameters: exactly the stored value.
    EXPECT_DOUBLE_EQ(sample_lut(img, d, {x.value(3), y.value(5)}, 0), stored(3, 5, 0));
    // Halfway (in u) between two texels along x: their mean.
    const double u = 0.5 * (x.u(3) + x.u(4));
    EXPECT_NEAR(sample_lut(img, d, {x.value_at_u(u), y.value(5)}, 1), 0.5 * (stored(3, 5, 1) + stored(4, 5, 1)), 1e-7);
    // Beyond the edge: clamped to the edge texel.
    EXPECT_DOUBLE_EQ(sample_lut(img, d, {0.0, 1.0}, 0), stored(0, 7, 0));
}

TEST(CliChecks, SampleNotesOnlyPointsOutsideADecreasingAxis) {
    // EEVEE's rows run from cos_theta = 1 down to 0 (min > max).
    TempDir dir;
    ASSERT_EQ(run_cli("generate eevee_brdf_ggx --size 8 -o .", dir).exit_code, 0);
    const auto inside = run_cli("sample eevee_brdf_ggx.exr --at roughness=0.5,cos_theta=0.5", dir);
    EXPECT_EQ(inside.exit_code, 0) << inside.err;
    EXPECT_EQ(inside.err.find("outside the table's range"), std::string::npos) << inside.err;
    const auto outside = run_cli("sample eevee_brdf_ggx.exr --at roughness=0.5,cos_theta=1.5", dir);
    EXPECT_EQ(outside.exit_code, 0) << outside.err;
    EXPECT_NE(outside.err.find("cos_theta = 1.5 is outside the table's range [1, 0]"), std::string::npos) << outside.err;
}

TEST(CliChecks, VerifyPrintsOneRowPerCheckAndJson) {
    TempDir dir;
    const auto r = run_cli("verify fresnel_dielectric_avg dipole_total", dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("F_avg(eta) vs the exact closed form"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("pass"), std::string::npos);
    const auto j = run_cli("verify ggx_albedo --json", dir);
    EXPECT_EQ(j.exit_code, 0) << j.err;
    const auto json = nlohmann::json::parse(j.out);
    EXPECT_TRUE(json.at("pass").get<bool>());
    EXPECT_GE(json.at("checks").size(), 3u);
}

TEST(CliChecks, CompareInspectAndSampleAGeneratedFile) {
    TempDir dir;
    ASSERT_EQ(run_cli("generate ggx_dfg ggx_albedo --size 16 -q -o '" + dir.path().string() + "'", dir).exit_code, 0);
    const std::string f = "'" + (dir / "ggx_dfg.exr") + "'";
    const auto c = run_cli("compare " + f + " --worst 3", dir);
    EXPECT_EQ(c.exit_code, 0) << c.err;
    EXPECT_NE(c.out.find("described by its metadata"), std::string::npos) << c.out;
    EXPECT_NE(c.out.find("worst texels"), std::string::npos) << c.out;
    const auto plotted = run_cli("compare " + f + " --plot '" + (dir / "err.png") + "'", dir);
    EXPECT_EQ(plotted.exit_code, 0) << plotted.err;
    EXPECT_EQ(test::read_file(dir / "err.png").substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    const auto i = run_cli("inspect " + f, dir);
    EXPECT_EQ(i.exit_code, 0) << i.err;
    EXPECT_NE(i.out.find("\"table\": \"ggx_dfg\""), std::string::npos) << i.out;
    const auto s = run_cli("sample " + f + " --at cos_theta=0.5,alpha=0.1", dir);
    EXPECT_EQ(s.exit_code, 0) << s.err;
    EXPECT_EQ(s.out.rfind("R = ", 0), 0u) << s.out;
    // The albedo file read as a split-sum table whose R holds A + B.
    const auto foreign = run_cli("compare '" + (dir / "ggx_albedo.exr") + "' --as ggx_dfg --channels R=R+G --json", dir);
    EXPECT_EQ(foreign.exit_code, 0) << foreign.err;
    const auto fj = nlohmann::json::parse(foreign.out);
    EXPECT_EQ(fj.at("described_by"), "command line");
    EXPECT_LT(fj.at("channels").at(0).at("max_abs_error").get<double>(), 1e-7);
    // Read with the channels swapped, the split-sum file is far off.
    const auto swapped = run_cli("compare " + f + " --as ggx_dfg --channels R=G,G=R --json", dir);
    EXPECT_GT(nlohmann::json::parse(swapped.out).at("channels").at(0).at("max_abs_error").get<double>(), 0.1);
}

TEST(CliChecks, InputThatIsNotWhatWeExpectGivesAOneLineErrorNeverACrash) {
    TempDir dir;
    ASSERT_EQ(run_cli("generate ggx_albedo --size 16 -q -o '" + dir.path().string() + "'", dir).exit_code, 0);
    const std::string good = test::read_file(dir / "ggx_albedo.exr");
    auto write = [&](const std::string& name, const std::string& bytes) {
        const std::string path = dir / name;
        std::ofstream(path, std::ios::binary) << bytes;
        std::string quoted = "'";
        quoted += path;
        quoted += "'";
        return quoted;
    };
    std::string flipped = good;
    for (std::size_t i = flipped.size() / 2; i < flipped.size(); i += 7) flipped[i] = static_cast<char>(~flipped[i]);
    std::string header_damaged = good;
    for (std::size_t i = 8; i < 64 && i < header_damaged.size(); ++i) header_damaged[i] = 'x';
    const std::string cases[] = {
        "'" + (dir / "missing.exr") + "'",
        write("empty.exr", ""),
        write("text.exr", "not an image at all"),
        write("truncated.exr", good.substr(0, good.size() / 2)),
        write("flipped.exr", flipped),
        write("header.exr", header_damaged),
    };
    for (const std::string& f : cases)
        for (const std::string cmd : {"compare ", "inspect ", "sample "}) {
            const std::string extra = cmd == "sample " ? " --at cos_theta=0.5,alpha=0.5" : "";
            const auto r = run_cli(cmd + f + extra, dir);
            // A clear one-line error and exit code 1, or (for damage the file
            // format cannot detect) a normal run; never a crash.
            EXPECT_TRUE(r.exit_code == 1 || r.exit_code == 0) << cmd << f << " exit " << r.exit_code << "\n" << r.err;
            if (r.exit_code == 1) {
                EXPECT_EQ(r.err.rfind("brdflut: error: ", 0), 0u) << r.err;
                EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
            }
        }
    // Missing, empty, text and truncated files are always errors.
    for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(run_cli("inspect " + cases[k], dir).exit_code, 1) << cases[k];
}

TEST(CliChecks, ForeignFilesNeedADescriptionThatFits) {
    TempDir dir;
    ASSERT_EQ(run_cli("generate ggx_albedo_avg ggx_dfg --size 16 -q -o '" + dir.path().string() + "'", dir).exit_code, 0);
    // Strip the metadata by writing a plain table through the library.
    {
        Table t = small_table("ggx_albedo", 16);
        write_exr(dir / "plain.exr", t, PixelType::float32);
    }
    const std::string dfg = "'" + (dir / "ggx_dfg.exr") + "'";
    const auto wrong_size = run_cli("compare " + dfg + " --as ggx_dfg --size 8", dir);
    EXPECT_EQ(wrong_size.exit_code, 1);
    EXPECT_NE(wrong_size.err.find("is 16x16 but the table described is 8x8"), std::string::npos) << wrong_size.err;
    const auto one_d = run_cli("compare " + dfg + " --as ggx_albedo_avg", dir);
    EXPECT_EQ(one_d.exit_code, 1);
    EXPECT_NE(one_d.err.find("is 1-D"), std::string::npos) << one_d.err;
    const auto too_many = run_cli("compare '" + (dir / "ggx_albedo_avg.exr") + "' --as ggx_albedo_avg --channels R=R,G=R", dir);
    EXPECT_EQ(too_many.exit_code, 1);
    EXPECT_NE(too_many.err.find("channel(s) but the description needs 2"), std::string::npos) << too_many.err;
    const auto opts_without_as = run_cli("compare " + dfg + " --size 8", dir);
    EXPECT_EQ(opts_without_as.exit_code, 2);
    EXPECT_NE(opts_without_as.err.find("need --as"), std::string::npos) << opts_without_as.err;
}
