// Integer encodings (brdflut/table.h): UNORM8, UNORM16, R10G10B10A2 and
// Babylon.js's RGBD, their rounding, their refusal of values out of range,
// and their round trips through every format that holds them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "brdflut/error.h"
#include "brdflut/exr.h"
#include "brdflut/formats.h"
#include "brdflut/lut.h"
#include "brdflut/table.h"
#include "test_support.h"

using namespace brdflut;
using brdflut::test::read_file;
using brdflut::test::run_cli;
using brdflut::test::TempDir;

namespace {

constexpr Storage kIntegers[] = {Storage::unorm8, Storage::unorm16, Storage::rgb10a2, Storage::rgbd};

double unorm_top(Storage s) {
    switch (s) {
        case Storage::unorm8: return 255.0;
        case Storage::unorm16: return 65535.0;
        default: return 1023.0;
    }
}

// A table of `channels` channels whose values spread over [0, top] and hit
// the ends of the range.
Table make_table(int channels, double top = 1.0, int width = 7, int height = 5) {
    Table t;
    t.id = "enc_test";
    t.axes.push_back(Axis{"cos_theta", 0.0, 1.0, width, Placement::center, Warp::linear});
    t.axes.push_back(Axis{"alpha", 0.0, 1.0, height, Placement::endpoints, Warp::linear});
    const char* names[4] = {"first", "second", "third", "fourth"};
    for (int c = 0; c < channels; ++c) t.channels.push_back(names[c]);
    t.model = {{"name", "test"}};
    t.method = {{"rule", "none"}};
    const std::size_t n = t.texel_count() * static_cast<std::size_t>(channels);
    for (std::size_t i = 0; i < n; ++i) {
        const double u = std::fmod(0.013 + 0.6180339887 * static_cast<double>(i), 1.0);
        t.values.push_back(i == 0 ? 0.0 : i == 1 ? top : u * top);
        t.errors.push_back(1e-9);
    }
    return t;
}

}  // namespace

// Round to nearest as D3D and Vulkan convert a float to UNORM: every value
// reads back within half a step, and the code chosen is the nearest one.
TEST(Encoding, UnormRoundsToNearestWithinHalfAStep) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (const Storage s : {Storage::unorm8, Storage::unorm16, Storage::rgb10a2}) {
        SCOPED_TRACE(std::string(to_string(s)));
        const double top = unorm_top(s);
        const std::uint32_t zero[4] = {0, 0, 0, 0};
        EXPECT_DOUBLE_EQ(encoding_step(s, zero, 0), 1.0 / top);
        for (int i = 0; i < 20000; ++i) {
            const double v[3] = {u(rng), u(rng), u(rng)};
            std::uint32_t q[4];
            encode_texel(s, v, 3, q);
            double back[4];
            decode_texel(s, q, back);
            for (int c = 0; c < 3; ++c) {
                ASSERT_LE(std::abs(back[c] - v[c]), 0.5 / top + 1e-15) << v[c];
                ASSERT_EQ(q[c], static_cast<std::uint32_t>(std::floor(v[c] * top + 0.5))) << v[c];
            }
            ASSERT_EQ(back[3], 1.0);  // A is 1 (padding) in every unorm texel of 3 channels
        }
        // The ends are exact; a tie rounds away from zero.
        const double ends[2] = {0.0, 1.0};
        std::uint32_t q[4];
        encode_texel(s, ends, 2, q);
        EXPECT_EQ(q[0], 0u);
        EXPECT_EQ(q[1], static_cast<std::uint32_t>(top));
    }
    const double tie = 2.5 / 255.0;  // 2.5 steps: 3, not the even 2
    std::uint32_t q[4];
    encode_texel(Storage::unorm8, &tie, 1, q);
    EXPECT_EQ(q[0], 3u);
}

// Babylon.js's RGBD: D is floor(255 / max) / 255 (1 for values up to 1), and
// the gamma-2.2 code of v * D is rounded to nearest; decoding reverses it.
TEST(Encoding, RgbdFollowsBabylonsEncodeAndDecode) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 20000; ++i) {
        const double top = i % 2 == 0 ? 1.0 : 1.0 + 254.0 * u(rng);
        const double v[3] = {top * u(rng), top * u(rng), top * u(rng)};
        const double m = std::max({v[0], v[1], v[2], 1e-7});
        std::uint32_t q[4];
        encode_texel(Storage::rgbd, v, 3, q);
        ASSERT_EQ(q[3], static_cast<std::uint32_t>(std::min(std::floor(std::max(255.0 / m, 1.0)), 255.0)));
        if (m <= 1.0) {
            ASSERT_EQ(q[3], 255u);
        }
        double back[3];
        decode_texel(Storage::rgbd, q, back);
        for (int c = 0; c < 3; ++c) {
            // Rounded to nearest in the stored (gamma) code ...
            const double code = 255.0 * std::pow(v[c] * q[3] / 255.0, 1.0 / 2.2);
            ASSERT_LE(std::abs(code - q[c]), 0.5 + 1e-9) << v[c];
            // ... so the value is within half of the larger gap around it.
            ASSERT_LE(std::abs(back[c] - v[c]), 0.5 * encoding_step(Storage::rgbd, q, c) + 1e-12) << v[c];
            ASSERT_DOUBLE_EQ(back[c], std::pow(q[c] / 255.0, 2.2) / (q[3] / 255.0));
        }
    }
}

TEST(Encoding, NamesRoundTripAndUnknownNamesListTheAllowed) {
    for (const Storage s : {Storage::half, Storage::float32, Storage::unorm16, Storage::unorm8, Storage::rgb10a2,
                            Storage::rgbd})
        EXPECT_EQ(storage_from_string(to_string(s)), s);
    try {
        storage_from_string("unorm12");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("'unorm12'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("allowed: half, float, unorm16, unorm8, rgb10a2, rgbd"),
                  std::string::npos)
            << e.what();
    }
}

// Every format that holds an encoding writes it and reads it back as the
// decoded values, with the metadata naming the encoding and its decode.
TEST(Encoding, EveryEncodingRoundTripsThroughEveryFormatHoldingIt) {
    TempDir dir;
    for (const Storage s : kIntegers) {
        const double top = s == Storage::rgbd ? 40.0 : 1.0;
        const auto formats = formats_holding(s);
        ASSERT_FALSE(formats.empty());
        for (const Format f : formats)
            for (int channels = 1; channels <= max_channels(s); ++channels) {
                SCOPED_TRACE(std::string(to_string(s)) + " " + std::string(to_string(f)) + " " +
                             std::to_string(channels));
                const Table t = make_table(channels, top);
                const std::string path = dir / ("t." + file_extension(f));
                write_table(path, t, s, f);
                ReadOptions o;
                // A dds has no metadata: its RGBA8 bytes are rgbd when said so.
                if (f == Format::dds && s == Storage::rgbd) o.decode = Decode::rgbd;
                const ExrImage img = read_table_image(path, o);
                EXPECT_EQ(img.storage, s);
                EXPECT_EQ(img.width, 7);
                EXPECT_EQ(img.height, 5);
                const std::size_t stored = img.channel_names.size();
                ASSERT_GE(stored, static_cast<std::size_t>(channels));
                for (std::size_t k = 0; k < t.texel_count(); ++k) {
                    double want[4];
                    round_texel(s, &t.values[k * static_cast<std::size_t>(channels)], channels, want);
                    for (int c = 0; c < channels; ++c) {
                        const double got = img.pixels[k * stored + static_cast<std::size_t>(c)];
                        ASSERT_NEAR(got, want[c], 1e-12 * std::max(1.0, want[c])) << "texel " << k << " channel " << c;
                        const double step = storage_step(img, k * stored + static_cast<std::size_t>(c), got);
                        ASSERT_LE(std::abs(got - t.at(k, c)), 0.5 * step + 1e-12) << "texel " << k << " channel " << c;
                    }
                }
                if (f != Format::dds) {
                    ASSERT_TRUE(img.has_metadata);
                    EXPECT_EQ(img.metadata.at("pixel"), to_string(s));
                    EXPECT_EQ(img.metadata.at("decode"), decode_rule(s));
                    EXPECT_EQ(img.metadata, metadata_json(t, s));
                }
                // compare's default for a file of integers: one step of its encoding.
                const Tolerance tol = default_tolerance(img);
                EXPECT_EQ(tol.steps, 1.0);
                EXPECT_EQ(tol.abs, 0.0);
                EXPECT_NE(tol.source.find(std::string(to_string(s))), std::string::npos) << tol.source;
            }
    }
}

// The DXGI and Vulkan codes and the KTX2 descriptor of the UNORM formats.
TEST(Encoding, DdsAndKtx2NameTheUnormFormats) {
    TempDir dir;
    struct Case {
        Storage s;
        int channels;
        std::uint32_t dxgi, vk;
    };
    const Case cases[] = {{Storage::unorm8, 1, 61, 9},   {Storage::unorm8, 2, 49, 16},  {Storage::unorm8, 3, 28, 37},
                          {Storage::unorm16, 1, 56, 70}, {Storage::unorm16, 2, 35, 77}, {Storage::unorm16, 4, 11, 91},
                          {Storage::rgb10a2, 2, 24, 64}, {Storage::rgbd, 2, 28, 37}};
    auto u32 = [](const std::string& b, std::size_t at) {
        std::uint32_t v = 0;
        for (int i = 3; i >= 0; --i) v = v << 8 | static_cast<unsigned char>(b.at(at + static_cast<std::size_t>(i)));
        return v;
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(std::string(to_string(c.s)) + " " + std::to_string(c.channels));
        const Table t = make_table(c.channels, c.s == Storage::rgbd ? 3.0 : 1.0);
        write_table(dir / "t.dds", t, c.s, Format::dds);
        write_table(dir / "t.ktx2", t, c.s, Format::ktx2);
        const std::string dds = read_file(dir / "t.dds"), ktx = read_file(dir / "t.ktx2");
        EXPECT_EQ(u32(dds, 128), c.dxgi);
        EXPECT_EQ(u32(ktx, 12), c.vk);
        // DFD: the first sample of an UNORM format is unsigned, not float, from 0 to 2^bits - 1.
        const std::size_t dfd = u32(ktx, 48);
        const std::uint32_t sample0 = u32(ktx, dfd + 28);
        EXPECT_EQ(sample0 >> 24 & 0xC0u, 0u);
        const std::uint32_t bits = (sample0 >> 16 & 0xFFu) + 1;
        EXPECT_EQ(bits, c.s == Storage::unorm16 ? 16u : c.s == Storage::rgb10a2 ? 10u : 8u);
        EXPECT_EQ(u32(ktx, dfd + 28 + 8), 0u);
        EXPECT_EQ(u32(ktx, dfd + 28 + 12), (1u << bits) - 1u);
    }
}

// A value that is an end of the range up to the rounding of a computed
// value is stored as that end.
TEST(Encoding, ValuesWithinRoundingOfAnEndAreStoredAsThatEnd) {
    TempDir dir;
    for (const Storage s : kIntegers) {
        const double top = s == Storage::rgbd ? 255.0 : 1.0;
        Table t = make_table(2, top);
        t.values[5] = -2.220446049250313e-16;
        t.values[6] = top * (1.0 + 4e-16);
        const Format f = formats_holding(s).front();
        const std::string path = dir / ("end." + file_extension(f));
        write_table(path, t, s, f);
        ReadOptions o;
        if (f == Format::dds && s == Storage::rgbd) o.decode = Decode::rgbd;
        const ExrImage back = read_table_image(path, o);
        // Values 5 and 6 are texel 2's channel 1 and texel 3's channel 0.
        const std::size_t stored = back.channel_names.size();
        EXPECT_EQ(back.pixels.at(2 * stored + 1), 0.0) << to_string(s);
        EXPECT_NEAR(back.pixels.at(3 * stored), top, 1e-12 * top) << to_string(s);
    }
}

// Out-of-range values are refused, never clamped, naming the value, the
// texel and the allowed range; nothing is written.
TEST(Encoding, ValuesOutOfRangeAndTooManyChannelsAreRefused) {
    TempDir dir;
    for (const Storage s : kIntegers) {
        const double top = s == Storage::rgbd ? 255.0 : 1.0;
        for (const double bad : {-1e-9, top * (1 + 1e-9)}) {
            Table t = make_table(2);
            t.values[5] = bad;
            for (const Format f : formats_holding(s)) {
                const std::string path = dir / ("bad." + file_extension(f));
                try {
                    write_table(path, t, s, f);
                    FAIL() << to_string(s) << " " << bad << ": expected a refusal";
                } catch (const Error& e) {
                    const std::string msg = e.what();
                    EXPECT_NE(msg.find(s == Storage::rgbd ? "outside [0, 255]" : "outside [0, 1]"), std::string::npos) << msg;
                    EXPECT_NE(msg.find("encoding " + std::string(to_string(s))), std::string::npos) << msg;
                    EXPECT_NE(msg.find("texel ("), std::string::npos) << msg;
                    EXPECT_NE(msg.find("not clamped"), std::string::npos) << msg;
                }
                EXPECT_FALSE(std::filesystem::exists(path));
            }
        }
    }
    for (const Storage s : {Storage::rgb10a2, Storage::rgbd}) {
        try {
            write_table(dir / "four.dds", make_table(4), s, Format::dds);
            FAIL() << "expected a refusal";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("holds 1 to 3"), std::string::npos) << e.what();
        }
    }
    try {
        write_table(dir / "t.exr", make_table(1), Storage::unorm8, Format::exr);
        FAIL() << "expected a refusal";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("allowed for exr: float, half"), std::string::npos) << e.what();
    }
}

// Corrupt and truncated files of the new formats are clear errors.
TEST(Encoding, CorruptAndTruncatedEncodedFilesAreClearErrors) {
    TempDir dir;
    for (const Storage s : kIntegers)
        for (const Format f : {Format::dds, Format::ktx2}) {
            SCOPED_TRACE(std::string(to_string(s)) + " " + std::string(to_string(f)));
            write_table(dir / ("t." + file_extension(f)), make_table(2), s, f);
            const std::string b = read_file(dir / ("t." + file_extension(f)));
            std::ofstream(dir / "cut", std::ios::binary) << b.substr(0, b.size() - 3);
            try {
                read_table_image(dir / "cut");
                FAIL() << "expected an error";
            } catch (const RuntimeError& e) {
                EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
            }
        }
    // An rgbd texel whose D (A) is 0 has no value.
    write_table(dir / "d.png", make_table(1, 2.0), Storage::rgbd, Format::png);
    write_table(dir / "d.dds", make_table(1, 2.0), Storage::rgbd, Format::dds);
    std::string b = read_file(dir / "d.dds");
    b[148 + 4 * 3 + 3] = '\0';  // A of texel 3
    std::ofstream(dir / "zero.dds", std::ios::binary) << b;
    ReadOptions rgbd;
    rgbd.decode = Decode::rgbd;
    try {
        read_table_image(dir / "zero.dds", rgbd);
        FAIL() << "expected an error";
    } catch (const RuntimeError& e) {
        EXPECT_NE(std::string(e.what()).find("texel 3 has D = 0"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("allowed: 1 to 255"), std::string::npos) << e.what();
    }
    // rgbd decoding needs 8-bit RGBA.
    write_table(dir / "u16.dds", make_table(4), Storage::unorm16, Format::dds);
    EXPECT_THROW(read_table_image(dir / "u16.dds", rgbd), RuntimeError);
    EXPECT_EQ(read_table_image(dir / "d.png").channel_names.size(), 3u);  // decoded by its metadata
}

// generate --encoding writes the file; compare reads it back as values and
// passes at one step of the encoding; a value two steps off fails.
TEST(Encoding, CliGeneratesComparesAndRefusesEncodings) {
    TempDir dir;
    const std::string out = dir / "o";
    auto r = run_cli("generate ggx_dfg --size 16x8 --format dds --encoding unorm16 -q -o '" + out + "'", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string dds = out + "/ggx_dfg.dds";
    r = run_cli("compare '" + dds + "' --as ggx_dfg --size 16x8", dir);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("one storage step of the file's unorm16 values"), std::string::npos) << r.out;
    // Texel 5's R moved by two steps.
    std::string b = read_file(dds);
    const std::size_t at = 148 + 4 * 5;
    const unsigned q = static_cast<unsigned char>(b[at]) | static_cast<unsigned char>(b[at + 1]) << 8;
    const unsigned moved = q >= 2 ? q - 2 : q + 2;
    b[at] = static_cast<char>(moved & 0xff);
    b[at + 1] = static_cast<char>(moved >> 8);
    std::ofstream(dir / "moved.dds", std::ios::binary) << b;
    r = run_cli("compare '" + (dir / "moved.dds") + "' --as ggx_dfg --size 16x8", dir);
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;

    for (const char* e : {"unorm8", "rgbd"}) {
        r = run_cli("generate ggx_dfg --size 16x8 --format png --encoding " + std::string(e) + " -q -o '" + out + "'", dir);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        r = run_cli("compare '" + out + "/ggx_dfg.png'", dir);
        EXPECT_EQ(r.exit_code, 0) << e << "\n" << r.out << r.err;
        r = run_cli("inspect '" + out + "/ggx_dfg.png' --json", dir);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_EQ(nlohmann::json::parse(r.out).at("pixel"), e);
    }
    r = run_cli("generate ggx_dfg --size 4 --format exr --encoding unorm8 -o '" + out + "'", dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("--encoding unorm8 does not apply to --format exr; allowed for exr: float, half"),
              std::string::npos)
        << r.err;
    r = run_cli("generate ggx_dfg --size 4 --format dds --encoding unorm12 -o '" + out + "'", dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("allowed: half, float, unorm16, unorm8, rgb10a2, rgbd"), std::string::npos) << r.err;
    r = run_cli("generate disney_diffuse_albedo --size 8 --format ktx2 --encoding rgb10a2 -o '" + out + "'", dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("outside [0, 1]"), std::string::npos) << r.err;
}

// A preset table that its engine stores in an integer encoding (Unreal's
// G16R16 UNORM, glTF's RGBA8 PNG, Babylon's RGBD) is written in it by the
// formats that hold it, unless --pixel or --encoding says otherwise; EXR and
// the other tables keep the preset's pixel type. (Unreal's cloth energy and
// glTF's Charlie exceed 1 and HDRP's diffuse channel E - 0.5 falls below 0:
// the engines' unorm textures clamp them, and brdflut refuses to, so those
// keep theirs.)
TEST(Encoding, PresetsWriteTheEnginesEncodingWhereTheFormatHoldsIt) {
    TempDir dir;
    const std::string out = dir / "o";
    // Runs `generate ARGS -o out` and returns the stored pixel type of each file.
    const auto generate = [&](const std::string& args, const std::vector<std::string>& files) {
        const auto r = run_cli("generate " + args + " -o '" + out + "'", dir);
        EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
        std::vector<std::string> pixels;
        for (const std::string& f : files) {
            const auto i = run_cli("inspect '" + out + "/" + f + "' --json", dir);
            EXPECT_EQ(i.exit_code, 0) << f << i.err;
            pixels.push_back(i.exit_code == 0 ? nlohmann::json::parse(i.out).at("pixel").get<std::string>() : "");
        }
        return std::make_pair(r.out, pixels);
    };
    using Pixels = std::vector<std::string>;
    const auto [said, unreal] = generate("--preset unreal --size 8 --format ktx2", {"unreal_dfg.ktx2", "unreal_cloth_energy.ktx2"});
    EXPECT_NE(said.find("unreal_dfg.ktx2: 8x8, 2 channel(s), unorm16"), std::string::npos) << said;
    EXPECT_EQ(unreal, (Pixels{"unorm16", "float"}));
    auto r = run_cli("compare '" + out + "/unreal_dfg.ktx2'", dir);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_EQ(generate("--preset unreal --size 8 --format ktx2 --pixel float -q", {"unreal_dfg.ktx2"}).second,
              Pixels{"float"});
    EXPECT_EQ(generate("--preset unreal --size 8 --format ktx2 --encoding half -q", {"unreal_dfg.ktx2"}).second,
              Pixels{"half"});
    EXPECT_EQ(generate("--preset unreal --size 8 -q", {"unreal_dfg.exr"}).second, Pixels{"float"});
    // A preset table named by id is written the same way.
    EXPECT_EQ(generate("gltf_ggx gltf_charlie --size 8 --format dds -q", {"gltf_ggx.dds", "gltf_charlie.dds"}).second,
              (Pixels{"unorm8", "float"}));
    EXPECT_EQ(generate("--preset babylon --size 8 --format png -q", {"babylon_brdf.png"}).second, Pixels{"rgbd"});
    r = run_cli("compare '" + out + "/babylon_brdf.png'", dir);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_EQ(generate("--preset hdrp --size 8 --format dds -q", {"hdrp_fgd.dds"}).second, Pixels{"half"});
    // The lookup functions read linear values: rgbd with --shader is refused,
    // naming the table for an engine encoding and the option for --encoding.
    r = run_cli("generate --preset babylon --size 8 --format png --shader glsl -q -o '" + out + "'", dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("babylon_brdf's engine encoding rgbd"), std::string::npos) << r.err;
    r = run_cli("generate ggx_dfg --size 8 --format png --encoding rgbd --shader glsl -q -o '" + out + "'", dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("--shader does not apply to --encoding rgbd"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("allowed with --shader: half, float, unorm16, unorm8, rgb10a2"), std::string::npos) << r.err;
}

// The fuzzer's seeds of the integer encodings (tests/fuzz/corpus, first
// byte the read options as fuzz_read_table.cpp picks them) read as tables.
TEST(Encoding, FuzzSeedsOfTheEncodingsReadAsTables) {
    const std::pair<const char*, Storage> seeds[] = {
        {"dds_unorm8_4x4.dds", Storage::unorm8},        {"ktx2_unorm16_4x4.ktx2", Storage::unorm16},
        {"ktx2_rgb10a2_4x4.ktx2", Storage::rgb10a2},    {"dds_rgb10a2_4x4.dds", Storage::rgb10a2},
        {"ktx2_rgbd_4x4.ktx2", Storage::rgbd},          {"png_rgbd_4x4.png", Storage::rgbd},
        {"png8_unorm8_4x4.png", Storage::unorm8},       {"dds_rgbd_4x4_decode_rgbd.dds", Storage::rgbd}};
    for (const auto& [name, storage] : seeds) {
        SCOPED_TRACE(name);
        const std::string b = read_file(std::string(BRDFLUT_SOURCE_DIR) + "/tests/fuzz/corpus/" + name);
        ASSERT_GT(b.size(), 1u);
        ReadOptions o;
        if (b[0] == 0x10) o.decode = Decode::rgbd;
        const ExrImage img = read_table_image_memory(b.data() + 1, b.size() - 1, name, o);
        EXPECT_EQ(img.storage, storage);
        EXPECT_EQ(img.width, 4);
        EXPECT_EQ(img.height, 4);
    }
}

// sample reads an encoded file as values: filtered, within half a step of
// the same point sampled from float storage (bilinear weights sum to 1).
TEST(Encoding, CliSamplesEncodedFilesAsValues) {
    TempDir dir;
    const std::string out = dir / "o";
    auto value_of = [](const std::string& text, const std::string& channel) {
        const std::size_t at = text.find(channel + " = ");
        return at == std::string::npos ? NAN : std::stod(text.substr(at + channel.size() + 3));
    };
    auto r = run_cli("generate ggx_dfg --size 16x8 -q -o '" + out + "'", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto reference = run_cli("sample '" + out + "/ggx_dfg.exr' --at cos_theta=0.43,alpha=0.31", dir);
    ASSERT_EQ(reference.exit_code, 0) << reference.err;
    for (const auto& [encoding, step] : {std::pair{"unorm8", 1.0 / 255.0}, std::pair{"unorm16", 1.0 / 65535.0}}) {
        SCOPED_TRACE(encoding);
        r = run_cli("generate ggx_dfg --size 16x8 --format png --encoding " + std::string(encoding) + " -q -o '" + out + "'", dir);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const auto s = run_cli("sample '" + out + "/ggx_dfg.png' --at cos_theta=0.43,alpha=0.31", dir);
        ASSERT_EQ(s.exit_code, 0) << s.err;
        for (const char* c : {"R", "G"}) {
            const double got = value_of(s.out, c), want = value_of(reference.out, c);
            EXPECT_LE(std::abs(got - want), 0.5 * step + 1e-7) << c << ": " << s.out;
        }
    }
}
