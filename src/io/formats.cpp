#include "brdflut/formats.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <iterator>
#include <string_view>

#include "brdflut/error.h"
#include "brdflut/exr.h"
#include "brdflut/png.h"
#include "io/table_checks.h"
#include "io/table_writers.h"

namespace brdflut {
namespace {

using S = Storage;
struct FormatInfo {
    Format format;
    const char* name;
    const char* extension;
    // The storage types the format holds; the first is used when none is
    // asked for and the pixel type is not one of them.
    std::array<Storage, 6> storages;
    int storage_count;
};
constexpr std::array<FormatInfo, 6> kFormats{{
    {Format::exr, "exr", "exr", {S::float32, S::half}, 2},
    {Format::cpp, "cpp", "h", {S::float32, S::half}, 2},
    {Format::png16, "png16", "png", {S::unorm16}, 1},
    {Format::png, "png", "png", {S::unorm16, S::unorm8, S::rgbd}, 3},
    {Format::dds, "dds", "dds", {S::float32, S::half, S::unorm8, S::unorm16, S::rgb10a2, S::rgbd}, 6},
    {Format::ktx2, "ktx2", "ktx2", {S::float32, S::half, S::unorm8, S::unorm16, S::rgb10a2, S::rgbd}, 6},
}};

const FormatInfo& info(Format f) {
    for (const auto& i : kFormats)
        if (i.format == f) return i;
    return kFormats[0];
}

constexpr std::string_view kKeywords[] = {
    "alignas", "alignof", "and", "and_eq", "asm", "auto", "bitand", "bitor", "bool", "break", "case", "catch",
    "char", "char8_t", "char16_t", "char32_t", "class", "compl", "concept", "const", "consteval", "constexpr",
    "constinit", "const_cast", "continue", "co_await", "co_return", "co_yield", "decltype", "default",
    "delete", "do", "double", "dynamic_cast", "else", "enum", "explicit", "export", "extern", "false", "float",
    "for", "friend", "goto", "if", "inline", "int", "long", "mutable", "namespace", "new", "noexcept", "not",
    "not_eq", "nullptr", "operator", "or", "or_eq", "private", "protected", "public", "register",
    "reinterpret_cast", "requires", "return", "short", "signed", "sizeof", "static", "static_assert",
    "static_cast", "struct", "switch", "template", "this", "thread_local", "throw", "true", "try", "typedef",
    "typeid", "typename", "union", "unsigned", "using", "virtual", "void", "volatile", "wchar_t", "while",
    "xor", "xor_eq", "final", "override", "import", "module", "std"};

// The PNG samples of a table: unorm8 and unorm16 as the table's channels
// (2 as RGB with B = 0: grey + alpha would be expanded by image loaders to
// (R, R, R, G)), rgbd always as RGBA.
std::vector<std::uint16_t> png_samples(const Table& t, Storage s, int& png_channels) {
    const int nc = t.channel_count();
    png_channels = s == Storage::rgbd ? 4 : (nc == 2 ? 3 : nc);
    std::vector<std::uint16_t> out;
    out.reserve(t.texel_count() * static_cast<std::size_t>(png_channels));
    std::uint32_t q[4];
    for (std::size_t k = 0; k < t.texel_count(); ++k) {
        encode_texel(s, &t.values[k * static_cast<std::size_t>(nc)], nc, q);
        for (int c = 0; c < png_channels; ++c) out.push_back(static_cast<std::uint16_t>(q[c]));
    }
    return out;
}

}  // namespace

std::string_view to_string(Format f) { return info(f).name; }

std::string file_extension(Format f) { return info(f).extension; }

Format format_from_string(std::string_view s) {
    std::string allowed;
    for (const auto& i : kFormats) {
        if (s == i.name) return i.format;
        allowed += (allowed.empty() ? "" : ", ") + std::string(i.name);
    }
    throw Error("format '" + std::string(s) + "' is not known; allowed: " + allowed);
}

Storage storage_for(Format f, PixelType pixel) {
    const FormatInfo& i = info(f);
    for (int k = 0; k < i.storage_count; ++k)
        if (i.storages[static_cast<std::size_t>(k)] == storage_of(pixel)) return storage_of(pixel);
    return i.storages[0];
}

bool format_holds(Format f, Storage s) {
    const FormatInfo& i = info(f);
    return std::find(i.storages.begin(), i.storages.begin() + i.storage_count, s) != i.storages.begin() + i.storage_count;
}

std::vector<Format> formats_holding(Storage s) {
    std::vector<Format> out;
    for (const auto& i : kFormats)
        if (format_holds(i.format, s)) out.push_back(i.format);
    return out;
}

std::string format_storages(Format f) {
    const FormatInfo& i = info(f);
    std::string out;
    for (int k = 0; k < i.storage_count; ++k) {
        if (k) out += ", ";
        out += to_string(i.storages[static_cast<std::size_t>(k)]);
    }
    return out;
}

void check_format_holds(Format f, Storage s) {
    if (!format_holds(f, s))
        throw Error("--encoding " + std::string(to_string(s)) + " does not apply to --format " +
                    std::string(to_string(f)) + "; allowed for " + std::string(to_string(f)) + ": " +
                    format_storages(f));
}

std::string cpp_identifier(std::string_view table_id) {
    std::string id;
    for (const char ch : table_id) {
        const bool ok = std::isalnum(static_cast<unsigned char>(ch)) && static_cast<unsigned char>(ch) < 0x80;
        const char c = ok ? ch : '_';
        if (c == '_' && (id.empty() || id.back() == '_')) continue;  // no leading '_' and no "__"
        id += c;
    }
    while (!id.empty() && id.back() == '_') id.pop_back();
    if (id.empty() || std::isdigit(static_cast<unsigned char>(id.front()))) id = "t_" + id;
    if (std::find(std::begin(kKeywords), std::end(kKeywords), id) != std::end(kKeywords)) id += "_lut";
    return id;
}

void write_png_table(const std::string& path, const Table& table, Storage storage) {
    check_shape(table);
    check_storable(table, storage);
    int channels = 0;
    const std::vector<std::uint16_t> samples = png_samples(table, storage, channels);
    write_png_samples(path, table.width(), table.height(), channels, storage == Storage::unorm16 ? 16 : 8, samples,
                      {{"brdflut", metadata_json(table, storage).dump()}});
}

void write_table(const std::string& path, const Table& table, PixelType pixel, Format f) {
    write_table(path, table, storage_for(f, pixel), f);
}

void write_table(const std::string& path, const Table& table, Storage storage, Format f) {
    check_format_holds(f, storage);
    const PixelType pixel = storage == Storage::half ? PixelType::half : PixelType::float32;
    switch (f) {
        case Format::exr: return write_exr(path, table, pixel);
        case Format::cpp: return write_cpp_header(path, table, pixel);
        case Format::png16:
        case Format::png: return write_png_table(path, table, storage);
        case Format::dds: return write_dds(path, table, storage);
        case Format::ktx2: return write_ktx2(path, table, storage);
    }
}

}  // namespace brdflut
