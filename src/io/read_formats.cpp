// read_table_image(): the format from the first bytes, then its reader. The
// readers of the binary formats brdflut writes are here (their layouts are
// the writers': io/dds.cpp, io/ktx2.cpp, io/formats.cpp for png16), with the
// general PNG reader; npy.cpp and source_array.cpp hold the others.
#include <png.h>
#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string_view>

#include "brdflut/error.h"
#include "brdflut/math.h"
#include "brdflut/formats.h"
#include "io/gpu_formats.h"
#include "io/image_limits.h"
#include "io/input_file.h"
#include "io/readers.h"

namespace brdflut {
namespace {

constexpr const char* kChannelNames[4] = {"R", "G", "B", "A"};

struct Bytes {
    std::string path;
    std::string_view b;
    [[noreturn]] void fail(const std::string& why) const { throw RuntimeError("cannot read '" + path + "': " + why); }
    std::uint64_t le(std::size_t at, int n) const {
        if (at > b.size() || static_cast<std::size_t>(n) > b.size() - at) fail("the file is truncated");
        std::uint64_t v = 0;
        for (int i = n - 1; i >= 0; --i) v = v << 8 | static_cast<unsigned char>(b[at + static_cast<std::size_t>(i)]);
        return v;
    }
    std::uint32_t u32(std::size_t at) const { return static_cast<std::uint32_t>(le(at, 4)); }
    std::uint64_t u64(std::size_t at) const { return le(at, 8); }
};

// Texels of format f from `at`.
void read_texels(const Bytes& f, std::uint64_t at, ExrImage& img, const GpuFormat& format) {
    const std::size_t texels = static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height);
    const std::size_t bytes = static_cast<std::size_t>(format.texel_bytes());
    if (at > f.b.size() || texels * bytes > f.b.size() - at) f.fail("the texel data is truncated");
    img.pixel = format.storage == Storage::half ? PixelType::half : PixelType::float32;
    // An rgbd texture reads as its RGBA8 bytes until decoded (its metadata or --decode rgbd).
    img.storage = format.storage == Storage::rgbd ? Storage::unorm8 : format.storage;
    const int channels = format.packed ? decoded_channels(format.storage) : format.channels;
    img.channel_names.assign(kChannelNames, kChannelNames + channels);
    img.pixels.reserve(texels * static_cast<std::size_t>(channels));
    unpack_texels(reinterpret_cast<const unsigned char*>(f.b.data()) + at, texels, format, img.pixels);
}

// A w x h texture of `depth` slices, stacked as rows.
void set_size(const Bytes& f, ExrImage& img, std::uint64_t w, std::uint64_t h, std::uint64_t depth, int channels) {
    if (depth < 1 || depth > static_cast<std::uint64_t>(kMaxImagePixels) || h > static_cast<std::uint64_t>(kMaxImagePixels))
        f.fail("the image has " + std::to_string(depth) + " slices of height " + std::to_string(h) +
               "; supported are at most " + std::to_string(kMaxImagePixels) + " rows");
    const std::uint64_t rows = h * depth;
    if (const std::string why = image_size_problem(static_cast<long long>(w), static_cast<long long>(rows), channels);
        !why.empty())
        f.fail("the image " + why);
    img.width = static_cast<int>(w);
    img.height = static_cast<int>(rows);
    img.depth = static_cast<int>(depth);
}

void parse_metadata(const Bytes& f, ExrImage& img, std::string_view json) {
    try {
        img.metadata = nlohmann::json::parse(json);
        img.has_metadata = true;
    } catch (const nlohmann::json::exception& e) {
        f.fail(std::string("metadata is not valid JSON: ") + e.what());
    }
}

ExrImage read_dds(const Bytes& f) {
    // DDS_HEADER at 4, DDS_PIXELFORMAT at 76, DDS_HEADER_DXT10 at 128.
    // The FourCC "DX10" read as a little-endian word, so a file cut short
    // before it is reported as truncated.
    constexpr std::uint32_t kFourCcDx10 = 0x30315844;
    if (f.u32(4) != 124 || f.u32(76) != 32 || f.u32(84) != kFourCcDx10) f.fail("not a DDS file with a DX10 header");
    constexpr std::uint32_t DDSD_DEPTH = 0x800000;
    constexpr std::uint32_t kTexture2D = 3, kTexture3D = 4;  // D3D10_RESOURCE_DIMENSION
    ExrImage img;
    const std::uint32_t dimension = f.u32(132);
    if ((dimension != kTexture2D && dimension != kTexture3D) || f.u32(140) != 1)
        f.fail("only single 2-D or 3-D textures are read (resourceDimension " + std::to_string(dimension) +
               ", arraySize " + std::to_string(f.u32(140)) + ")");
    std::uint64_t depth = 1;
    if (dimension == kTexture3D) {
        if ((f.u32(8) & DDSD_DEPTH) == 0) f.fail("a 3-D texture without DDSD_DEPTH in dwFlags");
        depth = f.u32(24);  // dwDepth
    }
    const GpuFormat* format = gpu_format_by_dxgi(f.u32(128));
    if (format == nullptr) f.fail("DXGI format " + std::to_string(f.u32(128)) + " is not one brdflut writes");
    set_size(f, img, f.u32(16), f.u32(12), depth, format->channels);
    read_texels(f, 148, img, *format);
    return img;
}

ExrImage read_ktx2(const Bytes& f) {
    ExrImage img;
    const GpuFormat* format = gpu_format_by_vk(f.u32(12));
    if (format == nullptr) f.fail("vkFormat " + std::to_string(f.u32(12)) + " is not one brdflut writes");
    const int channels = format->channels;
    if (f.u32(32) != 0 || f.u32(36) != 1 || f.u32(44) != 0)
        f.fail("only single 2-D or 3-D textures without supercompression are read");
    const std::uint32_t pixel_depth = f.u32(28);
    if (pixel_depth > 0 && f.u32(24) == 0) f.fail("a 3-D texture (pixelDepth > 0) needs pixelHeight > 0");
    set_size(f, img, f.u32(20), std::max<std::uint32_t>(1, f.u32(24)), std::max<std::uint32_t>(1, pixel_depth), channels);
    // Key/value data: look for the `brdflut` key.
    const std::uint64_t kvd = f.u32(56), kvd_end = kvd + f.u32(60);
    for (std::uint64_t at = kvd; at + 4 <= kvd_end;) {
        const std::uint64_t n = f.u32(static_cast<std::size_t>(at));
        if (at + 4 + n > f.b.size()) f.fail("the key/value data is truncated");
        const std::string_view kv = f.b.substr(static_cast<std::size_t>(at + 4), static_cast<std::size_t>(n));
        const std::size_t nul = kv.find('\0');
        if (nul != std::string_view::npos && kv.substr(0, nul) == "brdflut") {
            std::string_view value = kv.substr(nul + 1);
            if (!value.empty() && value.back() == '\0') value.remove_suffix(1);
            parse_metadata(f, img, value);
        }
        at += 4 + (n + 3) / 4 * 4;
    }
    read_texels(f, f.u64(80), img, *format);
    return img;
}

struct PngReadState {
    std::string_view bytes;
    std::size_t at;
};

void png_read_from_memory(png_structp png, png_bytep data, png_size_t n) {
    auto* s = static_cast<PngReadState*>(png_get_io_ptr(png));
    if (n > s->bytes.size() - s->at) png_error(png, "the file is truncated");
    std::memcpy(data, s->bytes.data() + s->at, n);
    s->at += n;
}

struct PngDecoded {
    png_uint_32 width = 0, height = 0;
    int channels = 0, bits = 0;
    bool size_ok = false;
    char error[200] = {};
};

void png_on_error(png_structp png, png_const_charp msg) {
    auto* d = static_cast<PngDecoded*>(png_get_error_ptr(png));
    std::snprintf(d->error, sizeof d->error, "%s", msg);
    png_longjmp(png, 1);
}
void png_on_warning(png_structp, png_const_charp) {}

// libpng reports errors by longjmp: only trivially destructible objects live
// across setjmp here; results go to the caller's buffers. Palettes, grey of
// fewer than 8 bits and tRNS transparency are expanded (to RGB or RGBA, 8-bit
// grey, an alpha channel). The pixels are decoded only when the header shows
// a size within the limits, into `samples` as the file's bytes (16-bit
// samples big-endian). Text chunks are capped so that compressed metadata
// cannot expand without bound.
bool decode_png(std::string_view bytes, PngDecoded* d, std::vector<unsigned char>* samples, std::string* text) {
    PngReadState state{bytes, 0};
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, d, png_on_error, png_on_warning);
    if (png == nullptr) return false;
    png_infop info = png_create_info_struct(png);
    if (info == nullptr || setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    png_set_read_fn(png, &state, png_read_from_memory);
    png_set_user_limits(png, 0x7fffffffu, 0x7fffffffu);
    png_set_chunk_malloc_max(png, 16u << 20);
    png_set_chunk_cache_max(png, 1000);
    png_read_info(png, info);
    const int color = png_get_color_type(png, info);
    if (color == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (color == PNG_COLOR_TYPE_GRAY && png_get_bit_depth(png, info) < 8) png_set_expand_gray_1_2_4_to_8(png);
    if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
    const int passes = png_set_interlace_handling(png);
    png_read_update_info(png, info);
    d->width = png_get_image_width(png, info);
    d->height = png_get_image_height(png, info);
    d->channels = png_get_channels(png, info);
    d->bits = png_get_bit_depth(png, info);
    d->size_ok = image_size_problem(d->width, d->height, d->channels).empty();
    if (d->size_ok) {
        const std::size_t row = png_get_rowbytes(png, info);
        samples->resize(row * d->height);
        for (int pass = passes; pass > 0; --pass)
            for (png_uint_32 y = 0; y < d->height; ++y) png_read_row(png, samples->data() + y * row, nullptr);
        png_read_end(png, info);  // text chunks after the image data
    }
    png_textp t = nullptr;
    const int n = png_get_text(png, info, &t, nullptr);
    for (int i = 0; i < n; ++i)
        if (std::strcmp(t[i].key, "brdflut") == 0)
            text->assign(t[i].text, t[i].itxt_length ? t[i].itxt_length : t[i].text_length);
    png_destroy_read_struct(&png, &info, nullptr);
    return true;
}

ExrImage read_png(const Bytes& f, const ReadOptions& opt) {
    PngDecoded d;
    std::vector<unsigned char> samples;
    std::string text;
    if (!decode_png(f.b, &d, &samples, &text))
        f.fail(std::string("not a readable PNG file") + (d.error[0] ? std::string(" (") + d.error + ")" : ""));
    ExrImage img;
    set_size(f, img, d.width, d.height, 1, d.channels);
    if (d.bits != 8 && d.bits != 16) f.fail("PNG samples of " + std::to_string(d.bits) + " bits are not read");
    if (!text.empty()) parse_metadata(f, img, text);
    if (!img.has_metadata && opt.decode == Decode::none)
        f.fail("a PNG without brdflut metadata needs a decoding: --decode linear (samples q as q/" +
               std::string(d.bits == 8 ? "255" : "65535") + ") or --decode srgb (then the sRGB EOTF)");
    img.pixel = PixelType::float32;
    img.channel_names.assign(kChannelNames, kChannelNames + std::min(d.channels, 4));
    img.pixels.reserve(samples.size() / (d.bits / 8));
    if (d.bits == 16) {
        img.storage = Storage::unorm16;
        for (std::size_t i = 0; i + 1 < samples.size(); i += 2)
            img.pixels.push_back((samples[i] << 8 | samples[i + 1]) / 65535.0);
    } else {
        img.storage = Storage::unorm8;
        for (unsigned char q : samples) img.pixels.push_back(q / 255.0);
    }
    return img;
}

// Babylon.js's RGBD: 8-bit RGBA read as unorm8 to three values a texel, with
// the spacing of the encoding around each.
void decode_rgbd(const std::string& name, ExrImage& img) {
    if (!img.is_unorm8() || img.channel_names.size() != 4)
        throw RuntimeError("cannot read '" + name + "': rgbd decoding applies to 8-bit RGBA images, and this one has " +
                           std::to_string(img.channel_names.size()) + " channel(s) of " +
                           std::string(img.stored_as()) + " values");
    const std::size_t texels = img.pixels.size() / 4;
    std::vector<double> values(texels * 3), steps(texels * 3);
    for (std::size_t k = 0; k < texels; ++k) {
        std::uint32_t q[4];
        for (std::size_t c = 0; c < 4; ++c) q[c] = static_cast<std::uint32_t>(std::lround(img.pixels[4 * k + c] * 255.0));
        if (q[3] == 0)
            throw RuntimeError("cannot read '" + name + "': rgbd texel " + std::to_string(k) +
                               " has D = 0 in A; allowed: 1 to 255");
        decode_texel(Storage::rgbd, q, &values[3 * k]);
        for (int c = 0; c < 3; ++c) steps[3 * k + static_cast<std::size_t>(c)] = encoding_step(Storage::rgbd, q, c);
    }
    img.pixels = std::move(values);
    img.steps = std::move(steps);
    img.storage = Storage::rgbd;
    img.channel_names.assign(kChannelNames, kChannelNames + 3);
}

// A brdflut file says in its metadata how it is stored: rgbd is decoded.
bool metadata_says_rgbd(const ExrImage& img) {
    return img.has_metadata && img.metadata.is_object() && img.metadata.contains("pixel") &&
           img.metadata["pixel"] == "rgbd";
}

void apply_decode(const std::string& name, ExrImage& img, Decode decode) {
    if (decode == Decode::rgbd || (decode == Decode::none && metadata_says_rgbd(img))) return decode_rgbd(name, img);
    if (decode != Decode::srgb) return;
    if (!img.is_unorm8() && !img.is_unorm16())
        throw RuntimeError("cannot read '" + name +
                           "': --decode srgb applies to 8- and 16-bit integer samples (PNG, .npy u1/u2), and this "
                           "file holds floating-point samples");
    const std::size_t nc = img.channel_names.size();
    for (std::size_t i = 0; i < img.pixels.size(); ++i)
        if (i % nc < 3) img.pixels[i] = srgb_eotf(img.pixels[i]);  // a 4th channel is alpha, stored linear
}

enum class Kind { exr, dds, ktx2, png, npy, unknown };

Kind kind_of(std::string_view head) {
    const std::string_view ktx2_id("\xABKTX 20\xBB\r\n\x1A\n", 12);
    if (head.substr(0, 4) == std::string_view("\x76\x2f\x31\x01", 4)) return Kind::exr;
    if (head.substr(0, 4) == "DDS ") return Kind::dds;
    if (head.substr(0, 12) == ktx2_id) return Kind::ktx2;
    if (head.substr(0, 8) == std::string_view("\x89PNG\r\n\x1a\n", 8)) return Kind::png;
    if (head.substr(0, 6) == std::string_view("\x93NUMPY", 6)) return Kind::npy;
    return Kind::unknown;
}
constexpr std::size_t kHeadBytes = 16;
constexpr const char* kKindNames[] = {"an OpenEXR", "a DDS", "a KTX2", "a PNG", "a NumPy .npy", ""};

// What the first bytes say, before the rest is read: the reader to use, or
// the reason the file is refused.
std::string refuse_from_head(std::string_view head, const ReadOptions& opt) {
    const Kind k = kind_of(head);
    if (k != Kind::unknown) {
        if (!opt.array.empty())
            return std::string("an array name (--array ") + opt.array + ") applies to source files, and this is " +
                   kKindNames[static_cast<int>(k)] + " file";
        if (opt.shape.given() && k != Kind::npy)
            return std::string("a shape (--shape ") + to_string(opt.shape) +
                   ") applies to source arrays and .npy files, and this is " + kKindNames[static_cast<int>(k)] +
                   " file, whose header gives its size";
        return {};
    }
    if (opt.array.empty())
        return "not an OpenEXR, DDS, KTX2, PNG or NumPy .npy file (a source file is read with --array NAME)";
    if (head.find('\0') != std::string_view::npos) return "not a text file (it holds NUL bytes), so not a source file";
    return {};
}

ExrImage read_known(const char* data, std::size_t size, const std::string& name, const ReadOptions& opt) {
    const Bytes f{name, std::string_view(data, size)};
    ExrImage img;
    switch (kind_of(f.b.substr(0, kHeadBytes))) {
        case Kind::exr: img = read_exr_memory(data, size, name); break;
        case Kind::dds: img = read_dds(f); break;
        case Kind::ktx2: img = read_ktx2(f); break;
        case Kind::png: img = read_png(f, opt); break;
        case Kind::npy: img = read_npy(data, size, name, opt); break;
        case Kind::unknown: img = read_source_array(data, size, name, opt); break;
    }
    apply_decode(name, img, opt.decode);
    return img;
}

}  // namespace

std::string_view to_string(Decode d) {
    switch (d) {
        case Decode::linear: return "linear";
        case Decode::srgb: return "srgb";
        case Decode::rgbd: return "rgbd";
        default: return "none";
    }
}

Decode decode_from_string(std::string_view s) {
    if (s == "linear") return Decode::linear;
    if (s == "srgb") return Decode::srgb;
    if (s == "rgbd") return Decode::rgbd;
    throw Error("--decode '" + std::string(s) + "' is not a decoding; allowed: linear, srgb, rgbd");
}

ArrayShape parse_array_shape(std::string_view s) {
    const std::string text(s);
    auto bad = [&](const std::string& why) -> Error {
        return Error("--shape '" + text + "': " + why +
                     "; allowed: W, WxH or WxHxD, optionally :C (1 to 4 channels) or :Cp (channels stored as planes), "
                     "e.g. 32x32, 64x64:2 or 32x32:3p");
    };
    auto number = [&](std::string_view part, long long max) {
        if (part.empty() || part.size() > 10 || part.find_first_not_of("0123456789") != std::string_view::npos)
            throw bad("'" + std::string(part) + "' is not a positive whole number");
        const long long v = std::stoll(std::string(part));
        if (v < 1 || v > max) throw bad(std::string(part) + " is out of range 1 to " + std::to_string(max));
        return v;
    };
    ArrayShape shape;
    std::string_view dims = s;
    if (const std::size_t colon = s.find(':'); colon != std::string_view::npos) {
        dims = s.substr(0, colon);
        std::string_view c = s.substr(colon + 1);
        if (!c.empty() && c.back() == 'p') {
            shape.planar = true;
            c.remove_suffix(1);
        }
        shape.channels = number(c, 4);
    }
    long long* fields[3] = {&shape.width, &shape.height, &shape.depth};
    int n = 0;
    for (std::size_t start = 0;;) {
        const std::size_t x = dims.find('x', start);
        if (n == 3) throw bad("more than three dimensions");
        *fields[n++] = number(dims.substr(start, x == std::string_view::npos ? x : x - start), kMaxImagePixels);
        if (x == std::string_view::npos) break;
        start = x + 1;
    }
    if (const std::string why = image_size_problem(shape.width, shape.height * shape.depth, shape.channels);
        !why.empty() || shape.depth > kMaxImagePixels / shape.height)
        throw bad("the image " + (why.empty() ? std::string("has too many rows") : why));
    return shape;
}

std::string to_string(const ArrayShape& s) {
    std::string out = std::to_string(s.width) + "x" + std::to_string(s.height);
    if (s.depth > 1) out += "x" + std::to_string(s.depth);
    return out + ":" + std::to_string(s.channels) + (s.planar ? "p" : "");
}

void interleave_planes(ExrImage& img, const ArrayShape& shape) {
    const std::size_t c = static_cast<std::size_t>(shape.channels);
    if (!shape.planar || c < 2) return;
    const std::size_t plane = img.pixels.size() / c;
    std::vector<double> out(img.pixels.size());
    for (std::size_t k = 0; k < c; ++k)
        for (std::size_t i = 0; i < plane; ++i) out[i * c + k] = img.pixels[k * plane + i];
    img.pixels.swap(out);
}

std::string resolve_shape(std::vector<long long> dims, long long count, const ArrayShape& given, ArrayShape& shape,
                          bool last_is_channels) {
    if (given.given()) {
        const long long need = given.width * given.height * given.depth * given.channels;
        if (need != count)
            return "holds " + std::to_string(count) + " numbers but the shape " + to_string(given) + " needs " +
                   std::to_string(need);
        shape = given;
        return {};
    }
    std::string declared;
    for (long long d : dims) declared += "[" + std::to_string(d) + "]";
    shape = ArrayShape{};
    if ((last_is_channels && dims.size() >= 2) || (dims.size() >= 3 && dims.back() >= 1 && dims.back() <= 4)) {
        shape.channels = dims.back();
        dims.pop_back();
    }
    switch (dims.size()) {
        case 1: shape.width = dims[0]; break;
        case 2: shape.height = dims[0]; shape.width = dims[1]; break;
        case 3: shape.depth = dims[0]; shape.height = dims[1]; shape.width = dims[2]; break;
        default:
            return "has the dimensions " + declared + ", which do not form an image; give its shape (--shape WxH[xD][:C])";
    }
    for (long long d : dims)
        if (d < 1) return "has the dimensions " + declared + ", with an empty one";
    return {};
}

std::string shape_image(ExrImage& img, const ArrayShape& shape) {
    if (shape.depth > kMaxImagePixels / std::max<long long>(1, shape.height))
        return "the image has " + std::to_string(shape.depth) + " slices of " + std::to_string(shape.height) + " rows";
    if (std::string why = image_size_problem(shape.width, shape.height * shape.depth, shape.channels); !why.empty())
        return "the image " + why;
    if (shape.channels > 4) return "the image has " + std::to_string(shape.channels) + " channels; at most 4 are read";
    img.width = static_cast<int>(shape.width);
    img.height = static_cast<int>(shape.height * shape.depth);
    img.depth = static_cast<int>(shape.depth);
    img.channel_names.assign(kChannelNames, kChannelNames + shape.channels);
    return {};
}

ExrImage read_table_image_memory(const char* data, std::size_t size, const std::string& name, const ReadOptions& opt) {
    const std::string_view head(data, std::min(size, kHeadBytes));
    if (const std::string why = refuse_from_head(head, opt); !why.empty())
        throw RuntimeError("cannot read '" + name + "': " + why);
    const std::uint64_t limit = kind_of(head) == Kind::unknown ? kMaxTextFileBytes : kMaxBinaryFileBytes;
    if (size > limit)
        throw RuntimeError("cannot read '" + name + "': the file is " + std::to_string(size) + " bytes; at most " +
                           std::to_string(limit) + " are read");
    return read_known(data, size, name, opt);
}

ExrImage read_table_image(const std::string& path, const ReadOptions& opt) {
    InputFile file(path);
    const std::string head = file.head(kHeadBytes);
    if (const std::string why = refuse_from_head(head, opt); !why.empty()) file.fail(why);
    const bool text = kind_of(head) == Kind::unknown;
    const std::string bytes = file.read_all(text ? kMaxTextFileBytes : kMaxBinaryFileBytes,
                                            text ? "a source file" : "a binary file");
    return read_known(bytes.data(), bytes.size(), path, opt);
}

}  // namespace brdflut
