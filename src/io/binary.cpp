#include "io/binary.h"


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
