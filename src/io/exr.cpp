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

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "brdflut/error.h"
#include "io/atomic_file.h"
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

constexpr std::size_t kMaxFileBytes = std::size_t{1} << 30;

}  // namespace

ExrImage read_exr_memory(const char* data, std::size_t size, const std::string& name) {
    ExrImage img;
    try {
        // OpenEXR's own checker reads every part of the file defensively
        // (bounded memory and time) and reports corruption without crashing.
        if (size < 4 || Imf::checkOpenEXRFile(data, size, true, true, true))
            throw RuntimeError("cannot read '" + name + "': not a valid OpenEXR file (corrupt, truncated or another format)");
        MemoryStream stream(data, size, name);
        Imf::InputFile in(stream);
        const Imf::Header& h = in.header();
        const Imath::Box2i dw = h.dataWindow();
        const long long w = static_cast<long long>(dw.max.x) - dw.min.x + 1;
        const long long ht = static_cast<long long>(dw.max.y) - dw.min.y + 1;
        if (w < 1 || ht < 1 || w * ht > (1LL << 28))
            throw RuntimeError("cannot read '" + name + "': image size " + std::to_string(w) + "x" +
                               std::to_string(ht) + " is not supported");
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
        if (names.size() > 64) throw RuntimeError("cannot read '" + name + "': too many channels");
        img.channel_names = names;
        img.pixel = any_half ? PixelType::half : PixelType::float32;
        const std::size_t nc = names.size();
        std::vector<float> buf(static_cast<std::size_t>(w * ht) * nc);
        Imf::FrameBuffer fb;
        // Slices are addressed relative to the data window origin.
        char* origin = reinterpret_cast<char*>(buf.data()) -
                       (static_cast<std::ptrdiff_t>(dw.min.x) +
                        static_cast<std::ptrdiff_t>(dw.min.y) * static_cast<std::ptrdiff_t>(w)) *
                           static_cast<std::ptrdiff_t>(nc * sizeof(float));
        for (std::size_t c = 0; c < nc; ++c)
            fb.insert(names[c], Imf::Slice(Imf::FLOAT, origin + c * sizeof(float), nc * sizeof(float),
                                           nc * sizeof(float) * static_cast<std::size_t>(w)));
        in.setFrameBuffer(fb);
        in.readPixels(dw.min.y, dw.max.y);
        img.pixels.assign(buf.begin(), buf.end());
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
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw RuntimeError("cannot read '" + path + "': no such file");
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) throw RuntimeError("cannot read '" + path + "': " + ec.message());
    if (size > kMaxFileBytes) throw RuntimeError("cannot read '" + path + "': larger than 1 GiB");
    std::ifstream in(path, std::ios::binary);
    std::vector<char> bytes(static_cast<std::size_t>(size));
    if (!in || !in.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
        throw RuntimeError("cannot read '" + path + "': " + std::strerror(errno));
    return read_exr_memory(bytes.data(), bytes.size(), path);
}

}  // namespace brdflut
