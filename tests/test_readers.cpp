// Readers that look before they read, and the readers of engines' tables:
// NumPy .npy, PNG of any kind, 3-D DDS and KTX2 textures, and arrays in
// C, C++, GLSL, HLSL and JavaScript sources.
#include <gtest/gtest.h>
#include <png.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <algorithm>
#include <cstring>
#include <fstream>

#include "brdflut/error.h"
#include "brdflut/formats.h"
#include "io/image_limits.h"
#include "test_support.h"

extern char** environ;

using namespace brdflut;
using brdflut::test::read_file;
using brdflut::test::run_cli;
using brdflut::test::TempDir;

namespace {

void write(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// The error message of read_table_image, or "" when it read the file.
std::string read_error(const std::string& path, const ReadOptions& opt = {}) {
    try {
        read_table_image(path, opt);
    } catch (const RuntimeError& e) {
        return e.what();
    }
    return "";
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// Runs the tool (no shell) and returns its exit code, peak resident memory
// (KiB) and wall time (s) from wait4.
struct Child {
    int exit_code = -1;
    long max_rss_kib = 0;
    double seconds = 0;
};
Child run_measured(std::vector<std::string> args) {
    args.insert(args.begin(), BRDFLUT_CLI);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
    const auto t0 = std::chrono::steady_clock::now();
    pid_t pid = 0;
    Child c;
    if (posix_spawn(&pid, BRDFLUT_CLI, &fa, nullptr, argv.data(), environ) != 0) return c;
    int status = 0;
    struct rusage ru{};
    wait4(pid, &status, 0, &ru);
    c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    posix_spawn_file_actions_destroy(&fa);
    c.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    c.max_rss_kib = ru.ru_maxrss;
    return c;
}

}  // namespace

// ------------------------------------------------------------ look before reading

TEST(LookBeforeReading, AFifoIsRefusedAtOnceWithoutWaitingForAWriter) {
    TempDir dir;
    const std::string fifo = dir / "table.exr";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    // Nothing writes the FIFO. Under `timeout`, so that a reader that waits
    // for a writer fails the test (exit 124) instead of hanging it.
    const auto t0 = std::chrono::steady_clock::now();
    const std::string cmd = "timeout 10 '" + std::string(BRDFLUT_CLI) + "' inspect '" + fifo + "' 2>'" + (dir / "err.txt") +
                            "' </dev/null";
    const int status = std::system(cmd.c_str());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const std::string err = read_file(dir / "err.txt");
    ASSERT_TRUE(WIFEXITED(status));
    ASSERT_EQ(WEXITSTATUS(status), 1) << err;
    EXPECT_LT(seconds, 5.0);
    EXPECT_TRUE(contains(err, "cannot read '" + fifo + "': not a regular file (a FIFO)")) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    // The library call, now known not to block.
    EXPECT_TRUE(contains(read_error(fifo), "FIFO"));
}

TEST(LookBeforeReading, DevZeroAndADirectoryAreRefusedAsNotRegularFiles) {
    EXPECT_TRUE(contains(read_error("/dev/zero"), "cannot read '/dev/zero': not a regular file (a character device)"))
        << read_error("/dev/zero");
    const Child c = run_measured({"inspect", "/dev/zero"});
    EXPECT_EQ(c.exit_code, 1);
    EXPECT_LT(c.seconds, 5.0);
    EXPECT_LT(c.max_rss_kib, 200 * 1024);
    TempDir dir;
    EXPECT_TRUE(contains(read_error(dir.path().string()), "not a regular file (a directory)"));
    EXPECT_TRUE(contains(read_error(dir / "missing.npy"), "no such file"));
    // read_exr() looks the same way.
    try {
        read_exr("/dev/zero");
        FAIL() << "expected an error";
    } catch (const RuntimeError& e) {
        EXPECT_TRUE(contains(e.what(), "character device")) << e.what();
    }
}

// A sparse file: 200 MB of zeros that take no disk. The first bytes are no
// format's, so it is refused from them; the tool's peak memory shows it was
// not read whole.
TEST(LookBeforeReading, ALargeFileOfZerosNamedExrIsRefusedFromItsFirstBytes) {
    TempDir dir;
    const std::string path = dir / "zeros.exr";
    { std::ofstream(path, std::ios::binary); }
    ASSERT_EQ(truncate(path.c_str(), 200LL << 20), 0);
    const std::string err = read_error(path);
    EXPECT_TRUE(contains(err, "not an OpenEXR, DDS, KTX2, PNG or NumPy .npy file")) << err;
    try {
        read_exr(path);
        FAIL() << "expected an error";
    } catch (const RuntimeError& e) {
        EXPECT_TRUE(contains(e.what(), "not the OpenEXR magic number")) << e.what();
    }
    const Child c = run_measured({"inspect", path});
    EXPECT_EQ(c.exit_code, 1);
    EXPECT_LT(c.max_rss_kib, 150 * 1024) << "the tool held " << c.max_rss_kib << " KiB";
    // With --array it would be a source file: refused for its NUL bytes, also from the first bytes.
    ReadOptions opt;
    opt.array = "lut";
    EXPECT_TRUE(contains(read_error(path, opt), "not a text file")) << read_error(path, opt);
}

TEST(LookBeforeReading, FilesLargerThanTheirKindsLimitAreRefusedFromTheirSize) {
    TempDir dir;
    // A binary file: the OpenEXR magic, then zeros to 1 GiB + 1 (sparse).
    const std::string big = dir / "big.exr";
    write(big, std::string("\x76\x2f\x31\x01", 4));
    ASSERT_EQ(truncate(big.c_str(), static_cast<off_t>(kMaxBinaryFileBytes + 1)), 0);
    EXPECT_TRUE(contains(read_error(big), "the file is 1073741825 bytes; at most 1073741824 bytes are read for a binary file"))
        << read_error(big);
    EXPECT_TRUE(contains(read_error(dir / "big.exr"), "big.exr"));
    // A source file: text, then zeros to 64 MiB + 1.
    const std::string src = dir / "big.c";
    write(src, "static const float lut[] = {1.0f, 2.0f};\n");
    ASSERT_EQ(truncate(src.c_str(), static_cast<off_t>(kMaxTextFileBytes + 1)), 0);
    ReadOptions opt;
    opt.array = "lut";
    EXPECT_TRUE(contains(read_error(src, opt), "at most 67108864 bytes are read for a source file")) << read_error(src, opt);
    const Child c = run_measured({"inspect", src, "--array", "lut"});
    EXPECT_EQ(c.exit_code, 1);
    EXPECT_LT(c.max_rss_kib, 150 * 1024);
}

// --------------------------------------------------------------------- NumPy

namespace {

// A .npy file: magic, version, header length, the header dict padded with
// spaces to a multiple of 64 bytes and ended by '\n', then the data.
std::string npy(const std::string& descr, const std::string& shape, const std::string& data, int major = 1,
                bool fortran = false) {
    std::string header = "{'descr': '" + descr + "', 'fortran_order': " + (fortran ? "True" : "False") +
                         ", 'shape': " + shape + ", }";
    const std::size_t prefix = major == 1 ? 10 : 12;
    while ((prefix + header.size() + 1) % 64 != 0) header += ' ';
    header += '\n';
    std::string out = std::string("\x93NUMPY", 6) + static_cast<char>(major) + '\0';
    const std::size_t n = header.size();
    out += static_cast<char>(n & 0xff);
    out += static_cast<char>(n >> 8 & 0xff);
    if (major > 1) out += std::string(2, '\0');
    return out + header + data;
}

template <class T>
std::string bytes_of(const std::vector<T>& v, bool big_endian = false) {
    std::string out;
    for (const T& x : v) {
        char b[sizeof(T)];
        std::memcpy(b, &x, sizeof(T));
        if (big_endian) std::reverse(b, b + sizeof(T));
        out.append(b, sizeof(T));
    }
    return out;
}

}  // namespace

TEST(NpyReader, FloatArraysOfEveryWidthAndByteOrderReadExactlyWithTheirShape) {
    TempDir dir;
    const std::vector<float> f4 = {0.5f, -1.25f, 3e-5f, 1.0f, 0.0f, 7.0f};
    write(dir / "f4.npy", npy("<f4", "(2, 3)", bytes_of(f4)));
    ExrImage img = read_table_image(dir / "f4.npy");
    EXPECT_EQ(img.width, 3);
    EXPECT_EQ(img.height, 2);
    EXPECT_EQ(img.depth, 1);
    ASSERT_EQ(img.channel_names.size(), 1u);
    for (std::size_t i = 0; i < f4.size(); ++i) EXPECT_EQ(img.pixels[i], f4[i]) << i;

    // (H, W, C), big-endian doubles, version 2 header.
    std::vector<double> f8(2 * 2 * 3);
    for (std::size_t i = 0; i < f8.size(); ++i) f8[i] = 0.1 * static_cast<double>(i) - 0.3;
    write(dir / "f8.npy", npy(">f8", "(2, 2, 3)", bytes_of(f8, true), 2));
    img = read_table_image(dir / "f8.npy");
    EXPECT_EQ(img.width, 2);
    EXPECT_EQ(img.height, 2);
    EXPECT_EQ(img.channel_names, (std::vector<std::string>{"R", "G", "B"}));
    for (std::size_t i = 0; i < f8.size(); ++i) EXPECT_EQ(img.pixels[i], f8[i]) << i;

    // Half floats, version 3, a 1-D shape.
    const std::vector<std::uint16_t> f2 = {0x3C00, 0xC000, 0x3555};  // 1, -2, 0.333251953125
    write(dir / "f2.npy", npy("<f2", "(3,)", bytes_of(f2), 3));
    img = read_table_image(dir / "f2.npy");
    EXPECT_EQ(img.width, 3);
    EXPECT_EQ(img.height, 1);
    EXPECT_EQ(img.pixel, PixelType::half);
    EXPECT_EQ(img.pixels, (std::vector<double>{1.0, -2.0, 0.333251953125}));
}

TEST(NpyReader, IntegerArraysAreUnormAndA4dShapeStacksItsSlicesAsRows) {
    TempDir dir;
    // (D, H, W, C) = (2, 3, 2, 2) of u1: value at (z, y, x, c) = 10 z + 4 y + 2 x + c.
    std::string u1;
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 2; ++x)
                for (int c = 0; c < 2; ++c) u1 += static_cast<char>(10 * z + 4 * y + 2 * x + c);
    write(dir / "u1.npy", npy("|u1", "(2, 3, 2, 2)", u1));
    ExrImage img = read_table_image(dir / "u1.npy");
    EXPECT_EQ(img.width, 2);
    EXPECT_EQ(img.height, 6);
    EXPECT_EQ(img.depth, 2);
    EXPECT_TRUE(img.is_unorm8());
    // Row z * 3 + y, column x, channel c.
    const auto at = [&](int z, int y, int x, int c) { return img.pixels[static_cast<std::size_t>(((z * 3 + y) * 2 + x) * 2 + c)]; };
    EXPECT_EQ(at(1, 2, 1, 1), (10 + 8 + 2 + 1) / 255.0);
    EXPECT_EQ(at(0, 1, 0, 0), 4 / 255.0);
    // u2, big-endian: q / 65535.
    write(dir / "u2.npy", npy(">u2", "(1, 2)", std::string("\xff\xff\x12\x34", 4)));
    img = read_table_image(dir / "u2.npy");
    EXPECT_TRUE(img.is_unorm16());
    EXPECT_EQ(img.pixels, (std::vector<double>{1.0, 0x1234 / 65535.0}));
    // A given shape reinterprets the numbers: (12,) as 2x3:2.
    write(dir / "flat.npy", npy("|u1", "(12,)", u1.substr(0, 12)));
    ReadOptions opt;
    opt.shape = parse_array_shape("2x3:2");
    img = read_table_image(dir / "flat.npy", opt);
    EXPECT_EQ(img.width, 2);
    EXPECT_EQ(img.height, 3);
    EXPECT_EQ(img.channel_names.size(), 2u);
}

TEST(NpyReader, UnsupportedOrDamagedFilesAreOneLineErrorsNamingTheProblem) {
    TempDir dir;
    const std::string four(16, '\0');
    const struct {
        std::string bytes, expect;
    } cases[] = {
        {npy("<i4", "(2, 2)", four), "dtype '<i4' is not read; allowed: f2, f4, f8, u1, u2"},
        {npy("<f4", "(2, 2)", four, 1, true), "Fortran order"},
        {npy("<f4", "(2, 3)", four), "the array data is truncated: shape (2, 3) of '<f4' needs 24 bytes, the file has 16"},
        {npy("<f4", "(2, 1)", four), "8 bytes after the array data"},
        {npy("<f4", "()", four), "a scalar"},
        {npy("<f4", "(2, 2, 2, 2, 2)", four), "do not form an image"},
        {npy("<f4", "(2, 2, 8)", four), "truncated"},  // (D, H, W) = (2, 2, 8): 32 values
        {npy("<f4", "(65535, 65535, 4)", four), "holds more than the 268435456 values"},
        {std::string("\x93NUMPY\x04\x00", 8) + "xx", "version 4.0 is not read"},
        {npy("<f4", "(2, 2)", "").substr(0, 30), "header is truncated"},
    };
    for (const auto& c : cases) {
        write(dir / "bad.npy", c.bytes);
        const std::string err = read_error(dir / "bad.npy");
        EXPECT_TRUE(contains(err, c.expect)) << "expected: " << c.expect << "\n got: " << err;
        EXPECT_TRUE(contains(err, "cannot read '" + (dir / "bad.npy") + "'")) << err;
        EXPECT_EQ(err.find('\n'), std::string::npos) << err;
    }
}

// ----------------------------------------------------------------------- PNG

namespace {
void append_png(png_structp png, png_bytep data, png_size_t n) {
    static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), n);
}

// A PNG of the given colour type and bit depth from raw sample bytes (16-bit
// samples big-endian), optionally with a palette and a brdflut text chunk.
std::string make_png(int w, int h, int color, int bits, const std::vector<png_byte>& samples,
                     const std::vector<png_color>& palette = {}, const std::string& metadata = "") {
    std::string file;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return {};
    }
    png_set_write_fn(png, &file, append_png, nullptr);
    png_set_IHDR(png, info, static_cast<png_uint_32>(w), static_cast<png_uint_32>(h), bits, color, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (!palette.empty()) png_set_PLTE(png, info, palette.data(), static_cast<int>(palette.size()));
    char key[] = "brdflut";
    std::string value = metadata;
    png_text text{};
    if (!metadata.empty()) {
        text.compression = PNG_TEXT_COMPRESSION_NONE;
        text.key = key;
        text.text = value.data();
        png_set_text(png, info, &text, 1);
    }
    png_write_info(png, info);
    const std::size_t row = samples.size() / static_cast<std::size_t>(h);
    for (int y = 0; y < h; ++y) png_write_row(png, samples.data() + static_cast<std::size_t>(y) * row);
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return file;
}

double srgb_eotf_oracle(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }
}  // namespace

TEST(PngReader, EightBitImagesOfEveryColourTypeReadAsQOver255WithLinearDecoding) {
    TempDir dir;
    ReadOptions linear;
    linear.decode = Decode::linear;
    const struct {
        int color, channels;
    } kinds[] = {{PNG_COLOR_TYPE_GRAY, 1}, {PNG_COLOR_TYPE_GRAY_ALPHA, 2}, {PNG_COLOR_TYPE_RGB, 3}, {PNG_COLOR_TYPE_RGBA, 4}};
    for (const auto& k : kinds) {
        SCOPED_TRACE(k.channels);
        std::vector<png_byte> s(static_cast<std::size_t>(3 * 2 * k.channels));
        for (std::size_t i = 0; i < s.size(); ++i) s[i] = static_cast<png_byte>(i * 37 + 5);
        write(dir / "t.png", make_png(3, 2, k.color, 8, s));
        // No metadata and no decoding given: refused, naming the choice.
        EXPECT_TRUE(contains(read_error(dir / "t.png"), "a PNG without brdflut metadata needs a decoding: --decode linear"))
            << read_error(dir / "t.png");
        const ExrImage img = read_table_image(dir / "t.png", linear);
        EXPECT_EQ(img.width, 3);
        EXPECT_EQ(img.height, 2);
        EXPECT_TRUE(img.is_unorm8());
        ASSERT_EQ(img.channel_names.size(), static_cast<std::size_t>(k.channels));
        ASSERT_EQ(img.pixels.size(), s.size());
        for (std::size_t i = 0; i < s.size(); ++i) EXPECT_EQ(img.pixels[i], s[i] / 255.0) << i;
    }
}

TEST(PngReader, SrgbDecodingAppliesTheExactEotfToColourButNotAlpha) {
    TempDir dir;
    const std::vector<png_byte> s = {0, 10, 128, 255, 200, 3, 77, 64};  // two RGBA texels
    write(dir / "t.png", make_png(2, 1, PNG_COLOR_TYPE_RGBA, 8, s));
    ReadOptions srgb;
    srgb.decode = Decode::srgb;
    const ExrImage img = read_table_image(dir / "t.png", srgb);
    ASSERT_EQ(img.pixels.size(), s.size());
    for (std::size_t i = 0; i < s.size(); ++i) {
        const double q = s[i] / 255.0;
        EXPECT_DOUBLE_EQ(img.pixels[i], i % 4 == 3 ? q : srgb_eotf_oracle(q)) << i;
    }
    EXPECT_DOUBLE_EQ(img.pixels[1], 10.0 / 255.0 / 12.92);                      // the linear segment
    EXPECT_NEAR(img.pixels[2], 0.2158605, 1e-7);  // 128: the power segment (published sRGB tables)
    // 16-bit grey: q / 65535, then the EOTF.
    write(dir / "g16.png", make_png(2, 1, PNG_COLOR_TYPE_GRAY, 16, {0x80, 0x00, 0x00, 0x10}));
    const ExrImage g = read_table_image(dir / "g16.png", srgb);
    EXPECT_TRUE(g.is_unorm16());
    EXPECT_DOUBLE_EQ(g.pixels[0], srgb_eotf_oracle(0x8000 / 65535.0));
    EXPECT_DOUBLE_EQ(g.pixels[1], 16 / 65535.0 / 12.92);
    // On float data the sRGB decoding is refused.
    write(dir / "f.npy", npy("<f4", "(1,)", bytes_of(std::vector<float>{0.5f})));
    EXPECT_TRUE(contains(read_error(dir / "f.npy", srgb), "--decode srgb applies to 8- and 16-bit integer samples"));
}

TEST(PngReader, PalettesAndLowBitGreyAreExpandedAndBrdflutMetadataNeedsNoDecoding) {
    TempDir dir;
    const std::vector<png_color> palette = {{10, 20, 30}, {200, 100, 0}};
    write(dir / "p.png", make_png(3, 1, PNG_COLOR_TYPE_PALETTE, 8, {1, 0, 1}, palette));
    ReadOptions linear;
    linear.decode = Decode::linear;
    ExrImage img = read_table_image(dir / "p.png", linear);
    ASSERT_EQ(img.channel_names.size(), 3u);
    EXPECT_EQ(img.pixels, (std::vector<double>{200 / 255.0, 100 / 255.0, 0.0, 10 / 255.0, 20 / 255.0, 30 / 255.0,
                                               200 / 255.0, 100 / 255.0, 0.0}));
    // 2-bit grey: q in 0..3 expands to q * 85 of 255.
    write(dir / "g2.png", make_png(4, 1, PNG_COLOR_TYPE_GRAY, 2, {0x1B}));  // 00 01 10 11
    img = read_table_image(dir / "g2.png", linear);
    EXPECT_EQ(img.pixels, (std::vector<double>{0.0, 85 / 255.0, 170 / 255.0, 1.0}));
    // An 8-bit PNG with brdflut metadata reads without --decode.
    write(dir / "m.png", make_png(1, 1, PNG_COLOR_TYPE_GRAY, 8, {51}, {}, "{\"table\":\"x\"}"));
    img = read_table_image(dir / "m.png");
    EXPECT_TRUE(img.has_metadata);
    EXPECT_EQ(img.pixels, (std::vector<double>{0.2}));
}

// --------------------------------------------------------- 3-D DDS and KTX2

namespace {
void put32(std::string& b, std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) b[at + static_cast<std::size_t>(i)] = static_cast<char>(v >> (8 * i) & 0xff);
}
void put64(std::string& b, std::size_t at, std::uint64_t v) {
    for (int i = 0; i < 8; ++i) b[at + static_cast<std::size_t>(i)] = static_cast<char>(v >> (8 * i) & 0xff);
}
// Float texels of a w x h x d texture: value (z, y, x) = 100 z + 10 y + x.
std::string volume_texels(int w, int h, int d) {
    std::vector<float> v;
    for (int z = 0; z < d; ++z)
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) v.push_back(static_cast<float>(100 * z + 10 * y + x));
    return bytes_of(v);
}
// DDS (Microsoft "DDS_HEADER", "DDS_HEADER_DXT10"): a DX10 R32_FLOAT volume.
std::string dds_volume(int w, int h, int d, bool depth_flag = true) {
    std::string b(148, '\0');
    b.replace(0, 4, "DDS ");
    put32(b, 4, 124);
    put32(b, 8, 0x1 | 0x2 | 0x4 | 0x8 | 0x1000 | 0x20000 | (depth_flag ? 0x800000 : 0));  // ... | DDSD_DEPTH
    put32(b, 12, static_cast<std::uint32_t>(h));
    put32(b, 16, static_cast<std::uint32_t>(w));
    put32(b, 20, static_cast<std::uint32_t>(w * 4));
    put32(b, 24, static_cast<std::uint32_t>(d));  // dwDepth
    put32(b, 28, 1);                              // dwMipMapCount
    put32(b, 76, 32);
    put32(b, 80, 0x4);  // DDPF_FOURCC
    b.replace(84, 4, "DX10");
    put32(b, 108, 0x1000);     // DDSCAPS_TEXTURE
    put32(b, 112, 0x200000);   // DDSCAPS2_VOLUME
    put32(b, 128, 41);         // DXGI_FORMAT_R32_FLOAT
    put32(b, 132, 4);          // D3D10_RESOURCE_DIMENSION_TEXTURE3D
    put32(b, 140, 1);          // arraySize
    return b + volume_texels(w, h, d);
}
// KTX 2.0 ("File Structure"): VK_FORMAT_R32_SFLOAT, pixelDepth d, one level.
std::string ktx2_volume(int w, int h, int d) {
    std::string b(104, '\0');
    b.replace(0, 12, std::string("\xABKTX 20\xBB\r\n\x1A\n", 12));
    put32(b, 12, 100);  // vkFormat
    put32(b, 16, 4);    // typeSize
    put32(b, 20, static_cast<std::uint32_t>(w));
    put32(b, 24, static_cast<std::uint32_t>(h));
    put32(b, 28, static_cast<std::uint32_t>(d));  // pixelDepth
    put32(b, 36, 1);                              // faceCount
    put32(b, 40, 1);                              // levelCount
    const std::string texels = volume_texels(w, h, d);
    put64(b, 80, b.size());  // level 0 byteOffset
    put64(b, 88, texels.size());
    put64(b, 96, texels.size());
    return b + texels;
}
void expect_volume(const ExrImage& img, int w, int h, int d) {
    EXPECT_EQ(img.width, w);
    EXPECT_EQ(img.height, h * d);
    EXPECT_EQ(img.depth, d);
    ASSERT_EQ(img.pixels.size(), static_cast<std::size_t>(w * h * d));
    for (int z = 0; z < d; ++z)
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)  // row = z * height + y
                ASSERT_EQ(img.pixels[static_cast<std::size_t>((z * h + y) * w + x)], 100 * z + 10 * y + x)
                    << z << " " << y << " " << x;
}
}  // namespace

TEST(Texture3d, DdsAndKtx2VolumesReadWithTheirSlicesStackedAsRows) {
    TempDir dir;
    write(dir / "v.dds", dds_volume(4, 3, 5));
    expect_volume(read_table_image(dir / "v.dds"), 4, 3, 5);
    write(dir / "v.ktx2", ktx2_volume(4, 3, 5));
    expect_volume(read_table_image(dir / "v.ktx2"), 4, 3, 5);
}

TEST(Texture3d, VolumesThatAreDamagedOrTooLargeAreRefusedFromTheirHeaders) {
    TempDir dir;
    write(dir / "v.dds", dds_volume(4, 3, 5, false));
    EXPECT_TRUE(contains(read_error(dir / "v.dds"), "a 3-D texture without DDSD_DEPTH")) << read_error(dir / "v.dds");
    std::string b = dds_volume(4, 3, 5);
    write(dir / "v.dds", b.substr(0, b.size() - 4));
    EXPECT_TRUE(contains(read_error(dir / "v.dds"), "the texel data is truncated"));
    put32(b, 24, 0x7fffffff);  // dwDepth
    write(dir / "v.dds", b);
    EXPECT_TRUE(contains(read_error(dir / "v.dds"), "slices of height 3")) << read_error(dir / "v.dds");
    put32(b, 24, 1 << 23);  // 4 x 3 x 8 Mi: more pixels than any table
    write(dir / "v.dds", b);
    EXPECT_TRUE(contains(read_error(dir / "v.dds"), "the image is 4x25165824 pixels")) << read_error(dir / "v.dds");
    std::string k = ktx2_volume(2, 2, 2);
    put32(k, 24, 0);  // pixelHeight 0 with pixelDepth 2
    write(dir / "v.ktx2", k);
    EXPECT_TRUE(contains(read_error(dir / "v.ktx2"), "needs pixelHeight > 0")) << read_error(dir / "v.ktx2");
}

// ------------------------------------------------------------ source arrays

namespace {
ExrImage read_array(const TempDir& dir, const std::string& file, const std::string& text, const std::string& array,
                    const std::string& shape = "") {
    write(dir / file, text);
    ReadOptions opt;
    opt.array = array;
    if (!shape.empty()) opt.shape = parse_array_shape(shape);
    return read_table_image(dir / file, opt);
}
std::string array_error(const TempDir& dir, const std::string& file, const std::string& text, const std::string& array,
                        const std::string& shape = "") {
    try {
        read_array(dir, file, text, array, shape);
    } catch (const RuntimeError& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(SourceArray, CArraysReadWithSuffixesSignsExponentsAndCommentsSkipped) {
    TempDir dir;
    const std::string c =
        "#include <x.h>\n#define N \\\n  4\n"
        "/* static const float lut[2] = {9, 9}; */\n"
        "static const float other[2] = {5.0f, 6.0f};\n"
        "const char* s = \"lut[] = {1}\";\n"
        "static const float lut[2][3] = {\n"
        "  { 1.0f, -2.5e-3F, +.5 },  // first row\n"
        "  { 0x10, 3., -1E+2f, },\n"
        "};\n";
    const ExrImage img = read_array(dir, "t.c", c, "lut");
    EXPECT_EQ(img.width, 3);
    EXPECT_EQ(img.height, 2);
    ASSERT_EQ(img.channel_names.size(), 1u);
    EXPECT_EQ(img.pixels, (std::vector<double>{1.0, -2.5e-3, 0.5, 16.0, 3.0, -100.0}));
    // The same numbers as a flat array of a declared product size, with a given shape.
    const ExrImage flat = read_array(dir, "f.c", "float lut[2 * 3] = {1, 2, 3, 4, 5, 6};", "lut", "3x2");
    EXPECT_EQ(flat.width, 3);
    EXPECT_EQ(flat.height, 2);
}

TEST(SourceArray, ShapesComeFromDeclaredDimensionsNestingOrVectorTypes) {
    TempDir dir;
    // [H][W][C] with C <= 4 (EEVEE's bsdf_split_sum_ggx[64][64][2] layout).
    std::string text = "const float split[2][3][2] = {{{0,1},{2,3},{4,5}},{{6,7},{8,9},{10,11}}};";
    ExrImage img = read_array(dir, "a.cc", text, "split");
    EXPECT_EQ(img.width, 3);
    EXPECT_EQ(img.height, 2);
    EXPECT_EQ(img.channel_names.size(), 2u);
    EXPECT_EQ(img.pixels[11], 11.0);
    // [D][H][W] when the last is above 4; slices stacked as rows.
    std::string vol = "float v[2][1][5] = {";
    for (int i = 0; i < 10; ++i) vol += std::to_string(i) + ",";
    img = read_array(dir, "v.c", vol + "};", "v");
    EXPECT_EQ(img.width, 5);
    EXPECT_EQ(img.height, 2);
    EXPECT_EQ(img.depth, 2);
    // An empty first dimension: count / rest; [H][W] even when W <= 4.
    img = read_array(dir, "n.c", "float n[][2] = {{1, 2}, {3, 4}, {5, 6}};", "n");
    EXPECT_EQ(img.width, 2);
    EXPECT_EQ(img.height, 3);
    EXPECT_EQ(img.channel_names.size(), 1u);
    // No declared size: the nesting.
    img = read_array(dir, "m.c", "float m[] = {{{1, 2}, {3, 4}, {5, 6}}};", "m");
    EXPECT_EQ(img.width, 3);
    EXPECT_EQ(img.height, 1);
    EXPECT_EQ(img.channel_names.size(), 2u);
    // HLSL float2 and GLSL vec2 constructors: a channel per component.
    img = read_array(dir, "l.hlsl", "static const float2 lut[2] = { float2(1, 2), float2(3, 4) };", "lut");
    EXPECT_EQ(img.width, 2);
    EXPECT_EQ(img.channel_names.size(), 2u);
    EXPECT_EQ(img.pixels, (std::vector<double>{1, 2, 3, 4}));
    img = read_array(dir, "l.glsl", "const vec2 lut[3] = vec2[3](vec2(0.1, 0.2), vec2(0.3, 0.4), vec2(0.5, 0.6));", "lut");
    EXPECT_EQ(img.width, 3);
    EXPECT_EQ(img.channel_names.size(), 2u);
    EXPECT_EQ(img.pixels[5], 0.6);
    img = read_array(dir, "g.glsl", "const float g[] = float[](1.0, 2.0, 3.0, 4.0, 5.0);", "g");
    EXPECT_EQ(img.width, 5);
}

TEST(SourceArray, JavaScriptArraysAndTypedArraysRead) {
    TempDir dir;
    const std::string js =
        "import { X } from './x.js';\n"
        "const note = `template [1, 2] ${1}`;\n"
        "const LTC_MAT_1 = [ 1, 0, 0, 2e-05, 0.5, -0.25 ]; // six numbers\n"
        "export const LTC_MAT_2 = new Float32Array( [ 1, 2, 3, 4 ] );\n"
        "const ltc_float_1 = new Float32Array( LTC_MAT_1 );\n"
        "let nested = [[1, 2], [3, 4], [5, 6]];\n";
    ExrImage img = read_array(dir, "l.js", js, "LTC_MAT_1", "3x2");
    EXPECT_EQ(img.pixels, (std::vector<double>{1, 0, 0, 2e-05, 0.5, -0.25}));
    img = read_array(dir, "l.js", js, "LTC_MAT_2", "1x1:4");
    EXPECT_EQ(img.channel_names.size(), 4u);
    img = read_array(dir, "l.js", js, "nested");  // [3][2]: 3 rows of 2
    EXPECT_EQ(img.width, 2);
    EXPECT_EQ(img.height, 3);
    // An array that is not there: the error lists those that are.
    const std::string err = array_error(dir, "l.js", js, "LTC_MAT_3");
    EXPECT_TRUE(contains(err, "no array 'LTC_MAT_3' in the file; its arrays: LTC_MAT_1, LTC_MAT_2, nested")) << err;
}

TEST(SourceArray, ErrorsNameTheArrayAndWhatIsWrong) {
    TempDir dir;
    const struct {
        std::string text, array, shape, expect;
    } cases[] = {
        {"float a[4] = {1, 2, 3};", "a", "", "array 'a' (line 1) is declared [4] (4 values) but its initializer holds 3 numbers"},
        {"float a[] = {1,\n 2, foo, 3};", "a", "", "array 'a' (line 2): expected a number, found 'foo'"},
        {"float a[] = {1, 2, 3};", "a", "2x2", "array 'a' (line 1) holds 3 numbers but the shape 2x2:1 needs 4"},
        {"float a[] = {1, 2 3};", "a", "", "expected ',' or '}', found '3'"},
        {"float a[] = {1, 2,", "a", "", "found the end of the file"},
        {"float a[] = {010, 2};", "a", "", "expected a number, found '010'"},
        {"float a[] = {1.0q};", "a", "", "found '1.0q'"},
        {"float a[] = {};", "a", "", "is empty"},
        {"float a[2][2][2][2][2] = {1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1};", "a", "", "do not form an image"},
        {"int x = 3; float b[] = {1};", "a", "", "no array 'a' in the file; its arrays: b"},
        {"int x = (y + 1);", "a", "", "it has no array initializers"},
        {"float a[] = {{{{{{{{{{1}}}}}}}}}};", "a", "", "nested deeper than 8 levels"},
    };
    for (const auto& c : cases) {
        const std::string err = array_error(dir, "e.c", c.text, c.array, c.shape);
        EXPECT_TRUE(contains(err, c.expect)) << c.text << "\n expected: " << c.expect << "\n got: " << err;
        EXPECT_TRUE(contains(err, "cannot read '" + (dir / "e.c") + "'")) << err;
    }
    // A binary file with --array, and a source file without it.
    write(dir / "t.npy", npy("<f4", "(1,)", bytes_of(std::vector<float>{0.5f})));
    ReadOptions opt;
    opt.array = "lut";
    EXPECT_TRUE(contains(read_error(dir / "t.npy", opt), "applies to source files, and this is a NumPy .npy file"));
    ReadOptions shaped;
    shaped.shape = parse_array_shape("2x2");
    write(dir / "t.png", make_png(2, 2, PNG_COLOR_TYPE_GRAY, 8, {1, 2, 3, 4}));
    EXPECT_TRUE(contains(read_error(dir / "t.png", shaped), "a shape (--shape 2x2:1) applies to source arrays and .npy files"))
        << read_error(dir / "t.png", shaped);
    write(dir / "s.c", "float lut[] = {1};");
    EXPECT_TRUE(contains(read_error(dir / "s.c"), "a source file is read with --array NAME"));
}

TEST(SourceArray, ShapeOptionsParseAndBadOnesNameTheText) {
    const ArrayShape s = parse_array_shape("16x16x16:2");
    EXPECT_EQ(s.width, 16);
    EXPECT_EQ(s.height, 16);
    EXPECT_EQ(s.depth, 16);
    EXPECT_EQ(s.channels, 2);
    EXPECT_EQ(parse_array_shape("32").height, 1);
    for (const char* bad : {"", "x", "32x", "0x4", "4x4:5", "4x4:", "1x2x3x4", "-4", "4x4:1:1", "99999999999"}) {
        try {
            parse_array_shape(bad);
            ADD_FAILURE() << bad;
        } catch (const Error& e) {
            EXPECT_TRUE(contains(e.what(), std::string("--shape '") + bad + "'")) << e.what();
        }
    }
    EXPECT_EQ(decode_from_string("srgb"), Decode::srgb);
    EXPECT_THROW(decode_from_string("gamma"), Error);
}

// Blender Cycles' tables as the engine ships them (tests/fixtures/cycles/README.md).
// Cycles' table_sheen_ltc stores its three channels as planes: ":3p"
// interleaves them on reading, texel (x, y) channel c = flat[c W H + y W + x].
TEST(SourceArray, PlanarChannelsAreInterleavedOnReading) {
    const std::string path = std::string(BRDFLUT_SOURCE_DIR) + "/tests/fixtures/cycles/shader_gen_schlick.tables";
    ReadOptions flat_opt;
    flat_opt.array = "table_sheen_ltc";
    const ExrImage flat = read_table_image(path, flat_opt);
    ASSERT_EQ(flat.pixels.size(), 3072u);
    ReadOptions opt = flat_opt;
    opt.shape = parse_array_shape("32x32:3p");
    EXPECT_TRUE(opt.shape.planar);
    EXPECT_EQ(to_string(opt.shape), "32x32:3p");
    const ExrImage img = read_table_image(path, opt);
    ASSERT_EQ(img.width, 32);
    ASSERT_EQ(img.height, 32);
    ASSERT_EQ(img.channel_names.size(), 3u);
    for (std::size_t y : {0u, 7u, 31u})
        for (std::size_t x : {0u, 5u, 31u})
            for (std::size_t c = 0; c < 3; ++c)
                EXPECT_EQ(img.pixels[(y * 32 + x) * 3 + c], flat.pixels[c * 1024 + y * 32 + x]) << x << " " << y << " " << c;
    EXPECT_EQ(img.pixels[1], 0.0006);  // texel 0: (A, B, R) from the three planes
    EXPECT_EQ(img.pixels[2], 1e-05);
    // The same shape interleaved reads the file's order unchanged.
    opt.shape = parse_array_shape("32x32:3");
    EXPECT_EQ(read_table_image(path, opt).pixels, flat.pixels);
    EXPECT_THROW(parse_array_shape("32x32:p"), Error);
    EXPECT_THROW(parse_array_shape("32x32:3q"), Error);
}

TEST(SourceArray, CyclesShaderTablesReadWithTheirSizesAndValues) {
    const std::string path = std::string(BRDFLUT_SOURCE_DIR) + "/tests/fixtures/cycles/shader.tables";
    auto read = [&](const std::string& array, const std::string& shape) {
        ReadOptions opt;
        opt.array = array;
        if (!shape.empty()) opt.shape = parse_array_shape(shape);
        return read_table_image(path, opt);
    };
    ExrImage e = read("table_ggx_E", "32x32");
    EXPECT_EQ(e.width, 32);
    EXPECT_EQ(e.height, 32);
    EXPECT_EQ(e.pixels[1], 0.980405);
    EXPECT_EQ(e.pixels[32 + 3], 0.954714);
    EXPECT_EQ(e.pixels[1023], 0.306853);
    // Declared [1024]: without a shape it is one row.
    EXPECT_EQ(read("table_ggx_E", "").width, 1024);
    ExrImage avg = read("table_ggx_Eavg", "");  // inferred from [32]
    EXPECT_EQ(avg.width, 32);
    EXPECT_EQ(avg.height, 1);
    EXPECT_EQ(avg.pixels[31], 0.409137);
    ExrImage glass = read("table_ggx_glass_E", "16x16x16");
    EXPECT_EQ(glass.width, 16);
    EXPECT_EQ(glass.height, 256);
    EXPECT_EQ(glass.depth, 16);
    EXPECT_EQ(glass.pixels[0], 0.999985);
    EXPECT_EQ(glass.pixels[256 + 1], 0.995405);       // slice 1, row 0, column 1
    EXPECT_EQ(glass.pixels[4095], 0.329698);
    ExrImage gavg = read("table_ggx_glass_Eavg", "16x16");
    EXPECT_EQ(gavg.height, 16);
    EXPECT_EQ(gavg.pixels[17], 0.999948);
    ExrImage inv = read("table_ggx_glass_inv_E", "16x16x16");
    EXPECT_EQ(inv.depth, 16);
    EXPECT_EQ(inv.pixels[256 + 16 + 3], 0.832222);  // slice 1, row 1, column 3
    EXPECT_EQ(inv.pixels[4095], 0.306851);
    ExrImage iavg = read("table_ggx_glass_inv_Eavg", "16x16");
    EXPECT_EQ(iavg.pixels[255], 0.409136);
    // Every table of the file is listed when a name is wrong.
    try {
        read("ggx_E", "");
        FAIL();
    } catch (const RuntimeError& err) {
        EXPECT_TRUE(contains(err.what(), "its arrays: table_ggx_E, table_ggx_Eavg, table_ggx_glass_E, "
                                         "table_ggx_glass_Eavg, table_ggx_glass_inv_E, table_ggx_glass_inv_Eavg"))
            << err.what();
    }
}

// ---------------------------------------------------------------- the tool

TEST(CliReaders, InspectCompareAndSampleTakeArrayShapeAndDecode) {
    TempDir dir;
    const std::string fixture = std::string(BRDFLUT_SOURCE_DIR) + "/tests/fixtures/cycles/shader.tables";
    auto r = run_cli("inspect '" + fixture + "' --array table_ggx_glass_E --shape 16x16x16 --json", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("width"), 16);
    EXPECT_EQ(j.at("height"), 256);
    EXPECT_EQ(j.at("depth"), 16);
    // A brdflut C++ header read back as a source array and compared.
    r = run_cli("generate ggx_albedo --size 8x6 --format cpp -q -o '" + dir.path().string() + "'", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = run_cli("compare '" + (dir / "ggx_albedo.h") + "' --array data --shape 8x6 --as ggx_albedo --json", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    j = nlohmann::json::parse(r.out);
    EXPECT_LT(j.at("channels").at(0).at("max_abs_error").get<double>(), 1e-6) << r.out;
    r = run_cli("sample '" + (dir / "ggx_albedo.h") + "' --array data --shape 8x6 --as ggx_albedo --at cos_theta=0.5,alpha=0.5", dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    // A PNG without metadata needs --decode; bad option values are usage errors.
    write(dir / "t.png", make_png(2, 1, PNG_COLOR_TYPE_GRAY, 8, {0, 255}));
    r = run_cli("inspect '" + (dir / "t.png") + "'", dir);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_TRUE(contains(r.err, "--decode linear")) << r.err;
    r = run_cli("inspect '" + (dir / "t.png") + "' --decode linear --json", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out).at("pixel"), "unorm8");
    r = run_cli("inspect '" + (dir / "t.png") + "' --decode gamma", dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_TRUE(contains(r.err, "allowed: linear, srgb")) << r.err;
    r = run_cli("inspect '" + fixture + "' --array table_ggx_E --shape 32x", dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_TRUE(contains(r.err, "--shape '32x'")) << r.err;
}

TEST(Texture3d, ADdsCutShortBeforeItsFourCcIsRefusedAsTruncated) {
    // Found by the fuzzer: 82 bytes, the DX10 FourCC at 84 out of reach.
    const std::string bytes = read_file(std::string(BRDFLUT_SOURCE_DIR) + "/tests/fuzz/corpus/dds_cut_before_fourcc.dds");
    ASSERT_GT(bytes.size(), 80u);
    // The corpus file starts with the fuzzer's option byte.
    const std::string dds = bytes.substr(1);
    try {
        read_table_image_memory(dds.data(), dds.size(), "cut.dds");
        ADD_FAILURE() << "a truncated DDS file was read";
    } catch (const RuntimeError& e) {
        EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
    }
}
