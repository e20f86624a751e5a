#include "io/binary.h"

#include <Imath/half.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "brdflut/error.h"
#include "io/atomic_file.h"

namespace brdflut {

void ByteWriter::patch_u32(std::size_t offset, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes_.at(offset + static_cast<std::size_t>(i)) = static_cast<std::uint8_t>(v >> (8 * i));
}

void ByteWriter::patch_u64(std::size_t offset, std::uint64_t v) {
    for (int i = 0; i < 8; ++i) bytes_.at(offset + static_cast<std::size_t>(i)) = static_cast<std::uint8_t>(v >> (8 * i));
}

std::vector<std::uint8_t> pack_texels(const Table& t, PixelType pixel, int stored_channels) {
    const std::size_t nc = t.channels.size(), sc = static_cast<std::size_t>(stored_channels);
    ByteWriter out;
    for (std::size_t k = 0; k < t.texel_count(); ++k) {
        for (std::size_t c = 0; c < sc; ++c) {
            const double v = c < nc ? t.values[k * nc + c] : 1.0;
            // Rounded as round_to_storage does (double -> float -> half).
            if (pixel == PixelType::half) {
                out.u16(Imath::half(static_cast<float>(v)).bits());
            } else {
                std::uint32_t bits;
                const float f = static_cast<float>(v);
                std::memcpy(&bits, &f, sizeof bits);
                out.u32(bits);
            }
        }
    }
    return out.bytes();
}

void write_file_atomically(const std::string& path, std::string_view bytes) {
    AtomicFile file(path);
    std::FILE* f = std::fopen(file.temp_path().c_str(), "wb");
    if (f == nullptr) throw RuntimeError("cannot write '" + path + "': " + std::strerror(errno));
    const bool written = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
    const int write_errno = errno;
    const bool closed = std::fclose(f) == 0;
    if (!written) throw RuntimeError("cannot write '" + path + "': " + std::strerror(write_errno));
    if (!closed) throw RuntimeError("cannot write '" + path + "': " + std::strerror(errno));
    file.commit();
}

}  // namespace brdflut
