// Output formats: C++ header, 16-bit PNG, DDS and KTX2, read back field by
// field against their specifications, and the CLI's --format.
#include <gtest/gtest.h>
#include <png.h>
#include <zlib.h>
#include <Imath/half.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <string>
#include <vector>

#include "brdflut/error.h"
#include "brdflut/exr.h"
#include "brdflut/formats.h"
#include "brdflut/table.h"
#include "test_support.h"

using namespace brdflut;
using brdflut::test::read_file;
using brdflut::test::run_cli;
using brdflut::test::TempDir;

namespace {

// A small table with `channels` channels on a width x height grid whose
// values are not exactly representable in half or float.
Table make_table(int channels, int width = 5, int height = 3, std::string id = "fmt_test") {
    Table t;
    t.id = std::move(id);
    Axis x{"cos_theta", 0.0, 1.0, width, Placement::center, Warp::linear};
    t.axes.push_back(x);
    if (height > 1) t.axes.push_back(Axis{"alpha", 0.0, 1.0, height, Placement::endpoints, Warp::square});
    const char* names[4] = {"first", "second", "third", "fourth"};
    for (int c = 0; c < channels; ++c) t.channels.push_back(names[c]);
    t.model = {{"name", "test"}};
    t.method = {{"rule", "none"}};
    const std::size_t n = t.texel_count() * static_cast<std::size_t>(channels);
    for (std::size_t i = 0; i < n; ++i) {
        t.values.push_back(std::fmod(0.1 + 0.37 * static_cast<double>(i) / 3.0, 1.0));
        t.errors.push_back(1e-9);
    }
    return t;
}

// Little-endian reads from a byte string.
std::uint32_t u32(const std::string& b, std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 3; i >= 0; --i) v = v << 8 | static_cast<unsigned char>(b.at(at + static_cast<std::size_t>(i)));
    return v;
}
std::uint64_t u64(const std::string& b, std::size_t at) {
    return static_cast<std::uint64_t>(u32(b, at)) | static_cast<std::uint64_t>(u32(b, at + 4)) << 32;
}
std::uint16_t u16(const std::string& b, std::size_t at) {
    return static_cast<std::uint16_t>(static_cast<unsigned char>(b.at(at)) |
                                      static_cast<unsigned char>(b.at(at + 1)) << 8);
}
float f32(const std::string& b, std::size_t at) {
    const std::uint32_t bits = u32(b, at);
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}
double half_value(std::uint16_t bits) {
    Imath::half h;
    h.setBits(bits);
    return static_cast<double>(static_cast<float>(h));
}

// The stored value of channel c of texel k in packed little-endian texels.
double stored_at(const std::string& b, std::size_t data_at, PixelType p, int stored_channels, std::size_t k,
                 int c) {
    const std::size_t comp = p == PixelType::half ? 2 : 4;
    const std::size_t at = data_at + (k * static_cast<std::size_t>(stored_channels) + static_cast<std::size_t>(c)) * comp;
    return p == PixelType::half ? half_value(u16(b, at)) : static_cast<double>(f32(b, at));
}

// Every stored value equals the table value rounded to the pixel type; a
// padding channel holds 1.
void expect_texels(const std::string& b, std::size_t data_at, const Table& t, PixelType p, int stored_channels) {
    for (std::size_t k = 0; k < t.texel_count(); ++k)
        for (int c = 0; c < stored_channels; ++c) {
            const double want = c < t.channel_count() ? round_to_storage(t.at(k, c), p) : 1.0;
            ASSERT_EQ(stored_at(b, data_at, p, stored_channels, k, c), want) << "texel " << k << " channel " << c;
        }
}

std::vector<std::string> files_in(const std::filesystem::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

struct PngData {
    int width = 0, height = 0, bit_depth = 0, color_type = 0, channels = 0;
    std::vector<std::uint16_t> samples;
    std::vector<std::pair<std::string, std::string>> text;
};

struct PngSource {
    std::string bytes;
    std::size_t at = 0;
};

void read_from_memory(png_structp png, png_bytep data, png_size_t n) {
    auto* src = static_cast<PngSource*>(png_get_io_ptr(png));
    if (src->at + n > src->bytes.size()) png_error(png, "unexpected end of file");
    std::memcpy(data, src->bytes.data() + src->at, n);
    src->at += n;
}

// Reads a 16-bit PNG as stored (no transformations); fails the test on error.
PngData read_png16(const std::string& path) {
    PngData out;
    PngSource src{read_file(path)};
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        ADD_FAILURE() << "libpng could not read " << path;
        return PngData{};
    }
    png_set_read_fn(png, &src, read_from_memory);
    png_read_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
    out.width = static_cast<int>(png_get_image_width(png, info));
    out.height = static_cast<int>(png_get_image_height(png, info));
    out.bit_depth = png_get_bit_depth(png, info);
    out.color_type = png_get_color_type(png, info);
    out.channels = png_get_channels(png, info);
    png_bytepp rows = png_get_rows(png, info);
    for (int y = 0; y < out.height; ++y)
        for (int i = 0; i < out.width * out.channels; ++i)
            out.samples.push_back(static_cast<std::uint16_t>(rows[y][2 * i] << 8 | rows[y][2 * i + 1]));
    png_textp text = nullptr;
    const int n = png_get_text(png, info, &text, nullptr);
    for (int i = 0; i < n; ++i) out.text.emplace_back(text[i].key, text[i].text);
    png_destroy_read_struct(&png, &info, nullptr);
    return out;
}

}  // namespace

// ---------------------------------------------------------------- names

TEST(Formats, NamesAndExtensionsRoundTripAndUnknownNamesListTheAllowed) {
    const std::pair<Format, const char*> cases[] = {
        {Format::exr, "exr"}, {Format::cpp, "h"}, {Format::png16, "png"}, {Format::dds, "dds"}, {Format::ktx2, "ktx2"}};
    for (const auto& [f, ext] : cases) {
        EXPECT_EQ(format_from_string(to_string(f)), f);
        EXPECT_EQ(file_extension(f), ext);
    }
    try {
        format_from_string("tiff");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("'tiff'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("allowed: exr, cpp, png16, png, dds, ktx2"), std::string::npos) << e.what();
    }
    EXPECT_EQ(storage_for(Format::png16, PixelType::float32), Storage::unorm16);
    EXPECT_EQ(storage_for(Format::dds, PixelType::half), Storage::half);
}

// ---------------------------------------------------------------- DDS

TEST(Dds, HeaderFieldsFollowTheSpecificationForEveryChannelCountAndPixelType) {
    TempDir dir;
    struct Case {
        int channels;
        PixelType pixel;
        std::uint32_t dxgi, stored, alpha_mode;
    };
    const Case cases[] = {
        {1, PixelType::half, 54, 1, 0}, {2, PixelType::half, 34, 2, 0}, {3, PixelType::half, 10, 4, 3},
        {4, PixelType::half, 10, 4, 4}, {1, PixelType::float32, 41, 1, 0}, {2, PixelType::float32, 16, 2, 0},
        {3, PixelType::float32, 2, 4, 3}, {4, PixelType::float32, 2, 4, 4},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(std::to_string(c.channels) + " channels, " + std::string(to_string(c.pixel)));
        const Table t = make_table(c.channels, 5, 3);
        const std::string path = dir / "t.dds";
        write_table(path, t, c.pixel, Format::dds);
        const std::string b = read_file(path);
        const std::uint32_t texel_bytes = c.stored * (c.pixel == PixelType::half ? 2 : 4);
        ASSERT_EQ(b.size(), 4u + 124u + 20u + 5u * 3u * texel_bytes);
        EXPECT_EQ(b.substr(0, 4), "DDS ");
        EXPECT_EQ(u32(b, 4), 124u);                                   // dwSize
        EXPECT_EQ(u32(b, 8), 0x1u | 0x2u | 0x4u | 0x8u | 0x1000u | 0x20000u);  // CAPS|HEIGHT|WIDTH|PITCH|PIXELFORMAT|MIPMAPCOUNT
        EXPECT_EQ(u32(b, 12), 3u);                                    // dwHeight
        EXPECT_EQ(u32(b, 16), 5u);                                    // dwWidth
        EXPECT_EQ(u32(b, 20), 5u * texel_bytes);                      // dwPitchOrLinearSize
        EXPECT_EQ(u32(b, 24), 0u);                                    // dwDepth
        EXPECT_EQ(u32(b, 28), 1u);                                    // dwMipMapCount
        for (int i = 0; i < 11; ++i) EXPECT_EQ(u32(b, 32 + 4 * static_cast<std::size_t>(i)), 0u);  // dwReserved1
        EXPECT_EQ(u32(b, 76), 32u);                                   // ddspf.dwSize
        EXPECT_EQ(u32(b, 80), 0x4u);                                  // DDPF_FOURCC
        EXPECT_EQ(b.substr(84, 4), "DX10");
        for (int i = 0; i < 5; ++i) EXPECT_EQ(u32(b, 88 + 4 * static_cast<std::size_t>(i)), 0u);  // bit count, masks
        EXPECT_EQ(u32(b, 108), 0x1000u);                              // DDSCAPS_TEXTURE
        for (int i = 0; i < 4; ++i) EXPECT_EQ(u32(b, 112 + 4 * static_cast<std::size_t>(i)), 0u);
        EXPECT_EQ(u32(b, 128), c.dxgi);                               // dxgiFormat
        EXPECT_EQ(u32(b, 132), 3u);                                   // TEXTURE2D
        EXPECT_EQ(u32(b, 136), 0u);                                   // miscFlag
        EXPECT_EQ(u32(b, 140), 1u);                                   // arraySize
        EXPECT_EQ(u32(b, 144), c.alpha_mode);                         // miscFlags2
        expect_texels(b, 148, t, c.pixel, static_cast<int>(c.stored));
    }
}

TEST(Dds, OneAxisTableIsATwoDimensionalTextureOfHeightOne) {
    TempDir dir;
    const Table t = make_table(1, 7, 1);
    write_table(dir / "t.dds", t, PixelType::float32, Format::dds);
    const std::string b = read_file(dir / "t.dds");
    EXPECT_EQ(u32(b, 12), 1u);
    EXPECT_EQ(u32(b, 16), 7u);
    EXPECT_EQ(u32(b, 132), 3u);
    expect_texels(b, 148, t, PixelType::float32, 1);
}

// A 3-axis table: 4 x 3 x 2 texels, x fastest, then y, then z.
Table make_volume(int channels) {
    Table t = make_table(channels, 4, 3, "fmt_volume");
    t.axes.push_back(Axis{"ior", 1.0, 3.0, 2, Placement::center, Warp::linear});
    t.values.clear();
    t.errors.clear();
    const std::size_t n = t.texel_count() * static_cast<std::size_t>(channels);
    for (std::size_t i = 0; i < n; ++i) {
        t.values.push_back(std::fmod(0.1 + 0.37 * static_cast<double>(i) / 3.0, 1.0));
        t.errors.push_back(1e-9);
    }
    return t;
}

TEST(Dds, ThreeAxisTableIsAVolumeTextureWithItsSlicesInOrder) {
    TempDir dir;
    const Table t = make_volume(3);
    write_table(dir / "v.dds", t, PixelType::half, Format::dds);
    const std::string b = read_file(dir / "v.dds");
    ASSERT_EQ(b.size(), 4u + 124u + 20u + 4u * 3u * 2u * 8u);
    EXPECT_EQ(u32(b, 8), 0x1u | 0x2u | 0x4u | 0x8u | 0x1000u | 0x20000u | 0x800000u);  // ... | DDSD_DEPTH
    EXPECT_EQ(u32(b, 12), 3u);                                    // dwHeight: the second axis
    EXPECT_EQ(u32(b, 16), 4u);                                    // dwWidth
    EXPECT_EQ(u32(b, 20), 4u * 8u);                               // pitch of one row
    EXPECT_EQ(u32(b, 24), 2u);                                    // dwDepth: the third axis
    EXPECT_EQ(u32(b, 108), 0x1000u | 0x8u);                       // DDSCAPS_TEXTURE | DDSCAPS_COMPLEX
    EXPECT_EQ(u32(b, 112), 0x200000u);                            // DDSCAPS2_VOLUME
    EXPECT_EQ(u32(b, 132), 4u);                                   // TEXTURE3D
    EXPECT_EQ(u32(b, 140), 1u);                                   // arraySize
    expect_texels(b, 148, t, PixelType::half, 4);
}

TEST(Ktx2, ThreeAxisTableIsAThreeDimensionalTexture) {
    TempDir dir;
    const Table t = make_volume(1);
    write_table(dir / "v.ktx2", t, PixelType::float32, Format::ktx2);
    const std::string b = read_file(dir / "v.ktx2");
    ASSERT_GE(b.size(), 104u);
    EXPECT_EQ(u32(b, 20), 4u);  // pixelWidth
    EXPECT_EQ(u32(b, 24), 3u);  // pixelHeight: the second axis
    EXPECT_EQ(u32(b, 28), 2u);  // pixelDepth: the third axis
    EXPECT_EQ(u32(b, 32), 0u);  // layerCount
    EXPECT_EQ(u32(b, 40), 1u);  // levelCount
    const std::uint64_t level_offset = u64(b, 80), level_length = u64(b, 88);
    EXPECT_EQ(level_length, 4u * 3u * 2u * 4u);
    ASSERT_EQ(b.size(), level_offset + level_length);
    expect_texels(b, static_cast<std::size_t>(level_offset), t, PixelType::float32, 1);
}

TEST(CppHeader, ThreeAxisTableHasADepthAndSliceMajorData) {
    TempDir dir;
    const Table t = make_volume(2);
    write_table(dir / "v.h", t, PixelType::float32, Format::cpp);
    const std::string h = read_file(dir / "v.h");
    EXPECT_NE(h.find("inline constexpr int width = 4;"), std::string::npos);
    EXPECT_NE(h.find("inline constexpr int height = 3;"), std::string::npos);
    EXPECT_NE(h.find("inline constexpr int depth = 2;"), std::string::npos);
    EXPECT_NE(h.find("data[width * height * depth * channels]"), std::string::npos);
    // A 2-axis table has depth 1.
    write_table(dir / "p.h", make_table(1, 5, 3), PixelType::float32, Format::cpp);
    const std::string p = read_file(dir / "p.h");
    EXPECT_NE(p.find("inline constexpr int height = 3;"), std::string::npos);
    EXPECT_NE(p.find("inline constexpr int depth = 1;"), std::string::npos);
}

// ---------------------------------------------------------------- KTX2

namespace {
struct Ktx2Entry {
    std::string key, value;  // value without its NUL
};

// Parses the key/value data as the spec lays it out, checking the padding.
std::vector<Ktx2Entry> parse_kvd(const std::string& b, std::size_t at, std::size_t length) {
    std::vector<Ktx2Entry> out;
    const std::size_t end = at + length;
    while (at < end) {
        const std::uint32_t n = u32(b, at);
        EXPECT_GE(n, 2u);
        const std::string kv = b.substr(at + 4, n);
        const std::size_t nul = kv.find('\0');
        EXPECT_NE(nul, std::string::npos);
        std::string value = kv.substr(nul + 1);
        EXPECT_FALSE(value.empty());
        EXPECT_EQ(value.back(), '\0') << "string values are NUL-terminated";
        if (!value.empty()) value.pop_back();
        out.push_back({kv.substr(0, nul), value});
        std::size_t next = at + 4 + n;
        while (next % 4 != 0) {
            EXPECT_EQ(b.at(next), '\0') << "valuePadding";
            ++next;
        }
        at = next;
    }
    EXPECT_EQ(at, end);
    return out;
}
}  // namespace

TEST(Ktx2, HeaderIndexAndLevelIndexFollowTheSpecification) {
    TempDir dir;
    struct Case {
        int channels;
        PixelType pixel;
        std::uint32_t vk_format, stored;
    };
    const Case cases[] = {
        {1, PixelType::half, 76, 1},     {2, PixelType::half, 83, 2},     {3, PixelType::half, 97, 4},
        {4, PixelType::half, 97, 4},     {1, PixelType::float32, 100, 1}, {2, PixelType::float32, 103, 2},
        {3, PixelType::float32, 109, 4}, {4, PixelType::float32, 109, 4},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(std::to_string(c.channels) + " channels, " + std::string(to_string(c.pixel)));
        const Table t = make_table(c.channels, 5, 3);
        const std::string path = dir / "t.ktx2";
        write_table(path, t, c.pixel, Format::ktx2);
        const std::string b = read_file(path);
        const std::string id = {'\xAB', 'K', 'T', 'X', ' ', '2', '0', '\xBB', '\r', '\n', '\x1A', '\n'};
        ASSERT_GE(b.size(), 104u);
        EXPECT_EQ(b.substr(0, 12), id);
        const std::uint32_t comp = c.pixel == PixelType::half ? 2 : 4;
        EXPECT_EQ(u32(b, 12), c.vk_format);  // vkFormat
        EXPECT_EQ(u32(b, 16), comp);         // typeSize
        EXPECT_EQ(u32(b, 20), 5u);           // pixelWidth
        EXPECT_EQ(u32(b, 24), 3u);           // pixelHeight
        EXPECT_EQ(u32(b, 28), 0u);           // pixelDepth
        EXPECT_EQ(u32(b, 32), 0u);           // layerCount
        EXPECT_EQ(u32(b, 36), 1u);           // faceCount
        EXPECT_EQ(u32(b, 40), 1u);           // levelCount
        EXPECT_EQ(u32(b, 44), 0u);           // supercompressionScheme
        const std::uint32_t dfd_offset = u32(b, 48), dfd_length = u32(b, 52);
        const std::uint32_t kvd_offset = u32(b, 56), kvd_length = u32(b, 60);
        EXPECT_EQ(dfd_offset, 104u);  // right after the single level index entry
        EXPECT_EQ(dfd_length, 4u + 24u + 16u * c.stored);
        EXPECT_EQ(u32(b, dfd_offset), dfd_length);  // dfdTotalSize == dfdByteLength
        EXPECT_EQ(kvd_offset, dfd_offset + dfd_length);
        EXPECT_EQ(kvd_offset % 4, 0u);
        EXPECT_EQ(u64(b, 64), 0u);  // sgdByteOffset
        EXPECT_EQ(u64(b, 72), 0u);  // sgdByteLength
        const std::uint64_t level_offset = u64(b, 80), level_length = u64(b, 88);
        const std::uint64_t texel_bytes = c.stored * comp;
        EXPECT_EQ(level_length, 5u * 3u * texel_bytes);
        EXPECT_EQ(u64(b, 96), level_length);  // uncompressedByteLength
        // mipPadding: the level starts at the first multiple of
        // lcm(texel block size, 4) after the key/value data.
        const std::uint64_t align = std::lcm(texel_bytes, std::uint64_t{4});
        EXPECT_EQ(level_offset % align, 0u);
        EXPECT_GE(level_offset, kvd_offset + kvd_length);
        EXPECT_LT(level_offset, kvd_offset + kvd_length + align);
        for (std::uint64_t i = kvd_offset + kvd_length; i < level_offset; ++i) EXPECT_EQ(b.at(i), '\0');
        EXPECT_EQ(b.size(), level_offset + level_length);
        expect_texels(b, level_offset, t, c.pixel, static_cast<int>(c.stored));
    }
}

TEST(Ktx2, DataFormatDescriptorIsTheBasicDescriptorOfTheSignedFloatFormat) {
    TempDir dir;
    for (const PixelType p : {PixelType::half, PixelType::float32})
        for (const int channels : {1, 2, 3, 4}) {
            SCOPED_TRACE(std::to_string(channels) + " channels, " + std::string(to_string(p)));
            write_table(dir / "t.ktx2", make_table(channels), p, Format::ktx2);
            const std::string b = read_file(dir / "t.ktx2");
            const std::size_t d = u32(b, 48);
            const std::uint32_t stored = channels == 3 ? 4 : static_cast<std::uint32_t>(channels);
            const std::uint32_t bits = p == PixelType::half ? 16 : 32;
            EXPECT_EQ(u32(b, d + 4) & 0x1FFFFu, 0u);         // vendorId: Khronos
            EXPECT_EQ(u32(b, d + 4) >> 17, 0u);               // descriptorType: basic format
            EXPECT_EQ(u32(b, d + 8) & 0xFFFFu, 2u);           // versionNumber: 1.3
            EXPECT_EQ(u32(b, d + 8) >> 16, 24u + 16u * stored);  // descriptorBlockSize
            const std::uint32_t w2 = u32(b, d + 12);
            EXPECT_EQ(w2 & 0xFFu, 1u);          // colorModel: RGBSDA
            EXPECT_EQ(w2 >> 8 & 0xFFu, 0u);     // colorPrimaries: unspecified (data, not colour)
            EXPECT_EQ(w2 >> 16 & 0xFFu, 1u);    // transferFunction: linear
            EXPECT_EQ(w2 >> 24 & 0xFFu, 0u);    // flags: alpha straight
            EXPECT_EQ(u32(b, d + 16), 0u);      // texelBlockDimension0..3: 1x1x1x1
            EXPECT_EQ(u32(b, d + 20), stored * bits / 8);  // bytesPlane0, planes 1..3 = 0
            EXPECT_EQ(u32(b, d + 24), 0u);                 // bytesPlane4..7
            const std::uint32_t ids[4] = {0, 1, 2, 15};
            for (std::uint32_t s = 0; s < stored; ++s) {
                const std::size_t at = d + 28 + 16 * s;
                const std::uint32_t w = u32(b, at);
                EXPECT_EQ(w & 0xFFFFu, bits * s) << "bitOffset of sample " << s;
                EXPECT_EQ(w >> 16 & 0xFFu, bits - 1) << "bitLength - 1";
                EXPECT_EQ(w >> 24 & 0x0Fu, ids[s]) << "channel id";
                EXPECT_EQ(w >> 24 & 0xF0u, 0xC0u) << "qualifiers: float, signed; not exponent, not linear";
                EXPECT_EQ(u32(b, at + 4), 0u);                 // samplePosition0..3
                EXPECT_EQ(f32(b, at + 8), -1.0f);              // sampleLower
                EXPECT_EQ(f32(b, at + 12), 1.0f);              // sampleUpper
            }
        }
}

TEST(Ktx2, KeyValueDataIsSortedPaddedAndHoldsWriterOrientationAndMetadata) {
    TempDir dir;
    const Table t = make_table(2);
    write_table(dir / "t.ktx2", t, PixelType::half, Format::ktx2);
    const std::string b = read_file(dir / "t.ktx2");
    const auto kv = parse_kvd(b, u32(b, 56), u32(b, 60));
    ASSERT_EQ(kv.size(), 3u);
    EXPECT_EQ(kv[0].key, "KTXorientation");
    EXPECT_EQ(kv[0].value, "rd");
    EXPECT_EQ(kv[1].key, "KTXwriter");
    EXPECT_EQ(kv[1].value, "brdflut 0.1.0");
    EXPECT_EQ(kv[2].key, "brdflut");
    for (std::size_t i = 1; i < kv.size(); ++i) EXPECT_LT(kv[i - 1].key, kv[i].key) << "sorted by code point";
    const auto m = nlohmann::json::parse(kv[2].value);
    EXPECT_EQ(m, metadata_json(t, PixelType::half));
    EXPECT_EQ(m.at("pixel"), "half");
}

// ---------------------------------------------------------------- C++ header

namespace {
// Compiles a program that includes the header and prints every value's bit
// pattern, width, height, channels and the metadata; returns its output.
std::string compile_and_run(const TempDir& dir, const std::string& header, const std::string& ns, bool half) {
    const std::string main_cpp = dir / "main.cpp";
    std::ofstream(main_cpp) << "#include \"" << header << "\"\n"
                            << "#include <cstdio>\n#include <cstring>\n#include <cstdint>\n"
                            << "int main() {\n"
                            << "  namespace lut = " << ns << ";\n"
                            << "  std::printf(\"%d %d %d\\n\", lut::width, lut::height, lut::channels);\n"
                            << "  for (const auto& v : lut::data) {\n"
                            << (half ? "    std::printf(\"%04x\\n\", static_cast<unsigned>(v));\n"
                                     : "    std::uint32_t b; std::memcpy(&b, &v, 4); std::printf(\"%08x\\n\", b);\n")
                            << "  }\n"
                            << "  std::printf(\"%s\", lut::metadata);\n"
                            << "}\n";
    const std::string exe = dir / "prog", log = dir / "compile.txt";
    const std::string cmd = std::string("'") + BRDFLUT_CXX_COMPILER +
                            "' -std=c++17 -Wall -Wextra -pedantic -Werror -o '" + exe + "' '" + main_cpp + "' >'" +
                            log + "' 2>&1";
    const int rc = std::system(cmd.c_str());
    EXPECT_EQ(rc, 0) << read_file(log);
    if (rc != 0) return {};
    const std::string out = dir / "out.txt";
    EXPECT_EQ(std::system(("'" + exe + "' >'" + out + "'").c_str()), 0);
    return read_file(out);
}
}  // namespace

TEST(CppHeader, CompilesWarningFreeAsCpp17AndHoldsEveryStoredValueExactly) {
    TempDir dir;
    for (const PixelType p : {PixelType::float32, PixelType::half}) {
        SCOPED_TRACE(std::string(to_string(p)));
        Table t = make_table(3, 4, 3, "fmt-test");  // '-' is not an identifier character
        t.values[0] = 1.0;       // integral: needs a '.' before the f suffix
        t.values[1] = 1e-30;     // exponent form (0 in half)
        t.values[2] = -0.0;      // sign kept
        t.values[3] = 3.4e38;    // near FLT_MAX (checked only as float)
        if (p == PixelType::half) t.values[3] = 65504.0;
        t.model["note"] = "quotes \" backslash \\ question ?? newline \n tab \t unicode \xc3\xa9";
        const std::string header = dir / "fmt-test.h";
        write_table(header, t, p, Format::cpp);
        const std::string text = read_file(header);
        EXPECT_NE(text.find("C++17"), std::string::npos);
        EXPECT_NE(text.find("namespace brdflut_luts::fmt_test {"), std::string::npos);
        const std::string out = compile_and_run(dir, header, "brdflut_luts::fmt_test", p == PixelType::half);
        ASSERT_FALSE(out.empty());
        std::istringstream in(out);
        int w = 0, h = 0, c = 0;
        in >> w >> h >> c;
        EXPECT_EQ(w, 4);
        EXPECT_EQ(h, 3);
        EXPECT_EQ(c, 3);
        for (std::size_t i = 0; i < t.values.size(); ++i) {
            std::string hex;
            in >> hex;
            const unsigned long bits = std::stoul(hex, nullptr, 16);
            const float f = static_cast<float>(t.values[i]);
            unsigned long want;
            if (p == PixelType::half) {
                want = Imath::half(f).bits();
            } else {
                std::uint32_t b;
                std::memcpy(&b, &f, 4);
                want = b;
            }
            ASSERT_EQ(bits, want) << "value " << i << " = " << t.values[i];
        }
        std::string rest((std::istreambuf_iterator<char>(in >> std::ws)), std::istreambuf_iterator<char>());
        EXPECT_EQ(nlohmann::json::parse(rest), metadata_json(t, p));
    }
}

TEST(CppHeader, IdentifierSchemeGivesValidNamespaceNames) {
    EXPECT_EQ(cpp_identifier("ggx_dfg"), "ggx_dfg");
    EXPECT_EQ(cpp_identifier("fmt-test"), "fmt_test");
    EXPECT_EQ(cpp_identifier("a..b__c"), "a_b_c");    // no reserved "__"
    EXPECT_EQ(cpp_identifier("_x_"), "x");            // no leading '_'
    EXPECT_EQ(cpp_identifier("3d"), "t_3d");          // no leading digit
    EXPECT_EQ(cpp_identifier(""), "t_");
    EXPECT_EQ(cpp_identifier("float"), "float_lut");  // no keyword
}

// ---------------------------------------------------------------- png16

TEST(Png16Table, ChannelsMapToGreyRgbWithZeroBlueRgbAndRgbaWithMetadata) {
    TempDir dir;
    const int color_types[4] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGBA};
    for (int channels = 1; channels <= 4; ++channels) {
        SCOPED_TRACE(std::to_string(channels) + " channels");
        const Table t = make_table(channels, 5, 3);
        write_table(dir / "t.png", t, PixelType::float32, Format::png16);
        const PngData png = read_png16(dir / "t.png");
        EXPECT_EQ(png.width, 5);
        EXPECT_EQ(png.height, 3);
        EXPECT_EQ(png.bit_depth, 16);
        EXPECT_EQ(png.color_type, color_types[channels - 1]);
        const int stored = channels == 2 ? 3 : channels;
        ASSERT_EQ(png.samples.size(), t.texel_count() * static_cast<std::size_t>(stored));
        for (std::size_t k = 0; k < t.texel_count(); ++k)
            for (int c = 0; c < stored; ++c) {
                const std::uint16_t q = png.samples[k * static_cast<std::size_t>(stored) + static_cast<std::size_t>(c)];
                if (c < channels)
                    EXPECT_EQ(q, static_cast<std::uint16_t>(std::lround(t.at(k, c) * 65535.0)));
                else
                    EXPECT_EQ(q, 0) << "blue of a 2-channel table";
            }
        ASSERT_EQ(png.text.size(), 1u);
        EXPECT_EQ(png.text[0].first, "brdflut");
        const auto m = nlohmann::json::parse(png.text[0].second);
        EXPECT_EQ(m.at("pixel"), "unorm16");
        EXPECT_EQ(m.at("channels").size(), static_cast<std::size_t>(channels));
    }
}

TEST(Png16Table, ErrorBoundIsIntegrationErrorPlusTheActualQuantisation) {
    Table t = make_table(2);
    double want = 0.0;
    for (std::size_t i = 0; i < t.values.size(); ++i) {
        const double q = std::lround(t.values[i] * 65535.0) / 65535.0;
        EXPECT_EQ(round_to_storage(t.values[i], Storage::unorm16), q);
        want = std::max(want, t.errors[i] + std::abs(q - t.values[i]));
    }
    EXPECT_EQ(error_bound(t, Storage::unorm16), want);
    EXPECT_LE(want, 0.5 / 65535.0 + 1e-9);
    EXPECT_GT(want, error_bound(t, PixelType::float32));  // the quantisation is counted
    EXPECT_EQ(metadata_json(t, Storage::unorm16).at("error_bound").get<double>(), want);
    // Storage of a PixelType is the same as the PixelType itself.
    EXPECT_EQ(error_bound(t, Storage::half), error_bound(t, PixelType::half));
    EXPECT_EQ(metadata_json(t, Storage::float32), metadata_json(t, PixelType::float32));
}

TEST(Png16Table, RefusesValuesOutsideTheUnitIntervalNamingTableTexelAndValue) {
    TempDir dir;
    const std::string path = dir / "t.png";
    write_table(path, make_table(2), PixelType::float32, Format::png16);
    const std::string before = read_file(path);
    Table t = make_table(2);
    t.values[2 * 6 + 1] = 1.25;  // texel 6 = (x 1, y 1), channel G
    try {
        write_table(path, t, PixelType::float32, Format::png16);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("table 'fmt_test'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("value 1.25"), std::string::npos) << msg;
        EXPECT_NE(msg.find("cos_theta index 1"), std::string::npos) << msg;
        EXPECT_NE(msg.find("alpha index 1"), std::string::npos) << msg;
        EXPECT_NE(msg.find("channel G"), std::string::npos) << msg;
        EXPECT_NE(msg.find("outside [0, 1]"), std::string::npos) << msg;
    }
    EXPECT_EQ(read_file(path), before);
    EXPECT_EQ(files_in(dir.path()), std::vector<std::string>{"t.png"});
}

// ---------------------------------------------------------------- every format

TEST(Formats, EveryFormatWritesAtomicallyAndARefusedTableLeavesTheOldFileUntouched) {
    TempDir dir;
    for (const Format f : {Format::exr, Format::cpp, Format::png16, Format::dds, Format::ktx2}) {
        SCOPED_TRACE(std::string(to_string(f)));
        const std::string name = "t." + file_extension(f);
        const std::string path = dir / name;
        std::ofstream(path) << "previous contents";
        Table bad = make_table(2);
        bad.values[3] = std::nan("");
        try {
            write_table(path, bad, PixelType::float32, f);
            FAIL() << "expected an error";
        } catch (const RuntimeError& e) {
            EXPECT_NE(std::string(e.what()).find("not finite"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("cos_theta index 1"), std::string::npos) << e.what();
        }
        EXPECT_EQ(read_file(path), "previous contents");
        EXPECT_EQ(files_in(dir.path()), std::vector<std::string>{name}) << "no temporary file left";
        write_table(path, make_table(2), PixelType::float32, f);
        EXPECT_NE(read_file(path), "previous contents");
        EXPECT_EQ(files_in(dir.path()), std::vector<std::string>{name}) << "no temporary file left";
        std::filesystem::remove(path);
    }
}

TEST(Formats, HalfRefusesValuesThatOverflowInsteadOfStoringInfinity) {
    TempDir dir;
    Table t = make_table(1);
    t.values[4] = 70000.0;
    for (const Format f : {Format::exr, Format::cpp, Format::dds, Format::ktx2}) {
        SCOPED_TRACE(std::string(to_string(f)));
        try {
            write_table(dir / "t", t, PixelType::half, f);
            FAIL() << "expected an error";
        } catch (const RuntimeError& e) {
            EXPECT_NE(std::string(e.what()).find("does not fit in half"), std::string::npos) << e.what();
        }
        EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
        EXPECT_NO_THROW(write_table(dir / "t", t, PixelType::float32, f));
        std::filesystem::remove(dir / "t");
    }
}

// ---------------------------------------------------------------- CLI

TEST(Cli, GenerateWritesEachFormatUnderItsExtension) {
    TempDir dir;
    for (const char* f : {"exr", "cpp", "png16", "dds", "ktx2"}) {
        const auto r = run_cli("generate ggx_dfg --size 8x4 --format " + std::string(f) + " -o '" +
                                   dir.path().string() + "'",
                               dir);
        ASSERT_EQ(r.exit_code, 0) << f << "\n" << r.err;
    }
    for (const char* name : {"ggx_dfg.exr", "ggx_dfg.h", "ggx_dfg.png", "ggx_dfg.dds", "ggx_dfg.ktx2"})
        EXPECT_TRUE(std::filesystem::is_regular_file(dir / name)) << name;
    const std::string dds = read_file(dir / "ggx_dfg.dds");
    EXPECT_EQ(u32(dds, 128), 16u);  // R32G32_FLOAT: the default pixel type is float
    EXPECT_EQ(u32(dds, 16), 8u);
    EXPECT_EQ(u32(dds, 12), 4u);
    const PngData png = read_png16(dir / "ggx_dfg.png");
    ASSERT_EQ(png.text.size(), 1u);
    const auto m = nlohmann::json::parse(png.text[0].second);
    EXPECT_EQ(m.at("table"), "ggx_dfg");
    EXPECT_GT(m.at("error_bound").get<double>(), 1e-7);   // the 16-bit quantisation, not float's
    EXPECT_LE(m.at("error_bound").get<double>(), 1e-5);
    // The EXR and the DDS hold the same floats.
    const ExrImage exr = read_exr(dir / "ggx_dfg.exr");
    for (std::size_t i = 0; i < exr.pixels.size(); ++i) EXPECT_EQ(static_cast<double>(f32(dds, 148 + 4 * i)), exr.pixels[i]);
}

TEST(Cli, BadFormatRequestsAreUsageErrorsAndWriteNothing) {
    TempDir dir;
    const std::string out = dir / "o";
    auto r = run_cli("generate ggx_dfg --size 4 --format tiff -o '" + out + "'", dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("allowed: exr, cpp, png16, png, dds, ktx2"), std::string::npos) << r.err;
    r = run_cli("generate ggx_dfg --size 4 --format png16 --pixel half -o '" + out + "'", dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("--pixel half"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out) && !std::filesystem::is_empty(out));
}

TEST(Cli, Png16OfATableWithValuesAboveOneIsRefusedWithExitTwoAndNoFile) {
    TempDir dir;
    const std::string out = dir / "o";
    // The Burley diffuse albedo exceeds 1 for rough surfaces at grazing angles.
    const auto r = run_cli("generate disney_diffuse_albedo --size 8 --format png16 -o '" + out + "'", dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("table 'disney_diffuse_albedo'"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("is outside [0, 1]"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("texel ("), std::string::npos) << r.err;
    EXPECT_TRUE(std::filesystem::is_empty(out)) << "no file, not even a temporary one";
}

TEST(Cli, Png16OfSeveralTablesWritesNoneWhenALaterOneIsRefused) {
    TempDir dir;
    const std::string out = dir / "o";
    // ggx_dfg fits in [0, 1]; the Burley diffuse albedo, named after it, does not.
    const auto r =
        run_cli("generate ggx_dfg disney_diffuse_albedo --size 8 --format png16 -o '" + out + "'", dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("table 'disney_diffuse_albedo'"), std::string::npos) << r.err;
    EXPECT_TRUE(std::filesystem::is_empty(out)) << "ggx_dfg.png was written before the refusal";
}

// ---------------------------------------------------------------- reading back

TEST(ReadTableImage, ReadsEveryBinaryFormatBackToTheStoredValuesAndMetadata) {
    TempDir dir;
    for (const Format f : {Format::exr, Format::png16, Format::dds, Format::ktx2})
        for (const PixelType p : {PixelType::half, PixelType::float32})
            for (const int channels : {1, 2, 3, 4}) {
                if (f == Format::png16 && p == PixelType::half) continue;
                SCOPED_TRACE(std::string(to_string(f)) + " " + std::string(to_string(p)) + " " +
                             std::to_string(channels));
                const Table t = make_table(channels, 5, 3);
                const std::string path = dir / ("t." + file_extension(f));
                write_table(path, t, p, f);
                const ExrImage img = read_table_image(path);
                EXPECT_EQ(img.width, 5);
                EXPECT_EQ(img.height, 3);
                const Storage s = storage_for(f, p);
                const int stored = static_cast<int>(img.channel_names.size());
                ASSERT_GE(stored, channels);
                for (std::size_t k = 0; k < t.texel_count(); ++k)
                    for (int c = 0; c < channels; ++c)
                        ASSERT_NEAR(img.pixels[k * static_cast<std::size_t>(stored) + static_cast<std::size_t>(c)],
                                    round_to_storage(t.at(k, c), s), s == Storage::unorm16 ? 1e-15 : 0.0)
                            << "texel " << k << " channel " << c;
                if (f == Format::dds) {
                    EXPECT_FALSE(img.has_metadata);
                } else {
                    ASSERT_TRUE(img.has_metadata);
                    EXPECT_EQ(img.metadata, metadata_json(t, s));
                }
            }
}

TEST(ReadTableImage, UnknownOrTruncatedFilesAreClearErrors) {
    TempDir dir;
    std::ofstream(dir / "x.txt") << "hello";
    EXPECT_THROW(read_table_image(dir / "x.txt"), RuntimeError);
    EXPECT_THROW(read_table_image(dir / "missing.ktx2"), RuntimeError);
    write_table(dir / "t.ktx2", make_table(2), PixelType::half, Format::ktx2);
    const std::string b = read_file(dir / "t.ktx2");
    std::ofstream(dir / "cut.ktx2", std::ios::binary) << b.substr(0, b.size() - 10);
    try {
        read_table_image(dir / "cut.ktx2");
        FAIL() << "expected an error";
    } catch (const RuntimeError& e) {
        EXPECT_NE(std::string(e.what()).find("cut.ktx2"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
    }
}

namespace {
void append_to_string(png_structp png, png_bytep data, png_size_t n) {
    static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), n);
}
}  // namespace

// A 16-bit PNG from another tool: interlaced (Adam7), with its metadata text
// after the image data. Both are legal, and brdflut's own writer uses neither.
TEST(ReadTableImage, ReadsInterlacedPng16WithTextAfterTheImage) {
    constexpr int kW = 7, kH = 5, kC = 3;
    std::vector<std::uint16_t> v(kW * kH * kC);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<std::uint16_t>((i * 977 + 13) % 65536);
    std::vector<png_byte> bytes(v.size() * 2);
    for (std::size_t i = 0; i < v.size(); ++i) {
        bytes[2 * i] = static_cast<png_byte>(v[i] >> 8);
        bytes[2 * i + 1] = static_cast<png_byte>(v[i] & 0xff);
    }
    std::vector<png_bytep> rows(kH);
    for (int y = 0; y < kH; ++y) rows[static_cast<std::size_t>(y)] = bytes.data() + y * kW * kC * 2;
    std::string file;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    ASSERT_FALSE(setjmp(png_jmpbuf(png)));
    png_set_write_fn(png, &file, append_to_string, nullptr);
    png_set_IHDR(png, info, kW, kH, 16, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_ADAM7, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    png_write_image(png, rows.data());
    char key[] = "brdflut", value[] = "{\"table\":\"foreign\"}";
    png_text text{};
    text.compression = PNG_TEXT_COMPRESSION_NONE;
    text.key = key;
    text.text = value;
    png_set_text(png, info, &text, 1);  // written by png_write_end, after IDAT
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    ASSERT_LT(file.find("IDAT"), file.find("tEXt"));

    TempDir dir;
    std::ofstream(dir / "foreign.png", std::ios::binary) << file;
    const ExrImage img = read_table_image(dir / "foreign.png");
    EXPECT_EQ(img.width, kW);
    EXPECT_EQ(img.height, kH);
    ASSERT_EQ(img.pixels.size(), v.size());
    for (std::size_t i = 0; i < v.size(); ++i) EXPECT_EQ(img.pixels[i], v[i] / 65535.0) << i;
    ASSERT_TRUE(img.has_metadata);
    EXPECT_EQ(img.metadata.at("table"), "foreign");
}

namespace {
void put_u32(std::string& b, std::size_t at, std::uint32_t v, bool big_endian = false) {
    for (int i = 0; i < 4; ++i)
        b[at + static_cast<std::size_t>(i)] = static_cast<char>(v >> (8 * (big_endian ? 3 - i : i)) & 0xff);
}
}  // namespace

// A header that declares more pixels than any table is refused from the
// header, by the same limit in every format (the EXR reader's is tested in
// test_tables.cpp), before the texels are read or decoded.
TEST(ReadTableImage, HeadersDeclaringMoreThanAnyTableAreRefusedWithTheLimit) {
    TempDir dir;
    const std::string limit = "the image is 65535x65535 pixels with 4 channel(s); supported are at most 67108864 "
                              "pixels, 64 channels and 268435456 values";
    for (const Format f : {Format::dds, Format::ktx2, Format::png16}) {
        SCOPED_TRACE(to_string(f));
        const std::string path = dir / ("t." + file_extension(f));
        write_table(path, make_table(4, 5, 3), PixelType::float32, f);
        std::string b = read_file(path);
        if (f == Format::dds) {  // dwHeight at 12, dwWidth at 16
            put_u32(b, 12, 65535);
            put_u32(b, 16, 65535);
        } else if (f == Format::ktx2) {  // pixelWidth at 20, pixelHeight at 24
            put_u32(b, 20, 65535);
            put_u32(b, 24, 65535);
        } else {  // IHDR: width at 16, height at 20 (big-endian), CRC of type and data at 29
            ASSERT_EQ(b.compare(12, 4, "IHDR"), 0);
            put_u32(b, 16, 65535, true);
            put_u32(b, 20, 65535, true);
            put_u32(b, 29, static_cast<std::uint32_t>(crc32(0, reinterpret_cast<const Bytef*>(b.data() + 12), 17)),
                    true);
        }
        std::ofstream(path, std::ios::binary) << b;
        try {
            read_table_image(path);
            FAIL() << "expected an error";
        } catch (const RuntimeError& e) {
            EXPECT_NE(std::string(e.what()).find(limit), std::string::npos) << e.what();
        }
    }
}

TEST(Cli, CompareAndInspectReadKtx2AndPng16Files) {
    TempDir dir;
    for (const char* f : {"ktx2", "png16"}) {
        auto r = run_cli("generate ggx_dfg --size 8 --format " + std::string(f) + " -o '" + dir.path().string() + "'",
                         dir);
        ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    for (const char* name : {"ggx_dfg.ktx2", "ggx_dfg.png"}) {
        auto r = run_cli("compare '" + (dir / name) + "' --json", dir);
        ASSERT_EQ(r.exit_code, 0) << name << "\n" << r.err;
        const auto j = nlohmann::json::parse(r.out);
        EXPECT_EQ(j.at("table"), "ggx_dfg") << r.out;
        r = run_cli("inspect '" + (dir / name) + "' --json", dir);
        ASSERT_EQ(r.exit_code, 0) << name << "\n" << r.err;
        const auto info = nlohmann::json::parse(r.out);
        EXPECT_EQ(info.at("metadata").at("table"), "ggx_dfg");
        // The file's own sample type, which is the metadata's too.
        EXPECT_EQ(info.at("pixel"), info.at("metadata").at("pixel")) << name;
    }
}
