// The texture formats dds and ktx2 store, one entry per storage type and
// stored channel count: the DXGI and Vulkan format codes, and how a texel is
// laid out. Writers and readers of both formats go through this list.
#pragma once

#include <cstdint>
#include <vector>

#include "brdflut/table.h"

namespace brdflut {

struct GpuFormat {
    Storage storage;
    int channels;             // stored channels: 1, 2 or 4
    std::uint32_t dxgi;       // DXGI_FORMAT (dxgiformat.h)
    std::uint32_t vk;         // VkFormat (Vulkan specification, "Formats")
    int component_bytes;      // of one channel; 4 for the packed 32-bit word of rgb10a2
    bool packed;              // one 32-bit word a texel (rgb10a2)
    int texel_bytes() const { return packed ? component_bytes : channels * component_bytes; }
};

// The format a table of `table_channels` channels is stored in with storage
// s: 1, 2 or 4 channels (3 padded with A = 1), always 4 for rgb10a2 and rgbd.
const GpuFormat& gpu_format(Storage s, int table_channels);
// The format with this DXGI or Vulkan code, or nullptr; RGBA8 UNORM is
// unorm8 (an rgbd texture has the same code; its metadata or --decode rgbd
// says which).
const GpuFormat* gpu_format_by_dxgi(std::uint32_t dxgi);
const GpuFormat* gpu_format_by_vk(std::uint32_t vk);

// The table's values as stored texels of format f, little-endian, texels in
// the table's order (row 0 first); float channels rounded as
// round_to_storage, integer ones encoded by encode_texel.
std::vector<std::uint8_t> pack_texels(const Table& t, const GpuFormat& f);

// The inverse for `texels` texels at `data` (which holds texels *
// f.texel_bytes() bytes): their values appended to `values` (f.channels
// per texel; 4 for rgb10a2).
void unpack_texels(const unsigned char* data, std::size_t texels, const GpuFormat& f, std::vector<double>& values);

}  // namespace brdflut
