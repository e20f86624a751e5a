#pragma once

namespace brdflut {
inline constexpr const char* kName = "brdflut";
inline constexpr const char* kVersion = "0.1.0";
}  // namespace brdflut
