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

struct FormatInfo {
    Format format;
    const char* name;
    const char* extension;
};
constexpr std::array<FormatInfo, 5> kFormats{{{Format::exr, "exr", "exr"},
                                              {Format::cpp, "cpp", "h"},
                                              {Format::png16, "png16", "png"},
                                              {Format::dds, "dds", "dds"},
                                              {Format::ktx2, "ktx2", "ktx2"}}};

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

// 2-channel tables go into PNG as RGB with B = 0: grey + alpha would be
// expanded by image loaders to (R, R, R, G).
std::vector<double> png_values(const Table& t, int& png_channels) {
    png_channels = t.channel_count() == 2 ? 3 : t.channel_count();
    if (png_channels == t.channel_count()) return t.values;
    std::vector<double> v;
    v.reserve(t.texel_count() * 3);
    for (std::size_t k = 0; k < t.texel_count(); ++k) {
        v.push_back(t.at(k, 0));
        v.push_back(t.at(k, 1));
        v.push_back(0.0);
    }
    return v;
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

Storage storage_for(Format f, PixelType pixel) { return f == Format::png16 ? Storage::unorm16 : storage_of(pixel); }

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

void write_png16_table(const std::string& path, const Table& table) {
    check_shape(table);
    check_storable(table, Storage::unorm16);
    int channels = 0;
    const std::vector<double> values = png_values(table, channels);
    write_png16(path, table.width(), table.height(), channels, values,
                {{"brdflut", metadata_json(table, Storage::unorm16).dump()}});
}

void write_table(const std::string& path, const Table& table, PixelType pixel, Format f) {
    switch (f) {
        case Format::exr: return write_exr(path, table, pixel);
        case Format::cpp: return write_cpp_header(path, table, pixel);
        case Format::png16: return write_png16_table(path, table);
        case Format::dds: return write_dds(path, table, pixel);
        case Format::ktx2: return write_ktx2(path, table, pixel);
    }
}

}  // namespace brdflut
