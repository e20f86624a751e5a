// KTX 2.0 output: one uncompressed 2-D (or, for three axes, 3-D) level of a
// 16- or 32-bit float format.
//
// Layout (KTX File Format Specification 2.0, section "File Structure"):
//   identifier (12 bytes); header: vkFormat, typeSize, pixelWidth,
//   pixelHeight, pixelDepth, layerCount, faceCount, levelCount,
//   supercompressionScheme (UInt32 each); index: dfdByteOffset,
//   dfdByteLength, kvdByteOffset, kvdByteLength (UInt32), sgdByteOffset,
//   sgdByteLength (UInt64); level index: byteOffset, byteLength,
//   uncompressedByteLength (UInt64) per level; the Data Format Descriptor;
//   key/value data; mip padding; the level's texels. All little-endian.
#include <cstdint>
#include <map>
#include <numeric>
#include <string>

#include "brdflut/error.h"
#include "brdflut/version.h"
#include "io/binary.h"
#include "io/gpu_formats.h"
#include "io/table_checks.h"
#include "io/table_writers.h"

namespace brdflut {
namespace {

// Khronos Data Format Specification 1.3, "Khronos Basic Data Format
// Descriptor Block" (section 5) for a little-endian SFLOAT or UNORM format:
// one sample per channel (R10G10B10A2: four samples of one 32-bit word).
// The KTX spec ("Data Format Descriptor", "Restrictions") requires the
// samples to match vkFormat.
void write_dfd(ByteWriter& out, const GpuFormat& format) {
    constexpr std::uint32_t KHR_DF_VENDORID_KHRONOS = 0, KHR_DF_KHR_DESCRIPTORTYPE_BASICFORMAT = 0;
    constexpr std::uint32_t KHR_DF_VERSIONNUMBER_1_3 = 2;
    constexpr std::uint32_t KHR_DF_MODEL_RGBSDA = 1;
    // Table data has no colour primaries; three.js and others read
    // UNSPECIFIED + LINEAR as "no colour space", which is what a LUT is.
    // (rgbd's gamma is not a transfer function the DFD can name; the
    // metadata's `decode` gives it.)
    constexpr std::uint32_t KHR_DF_PRIMARIES_UNSPECIFIED = 0, KHR_DF_TRANSFER_LINEAR = 1;
    constexpr std::uint32_t KHR_DF_FLAG_ALPHA_STRAIGHT = 0;
    constexpr std::uint32_t KHR_DF_SAMPLE_DATATYPE_FLOAT = 0x80, KHR_DF_SAMPLE_DATATYPE_SIGNED = 0x40;
    constexpr std::uint32_t kChannelId[4] = {0, 1, 2, 15};  // RGBSDA red, green, blue, alpha
    constexpr std::uint32_t kMinusOne = 0xBF800000u, kPlusOne = 0x3F800000u;  // -1.0f, 1.0f

    const int channels = format.channels;
    const bool is_float = !is_integer(format.storage);
    const std::uint32_t block_size = 24 + 16 * static_cast<std::uint32_t>(channels);
    out.u32(4 + block_size);  // dfdTotalSize
    out.u32(KHR_DF_VENDORID_KHRONOS | KHR_DF_KHR_DESCRIPTORTYPE_BASICFORMAT << 17);
    out.u32(KHR_DF_VERSIONNUMBER_1_3 | block_size << 16);
    out.u32(KHR_DF_MODEL_RGBSDA | KHR_DF_PRIMARIES_UNSPECIFIED << 8 | KHR_DF_TRANSFER_LINEAR << 16 |
            KHR_DF_FLAG_ALPHA_STRAIGHT << 24);
    out.u32(0);  // texelBlockDimension0..3 = 0 (1x1x1x1)
    out.u32(static_cast<std::uint32_t>(format.texel_bytes()));  // bytesPlane0; planes 1..3 = 0
    out.u32(0);                                                 // bytesPlane4..7 = 0
    std::uint32_t offset = 0;
    for (int c = 0; c < channels; ++c) {
        const std::uint32_t bits = format.packed ? (c == 3 ? 2u : 10u)
                                                 : 8 * static_cast<std::uint32_t>(format.component_bytes);
        const std::uint32_t channel_type =
            kChannelId[c] | (is_float ? KHR_DF_SAMPLE_DATATYPE_FLOAT | KHR_DF_SAMPLE_DATATYPE_SIGNED : 0u);
        out.u32(offset | (bits - 1) << 16 | channel_type << 24);
        offset += bits;
        out.u32(0);  // samplePosition0..3
        // Float samples: sampleLower/Upper are the float values for -1 and 1
        // of a signed format (as Khronos' own dfdutils writes them); UNORM
        // samples: 0 and the largest integer.
        out.u32(is_float ? kMinusOne : 0u);
        out.u32(is_float ? kPlusOne : (1u << bits) - 1u);
    }
}

// KTX spec, "Key/Value Data": keys sorted by code point, each entry
// keyAndValueByteLength, key, NUL, value, padding to 4 bytes.
void write_key_values(ByteWriter& out, const std::map<std::string, std::string>& kv) {
    for (const auto& [key, value] : kv) {  // std::map: byte order = code point order for UTF-8
        out.u32(static_cast<std::uint32_t>(key.size() + 1 + value.size() + 1));
        out.raw(key);
        out.u8(0);
        out.raw(value);
        out.u8(0);  // string values are NUL-terminated (spec: "should be")
        out.align(4);
    }
}

}  // namespace

void write_ktx2(const std::string& path, const Table& table, Storage storage) {
    check_shape(table);
    check_storable(table, storage);
    const GpuFormat& format = gpu_format(storage, table.channel_count());
    const std::uint64_t texel_bytes = static_cast<std::uint64_t>(format.texel_bytes());
    const std::vector<std::uint8_t> texels = pack_texels(table, format);

    ByteWriter out;
    const char identifier[12] = {'\xAB', 'K', 'T', 'X', ' ', '2', '0', '\xBB', '\r', '\n', '\x1A', '\n'};
    out.raw(std::string_view(identifier, sizeof identifier));
    out.u32(format.vk);
    // typeSize: bytes of one component (of the 32-bit word of a packed format)
    out.u32(static_cast<std::uint32_t>(format.component_bytes));
    out.u32(static_cast<std::uint32_t>(table.width()));    // pixelWidth
    // pixelHeight: a 2-D texture also for one-axis tables (height 1), as the
    // dds and exr files are; pixelHeight 0 would make it a 1-D texture.
    // A table with three axes is a 3-D texture: pixelHeight y, pixelDepth z,
    // the slices one after another in the level (the same bytes as stacked rows).
    const bool volume = table.axes.size() == 3;
    out.u32(static_cast<std::uint32_t>(volume ? table.axes[1].count : table.height()));
    out.u32(volume ? static_cast<std::uint32_t>(table.axes[2].count) : 0u);  // pixelDepth
    out.u32(0);  // layerCount: not an array
    out.u32(1);  // faceCount
    out.u32(1);  // levelCount: the base level only, no mipmaps to generate
    out.u32(0);  // supercompressionScheme: none

    const std::size_t index_at = out.size();
    out.zeros(4 * 4 + 2 * 8);  // index, patched below
    const std::size_t level_index_at = out.size();
    out.zeros(3 * 8);  // level index, patched below

    const std::size_t dfd_at = out.size();
    write_dfd(out, format);
    const std::size_t kvd_at = out.size();
    write_key_values(out, {{"KTXorientation", "rd"},  // row 0 at the top, x to the right
                           {"KTXwriter", std::string(kName) + " " + kVersion},
                           {"brdflut", metadata_json(table, storage).dump()}});
    const std::size_t kvd_end = out.size();
    // "mipPadding": the level starts at a multiple of lcm(texel block size, 4).
    out.align(std::lcm(static_cast<std::size_t>(texel_bytes), std::size_t{4}));
    const std::size_t level_at = out.size();
    out.raw(texels);

    out.patch_u32(index_at, static_cast<std::uint32_t>(dfd_at));                 // dfdByteOffset
    out.patch_u32(index_at + 4, static_cast<std::uint32_t>(kvd_at - dfd_at));    // dfdByteLength
    out.patch_u32(index_at + 8, static_cast<std::uint32_t>(kvd_at));             // kvdByteOffset
    out.patch_u32(index_at + 12, static_cast<std::uint32_t>(kvd_end - kvd_at));  // kvdByteLength
    // sgdByteOffset, sgdByteLength stay 0: no supercompression global data.
    out.patch_u64(level_index_at, level_at);             // byteOffset
    out.patch_u64(level_index_at + 8, texels.size());    // byteLength
    out.patch_u64(level_index_at + 16, texels.size());   // uncompressedByteLength
    write_file_atomically(path, out.bytes());
}

}  // namespace brdflut
