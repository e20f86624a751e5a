// Little-endian byte buffers for the binary texture writers (DDS, KTX2).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "brdflut/table.h"

namespace brdflut {

class ByteWriter {
public:
    void u8(std::uint8_t v) { bytes_.push_back(v); }
    void u16(std::uint16_t v) { put(v, 2); }
    void u32(std::uint32_t v) { put(v, 4); }
    void u64(std::uint64_t v) { put(v, 8); }
    void raw(std::string_view s) { bytes_.insert(bytes_.end(), s.begin(), s.end()); }
    void raw(const std::vector<std::uint8_t>& b) { bytes_.insert(bytes_.end(), b.begin(), b.end()); }
    void zeros(std::size_t n) { bytes_.insert(bytes_.end(), n, 0); }
    // Zero bytes up to the next multiple of `alignment`.
    void align(std::size_t alignment) { zeros((alignment - bytes_.size() % alignment) % alignment); }
    // Overwrites 4 bytes at `offset` (for fields known only later).
    void patch_u32(std::size_t offset, std::uint32_t v);
    void patch_u64(std::size_t offset, std::uint64_t v);
    std::size_t size() const { return bytes_.size(); }
    const std::vector<std::uint8_t>& bytes() const { return bytes_; }

private:
    void put(std::uint64_t v, int n) {
        for (int i = 0; i < n; ++i) bytes_.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    }
    std::vector<std::uint8_t> bytes_;
};

// Writes the bytes to `path` atomically (AtomicFile); RuntimeError on failure.
void write_file_atomically(const std::string& path, std::string_view bytes);
inline void write_file_atomically(const std::string& path, const std::vector<std::uint8_t>& bytes) {
    write_file_atomically(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace brdflut
