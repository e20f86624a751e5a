#include "io/gpu_formats.h"

#include <Imath/half.h>

#include <array>
#include <cstring>

#include "brdflut/error.h"
#include "io/binary.h"

namespace brdflut {
namespace {

constexpr std::array<GpuFormat, 14> kGpuFormats{{
    {Storage::half, 1, 54, 76, 2, false},      // R16_FLOAT, R16_SFLOAT
    {Storage::half, 2, 34, 83, 2, false},      // R16G16_FLOAT, R16G16_SFLOAT
    {Storage::half, 4, 10, 97, 2, false},      // R16G16B16A16_FLOAT, R16G16B16A16_SFLOAT
    {Storage::float32, 1, 41, 100, 4, false},  // R32_FLOAT, R32_SFLOAT
    {Storage::float32, 2, 16, 103, 4, false},  // R32G32_FLOAT, R32G32_SFLOAT
    {Storage::float32, 4, 2, 109, 4, false},   // R32G32B32A32_FLOAT, R32G32B32A32_SFLOAT
    {Storage::unorm8, 1, 61, 9, 1, false},     // R8_UNORM
    {Storage::unorm8, 2, 49, 16, 1, false},    // R8G8_UNORM
    {Storage::unorm8, 4, 28, 37, 1, false},    // R8G8B8A8_UNORM
    {Storage::unorm16, 1, 56, 70, 2, false},   // R16_UNORM
    {Storage::unorm16, 2, 35, 77, 2, false},   // R16G16_UNORM
    {Storage::unorm16, 4, 11, 91, 2, false},   // R16G16B16A16_UNORM
    // R10G10B10A2_UNORM; Vulkan's A2B10G10R10_UNORM_PACK32 has the same bits
    // (R in the least significant ten).
    {Storage::rgb10a2, 4, 24, 64, 4, true},
    {Storage::rgbd, 4, 28, 37, 1, false},      // R8G8B8A8_UNORM, D in A
}};

void put_le(std::vector<std::uint8_t>& out, std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

std::uint64_t get_le(const unsigned char* p, int n) {
    std::uint64_t v = 0;
    for (int i = n - 1; i >= 0; --i) v = v << 8 | p[i];
    return v;
}

}  // namespace

const GpuFormat& gpu_format(Storage s, int table_channels) {
    const int stored = is_integer(s) && max_channels(s) == 3 ? 4 : (table_channels == 3 ? 4 : table_channels);
    for (const GpuFormat& f : kGpuFormats)
        if (f.storage == s && f.channels == stored) return f;
    throw Error("no dds or ktx2 format stores " + std::to_string(table_channels) + " channel(s) as " +
                std::string(to_string(s)));
}

const GpuFormat* gpu_format_by_dxgi(std::uint32_t dxgi) {
    for (const GpuFormat& f : kGpuFormats)
        if (f.dxgi == dxgi) return &f;
    return nullptr;
}

const GpuFormat* gpu_format_by_vk(std::uint32_t vk) {
    for (const GpuFormat& f : kGpuFormats)
        if (f.vk == vk) return &f;
    return nullptr;
}

std::vector<std::uint8_t> pack_texels(const Table& t, const GpuFormat& f) {
    const std::size_t nc = t.channels.size(), sc = static_cast<std::size_t>(f.channels);
    std::vector<std::uint8_t> out;
    out.reserve(t.texel_count() * static_cast<std::size_t>(f.texel_bytes()));
    for (std::size_t k = 0; k < t.texel_count(); ++k) {
        const double* v = &t.values[k * nc];
        if (!is_integer(f.storage)) {
            for (std::size_t c = 0; c < sc; ++c) {
                // Rounded as round_to_storage does (double -> float -> half).
                const float x = static_cast<float>(c < nc ? v[c] : 1.0);
                if (f.storage == Storage::half) {
                    put_le(out, Imath::half(x).bits(), 2);
                } else {
                    std::uint32_t bits;
                    std::memcpy(&bits, &x, sizeof bits);
                    put_le(out, bits, 4);
                }
            }
            continue;
        }
        std::uint32_t q[4];
        encode_texel(f.storage, v, static_cast<int>(nc), q);
        if (f.packed) {
            put_le(out, q[0] | q[1] << 10 | q[2] << 20 | q[3] << 30, 4);
            continue;
        }
        for (std::size_t c = 0; c < sc; ++c) put_le(out, q[c], f.component_bytes);
    }
    return out;
}

void unpack_texels(const unsigned char* data, std::size_t texels, const GpuFormat& f, std::vector<double>& values) {
    const int bytes = f.texel_bytes();
    for (std::size_t k = 0; k < texels; ++k) {
        const unsigned char* p = data + k * static_cast<std::size_t>(bytes);
        if (f.packed) {
            const std::uint32_t w = static_cast<std::uint32_t>(get_le(p, 4));
            const std::uint32_t q[4] = {w & 1023u, w >> 10 & 1023u, w >> 20 & 1023u, w >> 30};
            double v[4];
            decode_texel(f.storage, q, v);
            values.insert(values.end(), v, v + 4);
            continue;
        }
        for (int c = 0; c < f.channels; ++c) {
            const std::uint64_t bits = get_le(p + c * f.component_bytes, f.component_bytes);
            double v = 0.0;
            if (f.storage == Storage::half) {
                Imath::half h;
                h.setBits(static_cast<unsigned short>(bits));
                v = static_cast<double>(static_cast<float>(h));
            } else if (f.storage == Storage::float32) {
                const std::uint32_t b32 = static_cast<std::uint32_t>(bits);
                float x;
                std::memcpy(&x, &b32, sizeof x);
                v = static_cast<double>(x);
            } else {
                // unorm8, unorm16 (and rgbd's bytes, read as unorm8 until decoded)
                v = static_cast<double>(bits) / static_cast<double>((1ull << (8 * f.component_bytes)) - 1);
            }
            values.push_back(v);
        }
    }
}

}  // namespace brdflut
