// Readers for the binary formats brdflut writes (see formats.h); the layouts
// are the writers' (io/dds.cpp, io/ktx2.cpp, io/formats.cpp for png16).
#include <png.h>
#include <Imath/half.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

#include "brdflut/error.h"
#include "brdflut/formats.h"
#include "io/image_limits.h"

namespace brdflut {
namespace {

constexpr const char* kChannelNames[4] = {"R", "G", "B", "A"};

struct Bytes {
    std::string path;
    std::string b;
    [[noreturn]] void fail(const std::string& why) const { throw RuntimeError("cannot read '" + path + "': " + why); }
    std::uint64_t le(std::size_t at, int n) const {
        if (at + static_cast<std::size_t>(n) > b.size()) fail("the file is truncated");
        std::uint64_t v = 0;
        for (int i = n - 1; i >= 0; --i) v = v << 8 | static_cast<unsigned char>(b[at + static_cast<std::size_t>(i)]);
        return v;
    }
    std::uint32_t u32(std::size_t at) const { return static_cast<std::uint32_t>(le(at, 4)); }
    std::uint64_t u64(std::size_t at) const { return le(at, 8); }
};

// Texels of `channels` little-endian half or float components from `at`.
void read_texels(const Bytes& f, std::size_t at, ExrImage& img, int channels, PixelType pixel) {
    const std::size_t n = static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height) *
                          static_cast<std::size_t>(channels);
    const std::size_t comp = pixel == PixelType::half ? 2 : 4;
    if (at + n * comp > f.b.size()) f.fail("the texel data is truncated");
    img.pixel = pixel;
    img.channel_names.assign(kChannelNames, kChannelNames + channels);
    img.pixels.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint64_t bits = f.le(at + i * comp, static_cast<int>(comp));
        if (pixel == PixelType::half) {
            Imath::half h;
            h.setBits(static_cast<unsigned short>(bits));
            img.pixels[i] = static_cast<double>(static_cast<float>(h));
        } else {
            const std::uint32_t b32 = static_cast<std::uint32_t>(bits);
            float v;
            std::memcpy(&v, &b32, sizeof v);
            img.pixels[i] = static_cast<double>(v);
        }
    }
}

void set_size(const Bytes& f, ExrImage& img, std::uint64_t w, std::uint64_t h, int channels) {
    if (const std::string why = image_size_problem(static_cast<long long>(w), static_cast<long long>(h), channels);
        !why.empty())
        f.fail("the image " + why);
    img.width = static_cast<int>(w);
    img.height = static_cast<int>(h);
}

void parse_metadata(const Bytes& f, ExrImage& img, const std::string& json) {
    try {
        img.metadata = nlohmann::json::parse(json);
        img.has_metadata = true;
    } catch (const nlohmann::json::exception& e) {
        f.fail(std::string("metadata is not valid JSON: ") + e.what());
    }
}

ExrImage read_dds(const Bytes& f) {
    // DDS_HEADER at 4, DDS_PIXELFORMAT at 76, DDS_HEADER_DXT10 at 128.
    if (f.u32(4) != 124 || f.u32(76) != 32 || f.b.compare(84, 4, "DX10") != 0)
        f.fail("not a DDS file with a DX10 header");
    ExrImage img;
    if (f.u32(132) != 3 || f.u32(140) != 1) f.fail("only single 2-D textures are read");
    int channels = 0;
    PixelType pixel = PixelType::float32;
    switch (f.u32(128)) {
        case 54: channels = 1; pixel = PixelType::half; break;
        case 34: channels = 2; pixel = PixelType::half; break;
        case 10: channels = 4; pixel = PixelType::half; break;
        case 41: channels = 1; break;
        case 16: channels = 2; break;
        case 2: channels = 4; break;
        default: f.fail("DXGI format " + std::to_string(f.u32(128)) + " is not one brdflut writes");
    }
    set_size(f, img, f.u32(16), f.u32(12), channels);
    read_texels(f, 148, img, channels, pixel);
    return img;
}

ExrImage read_ktx2(const Bytes& f) {
    ExrImage img;
    int channels = 0;
    PixelType pixel = PixelType::float32;
    switch (f.u32(12)) {
        case 76: channels = 1; pixel = PixelType::half; break;
        case 83: channels = 2; pixel = PixelType::half; break;
        case 97: channels = 4; pixel = PixelType::half; break;
        case 100: channels = 1; break;
        case 103: channels = 2; break;
        case 109: channels = 4; break;
        default: f.fail("vkFormat " + std::to_string(f.u32(12)) + " is not one brdflut writes");
    }
    if (f.u32(28) != 0 || f.u32(32) != 0 || f.u32(36) != 1 || f.u32(44) != 0)
        f.fail("only single 2-D textures without supercompression are read");
    set_size(f, img, f.u32(20), std::max<std::uint32_t>(1, f.u32(24)), channels);
    // Key/value data: look for the `brdflut` key.
    const std::size_t kvd = f.u32(56), kvd_end = kvd + f.u32(60);
    for (std::size_t at = kvd; at + 4 <= kvd_end;) {
        const std::size_t n = f.u32(at);
        if (at + 4 + n > f.b.size()) f.fail("the key/value data is truncated");
        const std::string kv = f.b.substr(at + 4, n);
        const std::size_t nul = kv.find('\0');
        if (nul != std::string::npos && kv.compare(0, nul, "brdflut") == 0) {
            std::string value = kv.substr(nul + 1);
            if (!value.empty() && value.back() == '\0') value.pop_back();
            parse_metadata(f, img, value);
        }
        at += 4 + (n + 3) / 4 * 4;
    }
    read_texels(f, static_cast<std::size_t>(f.u64(80)), img, channels, pixel);
    return img;
}

struct PngReadState {
    const std::string* bytes;
    std::size_t at;
};

void png_read_from_memory(png_structp png, png_bytep data, png_size_t n) {
    auto* s = static_cast<PngReadState*>(png_get_io_ptr(png));
    if (s->at + n > s->bytes->size()) png_error(png, "the file is truncated");
    std::memcpy(data, s->bytes->data() + s->at, n);
    s->at += n;
}

// libpng reports errors by longjmp: only trivially destructible objects live
// across setjmp here; results go to the caller's buffers. The pixels are
// decoded only when the header shows 16 bits and a size within the limits,
// into `big_endian` as the file's big-endian sample bytes.
bool decode_png16(const std::string* bytes, png_uint_32* w, png_uint_32* h, int* channels, int* depth,
                  std::vector<unsigned char>* big_endian, std::string* text) {
    PngReadState state{bytes, 0};
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    if (png == nullptr) return false;
    png_infop info = png_create_info_struct(png);
    if (info == nullptr || setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    png_set_read_fn(png, &state, png_read_from_memory);
    png_read_info(png, info);
    *w = png_get_image_width(png, info);
    *h = png_get_image_height(png, info);
    *channels = png_get_channels(png, info);
    *depth = png_get_bit_depth(png, info);
    if (*depth == 16 && image_size_problem(*w, *h, *channels).empty()) {
        const std::size_t row = static_cast<std::size_t>(*w) * static_cast<std::size_t>(*channels) * 2;
        big_endian->resize(row * *h);
        for (int pass = png_set_interlace_handling(png); pass > 0; --pass)
            for (png_uint_32 y = 0; y < *h; ++y) png_read_row(png, big_endian->data() + y * row, nullptr);
        png_read_end(png, info);  // text chunks after the image data
    }
    png_textp t = nullptr;
    const int n = png_get_text(png, info, &t, nullptr);
    for (int i = 0; i < n; ++i)
        if (std::strcmp(t[i].key, "brdflut") == 0) text->assign(t[i].text, t[i].itxt_length ? t[i].itxt_length : t[i].text_length);
    png_destroy_read_struct(&png, &info, nullptr);
    return true;
}

ExrImage read_png16_image(const Bytes& f) {
    png_uint_32 w = 0, h = 0;
    int channels = 0, depth = 0;
    std::vector<unsigned char> big_endian;
    std::string text;
    if (!decode_png16(&f.b, &w, &h, &channels, &depth, &big_endian, &text)) f.fail("not a readable PNG file");
    if (depth != 16) f.fail("only 16-bit PNG files are read (this one has " + std::to_string(depth) + " bits)");
    ExrImage img;
    set_size(f, img, w, h, channels);
    img.pixel = PixelType::float32;
    img.channel_names.assign(kChannelNames, kChannelNames + channels);
    img.pixels.reserve(big_endian.size() / 2);
    for (std::size_t i = 0; i + 1 < big_endian.size(); i += 2)
        img.pixels.push_back((big_endian[i] << 8 | big_endian[i + 1]) / 65535.0);
    img.unorm16 = true;
    if (!text.empty()) parse_metadata(f, img, text);
    return img;
}

}  // namespace

ExrImage read_table_image(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw RuntimeError("cannot read '" + path + "': no such file");
    Bytes f{path, std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>())};
    const std::string ktx2_id = {'\xAB', 'K', 'T', 'X', ' ', '2', '0', '\xBB', '\r', '\n', '\x1A', '\n'};
    if (f.b.compare(0, 4, "\x76\x2f\x31\x01") == 0) return read_exr(path);
    if (f.b.compare(0, 4, "DDS ") == 0) return read_dds(f);
    if (f.b.compare(0, 12, ktx2_id) == 0) return read_ktx2(f);
    if (f.b.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0) return read_png16_image(f);
    f.fail("not an OpenEXR, DDS, KTX2 or PNG file");
}

}  // namespace brdflut
