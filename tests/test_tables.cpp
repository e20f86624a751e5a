// Generated tables: metadata, EXR round trip and thread independence.
#include <gtest/gtest.h>
#include <ImfChannelList.h>
#include <ImfDeepFrameBuffer.h>
#include <ImfDeepScanLineOutputFile.h>
#include <ImfPartType.h>
#include <ImfHeader.h>

#include <cmath>
#include <map>

#include "brdflut/catalogue.h"
#include "brdflut/error.h"
#include "brdflut/exr.h"
#include "brdflut/generate.h"
#include "brdflut/ggx_integrals.h"
#include "tables/shared_results.h"
#include "test_support.h"

using namespace brdflut;
using brdflut::test::TempDir;

namespace {
TableSettings small(const std::string& id, int n) {
    TableSettings s = default_settings(find_table(id));
    for (Axis& a : s.axes) a.count = n;
    return s;
}
}  // namespace

TEST(Catalogue, EveryTableIsWellFormed) {
    ASSERT_FALSE(catalogue().empty());
    for (const TableDefinition& d : catalogue()) {
        EXPECT_FALSE(d.description.empty()) << d.id;
        EXPECT_GE(d.channels.size(), 1u) << d.id;
        EXPECT_LE(d.channels.size(), 4u) << d.id;
        EXPECT_GE(d.axes.size(), 1u) << d.id;
        EXPECT_LE(d.axes.size(), 3u) << d.id;
        EXPECT_NO_THROW(validate_settings(d, default_settings(d))) << d.id;
        EXPECT_TRUE(static_cast<bool>(d.prepare)) << d.id;
    }
}

TEST(Catalogue, EachOptionNameHasOneMeaning) {
    // An option name means one thing across the catalogue: the same help
    // text and default wherever it appears (a table may accept fewer values).
    std::map<std::string, const ModelOption*> first;
    for (const TableDefinition& d : catalogue())
        for (const ModelOption& o : d.options) {
            const auto [it, added] = first.emplace(o.name, &o);
            if (added) continue;
            EXPECT_EQ(o.help, it->second->help) << "--" << o.name << " of " << d.id;
            EXPECT_EQ(o.default_value, it->second->default_value) << "--" << o.name << " of " << d.id;
        }
    EXPECT_GT(first.size(), 5u);
}

TEST(Catalogue, UnknownIdNamesTheKnownOnes) {
    try {
        find_table("ggx_nope");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("ggx_dfg"), std::string::npos);
    }
}

TEST(Axis, PlacementAndWarpsFollowTheDocumentedFormulas) {
    Axis a{"alpha", 0.0, 1.0, 4, Placement::center, Warp::square};
    EXPECT_DOUBLE_EQ(a.value(0), 0.125 * 0.125);
    EXPECT_DOUBLE_EQ(a.value(3), 0.875 * 0.875);
    a.placement = Placement::endpoints;
    EXPECT_DOUBLE_EQ(a.value(0), 0.0);
    EXPECT_DOUBLE_EQ(a.value(3), 1.0);
    a.warp = Warp::sqrt;
    EXPECT_DOUBLE_EQ(a.value(1), std::sqrt(1.0 / 3.0));
    Axis l{"radius", 1e-3, 64.0, 5, Placement::endpoints, Warp::log};
    EXPECT_DOUBLE_EQ(l.value(0), 1e-3);
    EXPECT_DOUBLE_EQ(l.value(4), 64.0);
    EXPECT_NEAR(l.value(2), std::sqrt(1e-3 * 64.0), 1e-12);
    EXPECT_NEAR(l.u_of_value(l.value(3)), l.u(3), 1e-14);
}

TEST(Axis, RejectsMalformedAxes) {
    EXPECT_THROW((Axis{"alpha", 0.0, 1.0, 0, Placement::center, Warp::linear}.validate()), Error);
    EXPECT_THROW((Axis{"alpha", 1.0, 1.0, 4, Placement::center, Warp::linear}.validate()), Error);
    EXPECT_THROW((Axis{"alpha", 0.0, 1.0, 1, Placement::endpoints, Warp::linear}.validate()), Error);
    EXPECT_THROW((Axis{"radius", 0.0, 1.0, 4, Placement::center, Warp::log}.validate()), Error);
}

TEST(Generate, ValuesMatchTheIntegralsAtTheAxisParameters) {
    const Table t = generate(find_table("ggx_dfg"), small("ggx_dfg", 8));
    ASSERT_EQ(t.values.size(), 8u * 8u * 2u);
    for (int j = 0; j < 8; j += 3)
        for (int i = 0; i < 8; i += 3) {
            const double mu = (i + 0.5) / 8, alpha = std::pow((j + 0.5) / 8, 2);
            const auto e = ggx_split_sum(mu, alpha, Visibility::height_correlated, kGgxTableTolerance);
            EXPECT_DOUBLE_EQ(t.at(static_cast<std::size_t>(j * 8 + i), 0), e.value[0]);
            EXPECT_DOUBLE_EQ(t.at(static_cast<std::size_t>(j * 8 + i), 1), e.value[1]);
        }
}

TEST(Generate, AlbedoIsTheSumOfTheSplitSumChannels) {
    const Table dfg = generate(find_table("ggx_dfg"), small("ggx_dfg", 6));
    const Table e = generate(find_table("ggx_albedo"), small("ggx_albedo", 6));
    for (std::size_t k = 0; k < e.texel_count(); ++k)
        EXPECT_DOUBLE_EQ(e.at(k, 0), dfg.at(k, 0) + dfg.at(k, 1));
}

TEST(Generate, SameBytesForAnyThreadCount) {
    TempDir dir;
    for (const std::string id : {"ggx_dfg", "ggx_albedo_avg"}) {
        TableSettings s = small(id, 16);
        // Each run computes every texel (no split sum shared from the last).
        for (int threads : {1, 2, 0})
            write_exr(dir / (id + std::to_string(threads) + ".exr"), test::generate_fresh(find_table(id), s, threads),
                      PixelType::float32);
        const std::string a = test::read_file(dir / (id + "1.exr"));
        EXPECT_FALSE(a.empty());
        EXPECT_EQ(a, test::read_file(dir / (id + "2.exr"))) << id;
        EXPECT_EQ(a, test::read_file(dir / (id + "0.exr"))) << id;
    }
}

TEST(Quality, IsRecordedAndSetsTheToleranceAndDraftEstimatesAreHonest) {
    // Every table with a tolerance, engine presets included: one that ignored
    // --quality would record the same tolerance at every quality.
    // Three texels per axis, the middle one included.
    int checked = 0;
    for (const TableDefinition& def : catalogue()) {
        const std::string id = def.id;
        std::map<Quality, Table> t;
        for (Quality q : {Quality::draft, Quality::standard, Quality::reference}) {
            TableSettings s = small(id, 3);
            s.quality = q;
            t.emplace(q, generate(def, s));
            EXPECT_EQ(t.at(q).method.at("quality"), std::string(to_string(q))) << id;
            if (!t.at(q).method.contains("abs_tolerance")) break;  // a closed form
        }
        if (t.size() < 3) continue;
        ++checked;
        const double draft = t.at(Quality::draft).method.at("abs_tolerance");
        const double standard = t.at(Quality::standard).method.at("abs_tolerance");
        const double reference = t.at(Quality::reference).method.at("abs_tolerance");
        EXPECT_GT(draft, standard) << id;
        // The default keeps every stored float within 1e-7 of the exact
        // value, with half a float step (3e-8 below 1) on top: at most 5e-8
        // (most tables ask for 1e-8, the glass tables 2e-8).
        EXPECT_LE(standard, 5e-8) << id;
        // The reference is at least 50 times tighter, so that it can judge
        // the default's errors (most 1e-12, the glass tables 1e-10).
        EXPECT_LE(reference, 0.02 * standard) << id;
        EXPECT_LT(reference, standard) << id;
        const Table& ref = t.at(Quality::reference);
        for (Quality q : {Quality::draft, Quality::standard}) {
            const Table& a = t.at(q);
            for (std::size_t n = 0; n < a.values.size(); ++n) {
                // Both are estimates of the same integral: their difference is
                // covered by the sum of their errors.
                EXPECT_LE(std::abs(a.values[n] - ref.values[n]), a.errors[n] + ref.errors[n] + 1e-14)
                    << id << " " << to_string(q) << " value " << n;
                EXPECT_LE(a.errors[n], to_string(q) == "draft" ? draft : standard) << id << " " << n;
            }
        }
    }
    EXPECT_GE(checked, 20);
    // Closed forms ignore it but say which was asked for.
    TableSettings s = small("fresnel_dielectric", 4);
    s.quality = Quality::draft;
    EXPECT_EQ(generate(find_table("fresnel_dielectric"), s).method.at("quality"), "draft");
    EXPECT_EQ(quality_from_string("default"), Quality::standard);
    EXPECT_THROW(quality_from_string("best"), Error);
}

TEST(Exr, RoundTripKeepsValuesAndMetadataDescribesEveryTexel) {
    TempDir dir;
    TableSettings s = default_settings(find_table("ggx_dfg"));
    s.axes[0].count = 12;
    s.axes[1].count = 5;
    s.axes[1].placement = Placement::endpoints;
    s.params["visibility"] = "separable";
    const Table t = generate(find_table("ggx_dfg"), s);
    for (PixelType p : {PixelType::float32, PixelType::half}) {
        const std::string path = dir / "t.exr";
        write_exr(path, t, p);
        const ExrImage img = read_exr(path);
        ASSERT_EQ(img.width, 12);
        ASSERT_EQ(img.height, 5);
        ASSERT_EQ(img.channel_names, (std::vector<std::string>{"R", "G"}));
        EXPECT_EQ(img.pixel, p);
        ASSERT_TRUE(img.has_metadata);
        const auto& m = img.metadata;
        EXPECT_EQ(m.at("table"), "ggx_dfg");
        EXPECT_EQ(m.at("generator").at("name"), "brdflut");
        EXPECT_EQ(m.at("model").at("visibility"), "separable");
        EXPECT_EQ(m.at("channels").size(), 2u);
        EXPECT_TRUE(m.at("method").contains("rule"));
        const double bound = m.at("error_bound").get<double>();
        EXPECT_GT(bound, 0.0);
        EXPECT_LT(bound, p == PixelType::half ? 1e-3 : 1e-7);
        const std::vector<Axis> axes = axes_from_json(m.at("axes"));
        ASSERT_EQ(axes.size(), 2u);
        // The metadata alone gives the parameters of every texel.
        for (int j = 0; j < 5; ++j)
            for (int i = 0; i < 12; ++i) {
                EXPECT_EQ(axes[0].value(i), t.axes[0].value(i));
                EXPECT_EQ(axes[1].value(j), t.axes[1].value(j));
                for (int c = 0; c < 2; ++c) {
                    const std::size_t k = static_cast<std::size_t>(j * 12 + i);
                    const double stored = img.pixels[k * 2 + static_cast<std::size_t>(c)];
                    EXPECT_EQ(stored, round_to_storage(t.at(k, c), p));
                    EXPECT_LE(std::abs(stored - t.at(k, c)), bound);
                }
            }
        EXPECT_EQ(axes[1].value(0), 0.0);
        EXPECT_EQ(axes[1].value(4), 1.0);
    }
}

TEST(Exr, RefusesNonFiniteValuesAndNamesTheTexel) {
    TempDir dir;
    Table t = generate(find_table("ggx_albedo"), small("ggx_albedo", 3));
    t.values[4] = std::nan("");
    try {
        write_exr(dir / "bad.exr", t, PixelType::float32);
        FAIL() << "expected an error";
    } catch (const RuntimeError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("ggx_albedo"), std::string::npos) << msg;
        EXPECT_NE(msg.find("cos_theta index 1"), std::string::npos) << msg;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "bad.exr"));
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(Exr, ReadingAMissingOrCorruptFileIsAClearError) {
    TempDir dir;
    EXPECT_THROW(read_exr(dir / "missing.exr"), RuntimeError);
    {
        std::ofstream f(dir / "junk.exr", std::ios::binary);
        f << "this is not an EXR file";
    }
    EXPECT_THROW(read_exr(dir / "junk.exr"), RuntimeError);
}

namespace {
// The bytes of a small valid table file, and the offset of the value of the
// header attribute `name` (just after its 4-byte size).
std::string table_bytes(const TempDir& dir) {
    const Table t = generate(find_table("ggx_dfg"), small("ggx_dfg", 4));
    write_exr(dir / "ok.exr", t, PixelType::float32);
    return brdflut::test::read_file(dir / "ok.exr");
}
std::size_t attribute_value(const std::string& bytes, const std::string& name, const std::string& type) {
    const std::string key = name + '\0' + type + '\0';
    const std::size_t at = bytes.find(key);
    EXPECT_NE(at, std::string::npos) << name;
    return at + key.size() + 4;
}
void put_int32(std::string& bytes, std::size_t at, std::int32_t v) {
    for (int i = 0; i < 4; ++i) bytes[at + i] = static_cast<char>((static_cast<std::uint32_t>(v) >> (8 * i)) & 0xff);
}
std::string read_error(const std::string& bytes) {
    try {
        read_exr_memory(bytes.data(), bytes.size(), "damaged");
    } catch (const RuntimeError& e) {
        return e.what();
    }
    return "(no error)";
}
}  // namespace

// Headers that claim more memory than the file could fill are refused by
// what they declare, before OpenEXR's C++ reader allocates for them.
TEST(Exr, HeadersDeclaringHugeSizesAreRefusedWithTheReason) {
    TempDir dir;
    const std::string good = table_bytes(dir);
    EXPECT_EQ(read_error(good), "(no error)");

    std::string attr = good;  // the metadata string claims 2 GB
    put_int32(attr, attribute_value(attr, "brdflut", "string") - 4, 0x7fff0000);
    EXPECT_NE(read_error(attr).find("not a valid OpenEXR file (Attribute 'brdflut', type 'string': Invalid size"),
              std::string::npos) << read_error(attr);

    const std::size_t dw = attribute_value(good, "dataWindow", "box2i");  // min.x, min.y, max.x, max.y
    std::string big = good;  // 16384 x 16384 pixels
    put_int32(big, dw + 8, 16383);
    put_int32(big, dw + 12, 16383);
    EXPECT_NE(read_error(big).find("part 0 is 16384x16384 pixels with 2 channel(s); supported are at most 67108864 "
                                   "pixels"),
              std::string::npos) << read_error(big);

    std::string wide = good;  // 16 M pixels wide: one 16-line zip block would need 2 GB
    put_int32(wide, dw + 8, 16777215);
    EXPECT_NE(read_error(wide).find("part 0 is stored in blocks of 16777216x16 pixels of 8 bytes"), std::string::npos)
        << read_error(wide);

    std::string tall = good;  // 4 M rows of zip blocks need a 2 MB offset table
    put_int32(tall, dw + 12, (1 << 22) - 1);
    EXPECT_NE(read_error(tall).find("truncated: part 0 declares 262144 blocks but the file has"), std::string::npos)
        << read_error(tall);
}

// Deep data (a sample list per pixel) is valid OpenEXR but no table.
TEST(Exr, DeepDataIsRefusedByName) {
    TempDir dir;
    {
        Imf::Header h(2, 2);
        h.setType(Imf::DEEPSCANLINE);
        h.compression() = Imf::ZIPS_COMPRESSION;
        h.channels().insert("R", Imf::Channel(Imf::FLOAT));
        Imf::DeepScanLineOutputFile out((dir / "deep.exr").c_str(), h);
        unsigned int counts[4] = {1, 1, 1, 1};
        float values[4] = {0.1f, 0.2f, 0.3f, 0.4f};
        float* pointers[4] = {&values[0], &values[1], &values[2], &values[3]};
        Imf::DeepFrameBuffer fb;
        fb.insertSampleCountSlice(Imf::Slice(Imf::UINT, reinterpret_cast<char*>(counts), sizeof(unsigned int),
                                             2 * sizeof(unsigned int)));
        fb.insert("R", Imf::DeepSlice(Imf::FLOAT, reinterpret_cast<char*>(pointers), sizeof(float*),
                                      2 * sizeof(float*), sizeof(float)));
        out.setFrameBuffer(fb);
        out.writePixels(2);
    }
    const std::string deep = brdflut::test::read_file(dir / "deep.exr");
    EXPECT_NE(read_error(deep).find("part 0 holds deep data, which no table uses"), std::string::npos)
        << read_error(deep);
}

TEST(SharedResults, CachesAtMostItsBoundAndClearSharedResultsEmptiesIt) {
    tables::SharedResults<1, std::uint64_t> cache(128);  // two values per shard
    int calls = 0;
    auto get = [&](std::uint64_t k, bool* computed) {
        return cache.get({k}, [&] { ++calls; return 3 * k; }, computed);
    };
    bool computed = false;
    for (std::uint64_t k = 0; k < 1000; ++k) {
        EXPECT_EQ(get(k, &computed), 3 * k);
        EXPECT_TRUE(computed) << k;
    }
    int hits = 0;
    for (std::uint64_t k = 0; k < 1000; ++k) {
        EXPECT_EQ(get(k, &computed), 3 * k);  // a hit returns what was computed
        hits += computed ? 0 : 1;
    }
    EXPECT_GT(hits, 0);
    EXPECT_LE(hits, 128);
    EXPECT_EQ(calls, 2000 - hits);
    clear_shared_results();
    for (std::uint64_t k = 0; k < 1000; ++k) {
        get(k, &computed);
        EXPECT_TRUE(computed) << k;
    }
}
