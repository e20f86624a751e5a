#include "brdflut/png.h"

#include <png.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string_view>

#include "brdflut/error.h"
#include "io/atomic_file.h"

namespace brdflut {
namespace {

// Everything libpng needs for one file. A plain struct: libpng reports errors
// by longjmp, which must not cross objects with destructors.
struct PngJob {
    std::FILE* file;
    int width, height, bit_depth, color_type;
    bool srgb;
    png_bytep* rows;
    png_textp text;
    int text_count;
    char message[256];
};

void on_png_error(png_structp png, png_const_charp msg) {
    auto* job = static_cast<PngJob*>(png_get_error_ptr(png));
    std::snprintf(job->message, sizeof job->message, "%s", msg);
    png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}

// Encodes the image into job->file. Returns false, with job->message set,
// on failure. Only trivially destructible locals live across setjmp.
bool encode(PngJob* job) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, job, on_png_error, on_png_warning);
    if (png == nullptr) {
        std::snprintf(job->message, sizeof job->message, "libpng could not be initialised");
        return false;
    }
    png_infop info = png_create_info_struct(png);
    if (info == nullptr) {
        png_destroy_write_struct(&png, nullptr);
        std::snprintf(job->message, sizeof job->message, "libpng could not be initialised");
        return false;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_init_io(png, job->file);
    png_set_IHDR(png, info, static_cast<png_uint_32>(job->width), static_cast<png_uint_32>(job->height),
                 job->bit_depth, job->color_type, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (job->srgb) png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    if (job->text_count > 0) png_set_text(png, info, job->text, job->text_count);
    png_write_info(png, info);
    png_write_image(png, job->rows);
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return true;
}

void check_size(const char* what, int width, int height) {
    constexpr long long kMaxSide = 1 << 20;
    if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide ||
        static_cast<long long>(width) * height > (1LL << 30)) {
        throw Error(std::string(what) + ": image size " + std::to_string(width) + "x" +
                    std::to_string(height) + " is out of range; allowed: 1 to " +
                    std::to_string(kMaxSide) + " per side, 2^30 pixels in all");
    }
}

void check_text(const char* what, const PngText& text) {
    for (const auto& [key, value] : text) {
        bool ok = !key.empty() && key.size() <= 79 && key.front() != ' ' && key.back() != ' ';
        for (const char ch : key) {
            const unsigned char c = static_cast<unsigned char>(ch);
            if (!((c >= 32 && c <= 126) || c >= 161)) ok = false;
        }
        if (!ok)
            throw Error(std::string(what) + ": text keyword '" + key +
                        "' is not allowed; a keyword has 1 to 79 printable Latin-1 characters"
                        " and no leading or trailing space");
    }
}

// Writes packed rows (row_bytes each, row 0 at the top) atomically.
void write_png(const std::string& path, int width, int height, int bit_depth, int color_type,
               bool srgb, std::vector<png_byte>& bytes, std::size_t row_bytes, const PngText& text) {
    std::vector<png_bytep> rows(static_cast<std::size_t>(height));
    for (std::size_t y = 0; y < rows.size(); ++y) rows[y] = bytes.data() + y * row_bytes;
    std::vector<png_text> chunks(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        std::memset(&chunks[i], 0, sizeof chunks[i]);
        chunks[i].compression = PNG_ITXT_COMPRESSION_zTXt;
        chunks[i].key = const_cast<char*>(text[i].first.c_str());
        chunks[i].text = const_cast<char*>(text[i].second.c_str());
    }

    AtomicFile file(path);
    std::FILE* f = std::fopen(file.temp_path().c_str(), "wb");
    if (f == nullptr) throw RuntimeError("cannot write '" + path + "': " + std::strerror(errno));
    PngJob job{f, width, height, bit_depth, color_type, srgb, rows.data(),
               chunks.empty() ? nullptr : chunks.data(), static_cast<int>(chunks.size()), {}};
    const bool encoded = encode(&job);
    const bool closed = std::fclose(f) == 0;
    if (!encoded) throw RuntimeError("cannot write '" + path + "': " + job.message);
    if (!closed) throw RuntimeError("cannot write '" + path + "': " + std::strerror(errno));
    file.commit();
}

}  // namespace

std::uint16_t png16_sample(double v) { return static_cast<std::uint16_t>(std::lround(v * 65535.0)); }

void write_png_rgb8(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb,
                    const PngText& text) {
    check_size("write_png_rgb8", width, height);
    check_text("write_png_rgb8", text);
    const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3;
    if (rgb.size() != n)
        throw Error("write_png_rgb8: " + std::to_string(rgb.size()) + " bytes given for a " +
                    std::to_string(width) + "x" + std::to_string(height) + " RGB image; expected " +
                    std::to_string(n));
    std::vector<png_byte> bytes(rgb.begin(), rgb.end());
    write_png(path, width, height, 8, PNG_COLOR_TYPE_RGB, true, bytes, static_cast<std::size_t>(width) * 3,
              text);
}

void write_png16(const std::string& path, int width, int height, int channels,
                 const std::vector<double>& values_0_1, const PngText& text) {
    if (channels < 1 || channels > 4)
        throw Error("write_png16: channels " + std::to_string(channels) + " is out of range; allowed: 1 to 4");
    check_size("write_png16", width, height);
    check_text("write_png16", text);
    const std::size_t nc = static_cast<std::size_t>(channels);
    const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * nc;
    if (values_0_1.size() != n)
        throw Error("write_png16: " + std::to_string(values_0_1.size()) + " values given for a " +
                    std::to_string(width) + "x" + std::to_string(height) + " image with " +
                    std::to_string(channels) + " channels; expected " + std::to_string(n));
    for (std::size_t i = 0; i < n; ++i) {
        const double v = values_0_1[i];
        if (v >= 0.0 && v <= 1.0) continue;  // false for NaN
        const std::size_t pixel = i / nc;
        char shortest[32];
        const auto end = std::to_chars(shortest, shortest + sizeof shortest, v).ptr;
        std::ostringstream s;
        s << "write_png16: value " << std::string_view(shortest, static_cast<std::size_t>(end - shortest)) << " at index " << i << " (pixel x " << pixel % static_cast<std::size_t>(width)
          << ", y " << pixel / static_cast<std::size_t>(width) << ", channel " << i % nc
          << ") is outside [0, 1]; a 16-bit PNG holds values in [0, 1] only; nothing was written";
        throw Error(s.str());
    }
    std::vector<std::uint16_t> samples(n);
    for (std::size_t i = 0; i < n; ++i) samples[i] = png16_sample(values_0_1[i]);
    write_png_samples(path, width, height, channels, 16, samples, text);
}

void write_png_samples(const std::string& path, int width, int height, int channels, int bits,
                       const std::vector<std::uint16_t>& samples, const PngText& text) {
    if (channels < 1 || channels > 4)
        throw Error("write_png_samples: channels " + std::to_string(channels) + " is out of range; allowed: 1 to 4");
    if (bits != 8 && bits != 16)
        throw Error("write_png_samples: " + std::to_string(bits) + " bits a sample; allowed: 8, 16");
    check_size("write_png_samples", width, height);
    check_text("write_png_samples", text);
    const std::size_t nc = static_cast<std::size_t>(channels), bytes_per = static_cast<std::size_t>(bits / 8);
    const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * nc;
    if (samples.size() != n)
        throw Error("write_png_samples: " + std::to_string(samples.size()) + " samples given for a " +
                    std::to_string(width) + "x" + std::to_string(height) + " image with " +
                    std::to_string(channels) + " channels; expected " + std::to_string(n));
    // PNG samples are big-endian.
    std::vector<png_byte> bytes(n * bytes_per);
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint16_t q = samples[i];
        if (bits == 16) {
            bytes[2 * i] = static_cast<png_byte>(q >> 8);
            bytes[2 * i + 1] = static_cast<png_byte>(q & 0xff);
        } else {
            if (q > 255) throw Error("write_png_samples: sample " + std::to_string(q) + " does not fit in 8 bits");
            bytes[i] = static_cast<png_byte>(q);
        }
    }
    static constexpr int kColorType[4] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                          PNG_COLOR_TYPE_RGBA};
    write_png(path, width, height, bits, kColorType[channels - 1], false, bytes,
              static_cast<std::size_t>(width) * nc * bytes_per, text);
}

}  // namespace brdflut
