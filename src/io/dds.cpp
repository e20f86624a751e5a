// DirectDraw Surface output with the DX10 header extension.
//
// Layout (Microsoft Learn, "DDS programming guide", "DDS_HEADER structure",
// "DDS_PIXELFORMAT structure", "DDS_HEADER_DXT10 structure"):
//   DWORD magic "DDS "; DDS_HEADER (124 bytes); DDS_HEADER_DXT10 (20 bytes);
//   the texels of the single mip level, rows top to bottom, tightly packed.
// A table with three axes is a volume texture (DDSD_DEPTH, DDSCAPS2_VOLUME,
// TEXTURE3D): width x, height y, depth z, the slices one after another.
// All fields little-endian.
#include <cstdint>

#include "brdflut/error.h"
#include "io/binary.h"
#include "io/gpu_formats.h"
#include "io/table_checks.h"
#include "io/table_writers.h"

namespace brdflut {
namespace {

// DDS_HEADER.dwFlags
constexpr std::uint32_t DDSD_CAPS = 0x1, DDSD_HEIGHT = 0x2, DDSD_WIDTH = 0x4, DDSD_PITCH = 0x8,
                        DDSD_PIXELFORMAT = 0x1000, DDSD_MIPMAPCOUNT = 0x20000, DDSD_DEPTH = 0x800000;
// DDS_PIXELFORMAT.dwFlags
constexpr std::uint32_t DDPF_FOURCC = 0x4;
// DDS_HEADER.dwCaps
constexpr std::uint32_t DDSCAPS_COMPLEX = 0x8, DDSCAPS_TEXTURE = 0x1000;
// DDS_HEADER.dwCaps2
constexpr std::uint32_t DDSCAPS2_VOLUME = 0x200000;
// D3D10_RESOURCE_DIMENSION
constexpr std::uint32_t kTexture2D = 3, kTexture3D = 4;
// DDS_HEADER_DXT10.miscFlags2: alpha mode
constexpr std::uint32_t DDS_ALPHA_MODE_UNKNOWN = 0, DDS_ALPHA_MODE_OPAQUE = 3, DDS_ALPHA_MODE_CUSTOM = 4;

constexpr std::uint32_t fourcc(char a, char b, char c, char d) {
    return static_cast<std::uint32_t>(static_cast<unsigned char>(a)) |
           static_cast<std::uint32_t>(static_cast<unsigned char>(b)) << 8 |
           static_cast<std::uint32_t>(static_cast<unsigned char>(c)) << 16 |
           static_cast<std::uint32_t>(static_cast<unsigned char>(d)) << 24;
}

}  // namespace

void write_dds(const std::string& path, const Table& table, Storage storage) {
    check_shape(table);
    check_storable(table, storage);
    const GpuFormat& format = gpu_format(storage, table.channel_count());
    const int channels = format.channels;
    const std::uint32_t width = static_cast<std::uint32_t>(table.width());
    const bool volume = table.axes.size() == 3;
    const std::uint32_t depth = volume ? static_cast<std::uint32_t>(table.axes[2].count) : 0u;
    const std::uint32_t height = static_cast<std::uint32_t>(volume ? table.axes[1].count : table.height());
    const std::uint32_t texel_bytes = static_cast<std::uint32_t>(format.texel_bytes());

    ByteWriter out;
    out.u32(fourcc('D', 'D', 'S', ' '));
    // DDS_HEADER
    out.u32(124);  // dwSize
    out.u32(DDSD_CAPS | DDSD_HEIGHT | DDSD_WIDTH | DDSD_PIXELFORMAT | DDSD_PITCH | DDSD_MIPMAPCOUNT |
            (volume ? DDSD_DEPTH : 0u));
    out.u32(height);
    out.u32(width);
    out.u32(width * texel_bytes);  // dwPitchOrLinearSize: bytes per row of an uncompressed texture
    out.u32(depth);                // dwDepth (0 unless a volume)
    out.u32(1);                    // dwMipMapCount
    out.zeros(11 * 4);             // dwReserved1[11]
    // DDS_PIXELFORMAT: the format is in the DX10 header.
    out.u32(32);  // dwSize
    out.u32(DDPF_FOURCC);
    out.u32(fourcc('D', 'X', '1', '0'));
    out.zeros(5 * 4);  // dwRGBBitCount, dwRBitMask, dwGBitMask, dwBBitMask, dwABitMask
    out.u32(DDSCAPS_TEXTURE | (volume ? DDSCAPS_COMPLEX : 0u));  // dwCaps
    out.u32(volume ? DDSCAPS2_VOLUME : 0u);                      // dwCaps2
    out.zeros(3 * 4);                                            // dwCaps3, dwCaps4, dwReserved2
    // DDS_HEADER_DXT10
    out.u32(format.dxgi);
    // A 2-D texture also for one-axis tables (height 1): every loader takes it.
    out.u32(volume ? kTexture3D : kTexture2D);
    out.u32(0);           // miscFlag
    out.u32(1);           // arraySize
    // A is padding (= 1) for 3-channel tables, data for 4-channel ones.
    out.u32(table.channel_count() == 3 ? DDS_ALPHA_MODE_OPAQUE
                                       : (channels == 4 ? DDS_ALPHA_MODE_CUSTOM : DDS_ALPHA_MODE_UNKNOWN));
    out.raw(pack_texels(table, format));
    write_file_atomically(path, out.bytes());
}

}  // namespace brdflut
