// The largest image the readers accept. No table is larger (axis.h: at most
// kMaxTexels texels and 4 channels), so a file that declares more is refused
// from its header, before anything is allocated for its pixels.
#pragma once

#include <string>

#include "brdflut/axis.h"

namespace brdflut {

inline constexpr long long kMaxImagePixels = kMaxTexels;
inline constexpr long long kMaxImageChannels = 64;
inline constexpr long long kMaxImageValues = 4 * kMaxTexels;  // pixels times channels

// Empty when a width x height image of `channels` channels is within the
// limits, else the reason: "is WxH pixels with N channel(s); supported are ...".
inline std::string image_size_problem(long long width, long long height, long long channels) {
    if (width >= 1 && height >= 1 && width <= kMaxImagePixels / height && channels <= kMaxImageChannels &&
        width * height * channels <= kMaxImageValues)
        return {};
    return "is " + std::to_string(width) + "x" + std::to_string(height) + " pixels with " + std::to_string(channels) +
           " channel(s); supported are at most " + std::to_string(kMaxImagePixels) + " pixels, " +
           std::to_string(kMaxImageChannels) + " channels and " + std::to_string(kMaxImageValues) + " values";
}

}  // namespace brdflut
