#include "brdflut/exr.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfCheckFile.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <Imath/half.h>
#include <openexr.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "brdflut/error.h"
#include "io/atomic_file.h"
#include "io/image_limits.h"
#include "io/input_file.h"
#include "io/table_checks.h"

namespace brdflut {
namespace {
constexpr const char* kChannelNames[4] = {"R", "G", "B", "A"};
}  // namespace

void write_exr(const std::string& path, const Table& table, PixelType pixel) {
    check_shape(table);
    check_storable(table, storage_of(pixel));
    const int nc = table.channel_count();
    const int width = table.width(), height = table.height();
    const std::string json = metadata_json(table, pixel).dump();

    Imf::Header header(width, height);
    header.compression() = Imf::ZIP_COMPRESSION;
    header.insert(kMetadataAttribute, Imf::StringAttribute(json));
    const Imf::PixelType type = pixel == PixelType::half ? Imf::HALF : Imf::FLOAT;
    for (int c = 0; c < nc; ++c) header.channels().insert(kChannelNames[c], Imf::Channel(type));

    const std::size_t n = table.values.size();
    std::vector<float> f32;
    std::vector<Imath::half> f16;
    Imf::FrameBuffer fb;
    if (pixel == PixelType::half) {
        f16.resize(n);
        for (std::size_t i = 0; i < n; ++i) f16[i] = Imath::half(static_cast<float>(table.values[i]));
    } else {
        f32.resize(n);
        for (std::size_t i = 0; i < n; ++i) f32[i] = static_cast<float>(table.values[i]);
    }
    const std::size_t elem = pixel == PixelType::half ? sizeof(Imath::half) : sizeof(float);
    char* base = pixel == PixelType::half ? reinterpret_cast<char*>(f16.data())
                                          : reinterpret_cast<char*>(f32.data());
    for (int c = 0; c < nc; ++c) {
        fb.insert(kChannelNames[c],
                  Imf::Slice(type, base + static_cast<std::size_t>(c) * elem,
                             elem * static_cast<std::size_t>(nc),
                             elem * static_cast<std::size_t>(nc) * static_cast<std::size_t>(width)));
    }

    AtomicFile file(path);
    try {
        Imf::OutputFile out(file.temp_path().c_str(), header);
        out.setFrameBuffer(fb);
        out.writePixels(height);
    } catch (const std::exception& e) {
        throw RuntimeError("cannot write '" + path + "': " + e.what());
    }
    file.commit();
}

namespace {

// An OpenEXR input stream over bytes in memory.
class MemoryStream final : public Imf::IStream {
public:
    MemoryStream(const char* data, std::size_t size, const std::string& name)
        : Imf::IStream(name.c_str()), data_(data), size_(size) {}
    bool read(char c[], int n) override {
        if (n < 0 || static_cast<std::uint64_t>(n) > size_ - pos_) throw std::runtime_error("unexpected end of file");
        std::memcpy(c, data_ + pos_, static_cast<std::size_t>(n));
        pos_ += static_cast<std::uint64_t>(n);
        return pos_ < size_;
    }
    uint64_t tellg() override { return pos_; }
    void seekg(uint64_t pos) override {
        if (pos > size_) throw std::runtime_error("seek past the end of file");
        pos_ = pos;
    }

private:
    const char* data_;
    std::uint64_t size_;
    std::uint64_t pos_ = 0;
};

// Bytes of one compressed chunk (a block of scan lines, or a tile) once
// decoded; OpenEXR allocates its buffers from this. A table is at most
// kMaxAxisCount wide, so 4 float channels in 256-line chunks fit.
constexpr long long kMaxChunkBytes = 1LL << 26;

// Checks the headers with OpenEXRCore before the C++ reader sees them.
// Strict mode checks every declared attribute size against the bytes
// actually present; the C++ reader and its file checker trust those sizes and
// allocate them up front, as they do buffers for the declared image and tile
// sizes. So a few damaged bytes could claim gigabytes. Returns an empty
// string when the file is sound and small enough, else what is wrong with it.
std::string preflight(const char* data, std::size_t size) {
    struct Source {
        const char* data;
        std::size_t size;
        std::string error;
    } src{data, size, {}};
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.user_data = &src;
    init.read_fn = [](exr_const_context_t, void* user, void* buffer, uint64_t sz, uint64_t offset,
                      exr_stream_error_func_ptr_t) -> int64_t {
        const auto* s = static_cast<const Source*>(user);
        if (offset >= s->size) return 0;
        const uint64_t n = std::min<uint64_t>(sz, s->size - offset);
        std::memcpy(buffer, s->data + offset, static_cast<std::size_t>(n));
        return static_cast<int64_t>(n);
    };
    init.size_fn = [](exr_const_context_t, void* user) -> int64_t {
        return static_cast<int64_t>(static_cast<const Source*>(user)->size);
    };
    init.error_handler_fn = [](exr_const_context_t ctxt, exr_result_t, const char* msg) {
        void* user = nullptr;
        if (exr_get_user_data(ctxt, &user) == EXR_ERR_SUCCESS && user) {
            auto* s = static_cast<Source*>(user);
            if (s->error.empty() && msg) s->error = msg;
        }
    };
    init.flags = EXR_CONTEXT_FLAG_STRICT_HEADER;
    exr_context_t ctxt = nullptr;
    const exr_result_t rv = exr_start_read(&ctxt, "input", &init);
    if (rv != EXR_ERR_SUCCESS) {
        if (ctxt) exr_finish(&ctxt);
        return "not a valid OpenEXR file (" +
               (src.error.empty() ? std::string(exr_get_default_error_message(rv)) : src.error) + ")";
    }
    std::string why;
    int parts = 0;
    if (exr_get_count(ctxt, &parts) != EXR_ERR_SUCCESS || parts < 1) why = "not a valid OpenEXR file (no image parts)";
    for (int p = 0; p < parts && why.empty(); ++p) {
        const std::string part = "part " + std::to_string(p);
        exr_storage_t storage{};
        exr_attr_box2i_t dw{};
        const exr_attr_chlist_t* channels = nullptr;
        if (exr_get_storage(ctxt, p, &storage) != EXR_ERR_SUCCESS ||
            exr_get_data_window(ctxt, p, &dw) != EXR_ERR_SUCCESS ||
            exr_get_channels(ctxt, p, &channels) != EXR_ERR_SUCCESS || !channels) {
            why = "not a valid OpenEXR file (" + part + " lacks a required attribute)";
            break;
        }
        if (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED) {
            why = part + " holds deep data, which no table uses";
            break;
        }
        const long long w = static_cast<long long>(dw.max.x) - dw.min.x + 1;
        const long long h = static_cast<long long>(dw.max.y) - dw.min.y + 1;
        const int nc = channels->num_channels;
        if (const std::string size = image_size_problem(w, h, nc); !size.empty()) {
            why = part + " " + size;
            break;
        }
        long long pixel_bytes = 0;
        for (int c = 0; c < nc; ++c) pixel_bytes += channels->entries[c].pixel_type == EXR_PIXEL_HALF ? 2 : 4;
        long long chunk_w = w, chunk_h = 0;
        if (storage == EXR_STORAGE_TILED) {
            uint32_t tx = 0, ty = 0;
            exr_tile_level_mode_t levels{};
            exr_tile_round_mode_t rounding{};
            if (exr_get_tile_descriptor(ctxt, p, &tx, &ty, &levels, &rounding) == EXR_ERR_SUCCESS) {
                chunk_w = tx;
                chunk_h = ty;
            }
        } else {
            int32_t lines = 0;
            if (exr_get_scanlines_per_chunk(ctxt, p, &lines) == EXR_ERR_SUCCESS) chunk_h = lines;
        }
        int32_t chunks = 0;
        if (exr_get_chunk_count(ctxt, p, &chunks) != EXR_ERR_SUCCESS || chunks < 1 ||
            static_cast<std::uint64_t>(chunks) * 8 > size) {
            // Each block has an 8-byte entry in the offset table.
            why = "not a valid OpenEXR file (truncated: " + part + " declares " + std::to_string(chunks) +
                  " blocks but the file has " + std::to_string(size) + " bytes)";
            break;
        }
        if (chunk_h < 1 || chunk_w * chunk_h * pixel_bytes > kMaxChunkBytes)
            why = part + " is stored in blocks of " + std::to_string(chunk_w) + "x" + std::to_string(chunk_h) +
                  " pixels of " + std::to_string(pixel_bytes) + " bytes; at most " + std::to_string(kMaxChunkBytes) +
                  " bytes per block are supported";
    }
    exr_finish(&ctxt);
    return why;
}

}  // namespace

ExrImage read_exr_memory(const char* data, std::size_t size, const std::string& name) {
    ExrImage img;
    try {
        // First the header sizes (preflight), then OpenEXR's own checker,
        // which reads every part of the file defensively (bounded memory and
        // time) and reports corruption without crashing.
        const std::string not_exr = "cannot read '" + name + "': not a valid OpenEXR file";
        if (size < 4) throw RuntimeError(not_exr + " (too short)");
        if (const std::string why = preflight(data, size); !why.empty())
            throw RuntimeError("cannot read '" + name + "': " + why);
        if (Imf::checkOpenEXRFile(data, size, true, true, true))
            throw RuntimeError(not_exr + " (corrupt, truncated or another format)");
        MemoryStream stream(data, size, name);
        Imf::InputFile in(stream);
        const Imf::Header& h = in.header();
        const Imath::Box2i dw = h.dataWindow();
        const long long w = static_cast<long long>(dw.max.x) - dw.min.x + 1;
        const long long ht = static_cast<long long>(dw.max.y) - dw.min.y + 1;
        img.width = static_cast<int>(w);
        img.height = static_cast<int>(ht);
        // R, G, B, A first in that order, then any other channels by name.
        std::vector<std::string> names;
        for (const char* c : kChannelNames)
            if (h.channels().findChannel(c)) names.push_back(c);
        bool any_half = false;
        for (auto it = h.channels().begin(); it != h.channels().end(); ++it) {
            const std::string cname = it.name();
            if (it.channel().type == Imf::HALF) any_half = true;
            if (it.channel().xSampling != 1 || it.channel().ySampling != 1)
                throw RuntimeError("cannot read '" + name + "': channel '" + cname + "' is subsampled");
            if (std::find(names.begin(), names.end(), cname) == names.end()) names.push_back(cname);
        }
        if (names.empty()) throw RuntimeError("cannot read '" + name + "': no channels");
        img.channel_names = names;
        img.pixel = any_half ? PixelType::half : PixelType::float32;
        const std::size_t nc = names.size();
        // Decode a strip of rows at a time so that memory grows only with
        // data actually present: a damaged file that declares a large image
        // fails on its first missing rows instead of after a large allocation.
        const std::size_t row = static_cast<std::size_t>(w) * nc;
        const long long strip_rows = std::clamp<long long>(static_cast<long long>((1u << 20) / row), 1, ht);
        std::vector<float> strip(static_cast<std::size_t>(strip_rows) * row);
        const std::ptrdiff_t pixel_bytes = static_cast<std::ptrdiff_t>(nc * sizeof(float));
        for (long long y0 = dw.min.y; y0 <= dw.max.y; y0 += strip_rows) {
            const long long y1 = std::min<long long>(dw.max.y, y0 + strip_rows - 1);
            // OpenEXR addresses a slice as base + x * xStride + y * yStride.
            char* origin = reinterpret_cast<char*>(strip.data()) -
                           (static_cast<std::ptrdiff_t>(dw.min.x) + static_cast<std::ptrdiff_t>(y0) * w) * pixel_bytes;
            Imf::FrameBuffer fb;
            for (std::size_t c = 0; c < nc; ++c)
                fb.insert(names[c], Imf::Slice(Imf::FLOAT, origin + c * sizeof(float), nc * sizeof(float),
                                               row * sizeof(float)));
            in.setFrameBuffer(fb);
            in.readPixels(static_cast<int>(y0), static_cast<int>(y1));
            img.pixels.insert(img.pixels.end(), strip.begin(),
                              strip.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(y1 - y0 + 1) * row));
        }
        if (const auto* attr = h.findTypedAttribute<Imf::StringAttribute>(kMetadataAttribute)) {
            img.metadata = nlohmann::json::parse(attr->value());
            img.has_metadata = true;
        }
    } catch (const RuntimeError&) {
        throw;
    } catch (const nlohmann::json::exception& e) {
        throw RuntimeError("cannot read '" + name + "': metadata is not valid JSON: " + e.what());
    } catch (const std::exception& e) {
        throw RuntimeError("cannot read '" + name + "': " + e.what());
    }
    return img;
}

ExrImage read_exr(const std::string& path) {
    // Look before reading: a regular file (not a FIFO or a device), the
    // OpenEXR magic number in its first bytes, then at most the size limit.
    InputFile file(path);
    if (file.head(4) != std::string("\x76\x2f\x31\x01", 4))
        file.fail("not a valid OpenEXR file (its first bytes are not the OpenEXR magic number)");
    const std::string bytes = file.read_all(kMaxBinaryFileBytes, "an OpenEXR file");
    return read_exr_memory(bytes.data(), bytes.size(), path);
}

}  // namespace brdflut
