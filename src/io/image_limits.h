// The largest image and file the readers accept. No table is larger
// (axis.h: at most kMaxTexels texels and 4 channels), so a file that declares
// more is refused from its header, before anything is allocated for its
// pixels; a file larger than its kind allows is refused from its size,
// before it is read.
#pragma once

#include <cstdint>
#include <string>

#include "brdflut/axis.h"

namespace brdflut {

inline constexpr long long kMaxImagePixels = kMaxTexels;
inline constexpr long long kMaxImageChannels = 64;
inline constexpr long long kMaxImageValues = 4 * kMaxTexels;  // pixels times channels

// Binary files (exr, png, dds, ktx2, npy): every value of the largest image
// as a 32-bit float fits, with room for headers.
inline constexpr std::uint64_t kMaxBinaryFileBytes = std::uint64_t{1} << 30;  // 1 GiB
// Source files holding arrays (C, C++, GLSL, HLSL, JavaScript). The largest
// engine source with tables is a few MiB; each number takes at least two
// bytes ("0,"), so at most 32 Mi numbers are held.
inline constexpr std::uint64_t kMaxTextFileBytes = std::uint64_t{64} << 20;  // 64 MiB

// Empty when a width x height image of `channels` channels is within the
// limits, else the reason: "is WxH pixels with N channel(s); supported are ...".
inline std::string image_size_problem(long long width, long long height, long long channels) {
    if (width >= 1 && height >= 1 && width <= kMaxImagePixels / height && channels >= 1 &&
        channels <= kMaxImageChannels && width * height * channels <= kMaxImageValues)
        return {};
    return "is " + std::to_string(width) + "x" + std::to_string(height) + " pixels with " + std::to_string(channels) +
           " channel(s); supported are at most " + std::to_string(kMaxImagePixels) + " pixels, " +
           std::to_string(kMaxImageChannels) + " channels and " + std::to_string(kMaxImageValues) + " values";
}

}  // namespace brdflut
