// The storage types of table values (brdflut/table.h): their names, ranges
// and decoding, and the integer encodings of a texel.
#include <Imath/half.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "brdflut/error.h"
#include "brdflut/table.h"

namespace brdflut {
namespace {

struct StorageInfo {
    Storage storage;
    const char* name;
    int bits;          // of an integer colour channel; 0 for the float types
    int max_channels;  // of a table stored this way
    double max;        // of an integer encoding's values (min 0)
    const char* decode;
};

constexpr std::array<StorageInfo, 6> kStorages{{
    {Storage::half, "half", 0, 4, 0.0, ""},
    {Storage::float32, "float", 0, 4, 0.0, ""},
    {Storage::unorm16, "unorm16", 16, 4, 1.0, "v = q / 65535 (q = round(v * 65535), to nearest)"},
    {Storage::unorm8, "unorm8", 8, 4, 1.0, "v = q / 255 (q = round(v * 255), to nearest)"},
    {Storage::rgb10a2, "rgb10a2", 10, 3, 1.0,
     "R10G10B10A2 UNORM: v = q / 1023 for R, G, B (bits 0-9, 10-19, 20-29), A = 3 (q = round(v * 1023), to "
     "nearest)"},
    {Storage::rgbd, "rgbd", 8, 3, 255.0,
     "Babylon.js RGBD in RGBA8: v = (q / 255)^2.2 / (a / 255), q in R, G, B and a in A (a = min(floor(max(255 / "
     "m, 1)), 255) for m the texel's largest value; q = round(255 * (v * a / 255)^(1 / 2.2)), to nearest)"},
}};

const StorageInfo& info(Storage s) {
    for (const auto& i : kStorages)
        if (i.storage == s) return i;
    return kStorages[1];
}

constexpr double kGamma = 2.2;           // Babylon.js's toLinearSpace / toGammaSpace exponent
constexpr double kRgbdMinMax = 1e-7;     // Babylon.js's maxEps

std::uint32_t unorm_max(Storage s) { return (1u << info(s).bits) - 1u; }

double rgbd_value(std::uint32_t q, std::uint32_t a) {
    return std::pow(static_cast<double>(q) / 255.0, kGamma) / (static_cast<double>(a) / 255.0);
}

}  // namespace

Storage storage_of(PixelType p) { return p == PixelType::half ? Storage::half : Storage::float32; }

std::string_view to_string(Storage s) { return info(s).name; }

std::string storage_names() {
    std::string out;
    for (const auto& i : kStorages) {
        if (!out.empty()) out += ", ";
        out += i.name;
    }
    return out;
}

Storage storage_from_string(std::string_view s) {
    for (const auto& i : kStorages)
        if (s == i.name) return i.storage;
    throw Error("encoding '" + std::string(s) + "' is not known; allowed: " + storage_names());
}

bool is_integer(Storage s) { return info(s).bits > 0; }
int max_channels(Storage s) { return info(s).max_channels; }
double storage_min(Storage s) { return is_integer(s) ? 0.0 : -HUGE_VAL; }
double storage_max(Storage s) { return is_integer(s) ? info(s).max : HUGE_VAL; }
std::string_view decode_rule(Storage s) { return info(s).decode; }

void encode_texel(Storage s, const double* v, int n, std::uint32_t q[4]) {
    if (s == Storage::rgbd) {
        double m = kRgbdMinMax;
        for (int c = 0; c < n; ++c) m = std::max(m, v[c]);
        const double a = std::min(std::floor(std::max(255.0 / m, 1.0)), 255.0);
        for (int c = 0; c < 3; ++c) {
            const double g = c < n ? std::pow(v[c] * a / 255.0, 1.0 / kGamma) : 0.0;
            q[c] = static_cast<std::uint32_t>(std::lround(std::clamp(g, 0.0, 1.0) * 255.0));
        }
        q[3] = static_cast<std::uint32_t>(a);
        return;
    }
    const std::uint32_t top = unorm_max(s);
    for (int c = 0; c < 4; ++c) {
        if (c < n)
            q[c] = static_cast<std::uint32_t>(std::lround(std::clamp(v[c], 0.0, 1.0) * static_cast<double>(top)));
        else
            q[c] = c == 3 ? (s == Storage::rgb10a2 ? 3u : top) : 0u;
    }
}

int decoded_channels(Storage s) { return s == Storage::rgbd ? 3 : 4; }

void decode_texel(Storage s, const std::uint32_t q[4], double* v) {
    if (s == Storage::rgbd) {
        for (int c = 0; c < 3; ++c) v[c] = rgbd_value(q[c], q[3]);
        return;
    }
    const double top = static_cast<double>(unorm_max(s));
    for (int c = 0; c < 3; ++c) v[c] = static_cast<double>(q[c]) / top;
    v[3] = static_cast<double>(q[3]) / (s == Storage::rgb10a2 ? 3.0 : top);
}

double encoding_step(Storage s, const std::uint32_t q[4], int c) {
    if (s != Storage::rgbd) return c == 3 && s == Storage::rgb10a2 ? 1.0 / 3.0 : 1.0 / unorm_max(s);
    // The gap to the code above (past 255 too): the decode is convex in q,
    // so it is the larger gap, and a value rounded to nearest in q lies
    // within half of it.
    return rgbd_value(q[c] + 1, q[3]) - rgbd_value(q[c], q[3]);
}

void round_texel(Storage s, const double* v, int n, double* out) {
    if (!is_integer(s)) {
        for (int c = 0; c < n; ++c) {
            const float f = static_cast<float>(v[c]);
            out[c] = s == Storage::half ? static_cast<double>(static_cast<float>(Imath::half(f)))
                                        : static_cast<double>(f);
        }
        return;
    }
    std::uint32_t q[4];
    double decoded[4];
    encode_texel(s, v, n, q);
    decode_texel(s, q, decoded);
    std::copy(decoded, decoded + n, out);
}

double round_to_storage(double v, Storage s) {
    double out = 0.0;
    round_texel(s, &v, 1, &out);
    return out;
}

double round_to_storage(double v, PixelType p) { return round_to_storage(v, storage_of(p)); }

}  // namespace brdflut
