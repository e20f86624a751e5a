// GLSL and HLSL lookup functions (include/brdflut/shader.h).
//
// The generated function follows the axis functions of the library step by
// step, so that it computes what sample_lut() computes:
//   1. v = clamp(parameter, Axis::lowest(), Axis::highest()): the values
//      the texels cover, the axis' clamps applied (sample clamps the
//      parameter to the axis' clamps and the texel position to
//      [0, count - 1], the same thing for a monotonic warp);
//   2. u = the inverse warp of v (the warp's shader expression);
//   3. position = u count - 0.5 - shift (center) or u (count - 1) - shift
//      (endpoints), count - 1 - position when the axis is stored flipped;
//   4. texture coordinate = (position + 0.5) / count, simplified per case;
//   5. the hardware's linear filter with clamp-to-edge addressing.
#include "brdflut/shader.h"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>
#include <system_error>

#include "brdflut/catalogue.h"
#include "brdflut/error.h"
#include "brdflut/formats.h"
#include "brdflut/version.h"
#include "io/binary.h"
#include "io/table_writers.h"

namespace brdflut {
namespace {

// A float literal valid in GLSL and HLSL that reads back as the same float
// as the value does: the shortest digits, with a '.' or exponent.
std::string literal(double value) {
    char buf[32];
    const auto end = std::to_chars(buf, buf + sizeof buf, static_cast<float>(value)).ptr;
    std::string s(buf, end);
    if (s.find_first_of(".eE") == std::string::npos) s += ".0";
    if (s.find_first_of("eE") != std::string::npos && s.find('.') == std::string::npos) {
        const std::size_t e = s.find_first_of("eE");
        s.insert(e, ".0");
    }
    return s;
}

// A number in a comment: a literal, or inf (which GLSL and HLSL cannot spell).
std::string comment_number(double value) {
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char buf[32];
    return std::string(buf, std::to_chars(buf, buf + sizeof buf, value).ptr);
}

// Words of GLSL or HLSL that a parameter or member must not be named.
bool reserved(const std::string& s) {
    static const std::set<std::string> words = {
        "input", "output", "sample", "filter", "common", "partition", "active", "half", "fixed", "texture",
        "sampler", "lut", "lut_sampler", "in", "out", "inout", "float", "int", "uint", "bool", "vec2", "vec3",
        "vec4", "float2", "float3", "float4", "matrix", "vector", "line", "point", "triangle", "precise",
        "shared", "packed", "register", "static", "const", "uniform", "buffer", "struct", "return", "x", "y",
        "z", "texel", "result", "not", "and", "or"};
    return words.count(s) > 0 || s.rfind("gl_", 0) == 0;
}

// An identifier from free text: letters, digits and single '_'.
std::string identifier(std::string_view text) {
    std::string id;
    for (const char ch : text) {
        const bool ok = std::isalnum(static_cast<unsigned char>(ch)) && static_cast<unsigned char>(ch) < 0x80;
        const char c = ok ? ch : '_';
        if (c == '_' && (id.empty() || id.back() == '_')) continue;
        id += c;
    }
    while (!id.empty() && id.back() == '_') id.pop_back();
    if (!id.empty() && std::isdigit(static_cast<unsigned char>(id.front()))) id = "c_" + id;
    return id;
}

// The symbol before the ':' of a channel's description ("A: integral of
// ..." -> A, "F_avg(1/eta): ..." -> F_avg_1_eta), empty when there is none.
std::string channel_symbol(const std::string& description) {
    const std::size_t colon = description.find(':');
    return colon == std::string::npos || colon > 24 ? "" : identifier(description.substr(0, colon));
}

// Member names, one per stored channel: its symbol, or for a stored sum of
// table channels (channel map) their symbols joined by "_plus_"; the
// channel letter where there is none, or where two channels would clash.
std::vector<std::string> field_names(const Table& t) {
    static const char* kLetters[4] = {"R", "G", "B", "A"};
    std::vector<std::string> names;
    const TableDefinition* def = nullptr;
    try {
        def = &find_table(t.id);
    } catch (const Error&) {
        def = nullptr;
    }
    for (std::size_t c = 0; c < t.channels.size(); ++c) {
        if (t.channel_map.empty() || !def || c >= t.channel_map.size()) {
            names.push_back(channel_symbol(t.channels[c]));
            continue;
        }
        std::string name;
        for (const int tc : t.channel_map[c]) {
            const std::string sym = tc >= 0 && tc < static_cast<int>(def->channels.size())
                                        ? channel_symbol(def->channels[static_cast<std::size_t>(tc)])
                                        : "";
            if (sym.empty()) {  // a part without a symbol: the letter is used
                name.clear();
                break;
            }
            name += (name.empty() ? "" : "_plus_") + sym;
        }
        names.push_back(name);
    }
    for (std::size_t i = 0; i < names.size(); ++i) {
        bool clash = names[i].empty() || reserved(names[i]);
        for (std::size_t j = 0; j < names.size(); ++j)
            if (j != i && names[j] == names[i]) clash = true;
        if (clash) names[i] = "";
    }
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i].empty()) names[i] = kLetters[i];
    return names;
}

std::string parameter_name(const std::string& axis) {
    const std::string id = identifier(axis);
    return reserved(id) ? id + "_value" : id;
}

// Replaces whole identifiers v, lo, hi of an expression.
std::string substitute(const std::string& expr, const std::string& v, const std::string& lo, const std::string& hi) {
    std::string out;
    for (std::size_t i = 0; i < expr.size();) {
        const unsigned char c = static_cast<unsigned char>(expr[i]);
        if (std::isalpha(c) || c == '_') {
            std::size_t j = i;
            while (j < expr.size() && (std::isalnum(static_cast<unsigned char>(expr[j])) || expr[j] == '_')) ++j;
            const std::string word = expr.substr(i, j - i);
            out += word == "v" ? v : word == "lo" ? lo : word == "hi" ? hi : word;
            i = j;
        } else {
            out += expr[i++];
        }
    }
    return out;
}

// The definition's order of the parameters (the function's signature does
// not change when a table is stored transposed).
std::vector<std::string> parameter_axes(const Table& t) {
    std::vector<std::string> names;
    try {
        for (const AxisSpec& s : find_table(t.id).axes) names.push_back(s.axis.name);
    } catch (const Error&) {
        names.clear();
    }
    if (names.size() != t.axes.size()) {
        names.clear();
        for (const Axis& a : t.axes) names.push_back(a.name);
    }
    return names;
}

std::string format_name(Storage s, int channels) {
    const int stored = gpu_stored_channels(channels);
    const char* rgba[4] = {"R", "RG", "RGBA", "RGBA"};
    const std::string letters = stored == 4 ? rgba[2] : rgba[stored - 1];
    switch (s) {
        case Storage::half: return letters + "16F (VK_FORMAT_" + (stored == 1 ? "R16" : stored == 2 ? "R16G16" : "R16G16B16A16") + "_SFLOAT)";
        case Storage::float32: return letters + "32F (VK_FORMAT_" + (stored == 1 ? "R32" : stored == 2 ? "R32G32" : "R32G32B32A32") + "_SFLOAT)";
        case Storage::unorm16: return letters + "16 UNORM (16-bit PNG)";
        case Storage::unorm8: return letters + "8 UNORM (VK_FORMAT_" + (stored == 1 ? "R8" : stored == 2 ? "R8G8" : "R8G8B8A8") + "_UNORM)";
        case Storage::rgb10a2: return "RGB10_A2 UNORM (VK_FORMAT_A2B10G10R10_UNORM_PACK32)";
        case Storage::rgbd: return "RGBA8 UNORM holding RGBD (decode after filtering)";
    }
    return "";
}

// Whether file channel c holds table channel c for every c (no channel map,
// or one that maps each channel to itself).
bool own_channels(const Table& t) {
    for (std::size_t c = 0; c < t.channel_map.size(); ++c)
        if (t.channel_map[c] != std::vector<int>{static_cast<int>(c)}) return false;
    return true;
}

// What a result form is given: the table, its catalogue definition (null for
// a table not in the catalogue) and the language.
struct FormContext {
    const Table& table;
    const TableDefinition* def;
    ShaderLanguage lang;
};

// How a function returns the filtered texel beyond the channels by name.
// Each entry adds struct members and the code filling them from `texel`
// (the filtered vec4 / float4) after the channels are set; a table names
// its entry in TableDefinition::shader_result.
struct ResultForm {
    std::string name;
    std::string member;                          // the member it adds (ShaderInterface::matrix), or ""
    std::string (*members)(const FormContext&);  // extra struct members, one per line
    std::string (*code)(const FormContext&);     // extra statements setting them
};

std::string none(const FormContext&) { return ""; }

// ---- ltc_inverse: the LTC's inverse matrix (Heitz et al. 2016) ----
//
// The matrix is M^-1 of ltc.h: in the shading frame (normal +z, view
// (sin theta, 0, cos theta)) it takes a light vertex v, a column vector, to
// the clamped cosine's frame. The same matrix in both languages, used as
// inverse_matrix * v (GLSL) and mul(inverse_matrix, v) (HLSL). Its elements
// come from TableDefinition::shader_matrix (by rows): the packing of the
// table, e.g. ltc_1 [[R, 0, B], [0, 1, 0], [G, 0, A]] (Heitz's (m00, m02,
// m20, m22) in glm's m[col][row]), hdrp_ltc_ggx [[R, 0, A], [0, B, 0],
// [G, 0, 1]] (HDRP's _m00_m02_m11_m20 of the transpose).
const char* kLtcMember = "inverse_matrix";

bool ltc_matrix_applies(const FormContext& f) { return f.def && own_channels(f.table); }

// The expression of one element of shader_matrix: a channel of `texel` or a
// float literal.
std::string matrix_element(const FormContext& f, const std::string& e) {
    static const char* kLetters = "RGBA";
    static const char* kComponent[4] = {"r", "g", "b", "a"};
    for (int c = 0; c < 4; ++c)
        if (e.size() == 1 && e[0] == kLetters[c]) {
            if (c >= f.table.channel_count())
                throw Error("table '" + f.table.id + "': matrix element '" + e + "' names a channel the table's " +
                            std::to_string(f.table.channel_count()) + " channels do not have");
            return std::string("texel.") + kComponent[c];
        }
    double v = 0.0;
    const auto [end, ec] = std::from_chars(e.data(), e.data() + e.size(), v);
    if (e.empty() || ec != std::errc() || end != e.data() + e.size() || !std::isfinite(v))
        throw Error("table '" + f.table.id + "': matrix element '" + e +
                    "' is neither a channel (R, G, B, A) nor a finite number");
    return literal(v);
}

std::string ltc_members(const FormContext& f) {
    if (!f.def) return "";
    if (!ltc_matrix_applies(f))
        return "    // (no " + std::string(kLtcMember) + ": the file stores sums of the table's channels, a channel\n"
               "    // map, so the matrix's elements are not the stored channels)\n";
    const bool glsl = f.lang == ShaderLanguage::glsl;
    std::string rows;
    for (int r = 0; r < 3; ++r) {
        rows += r ? ", [" : "[";
        for (int c = 0; c < 3; ++c) rows += (c ? ", " : "") + f.def->shader_matrix[static_cast<std::size_t>(3 * r + c)];
        rows += "]";
    }
    std::ostringstream o;
    o << "    // " << kLtcMember << ": the inverse matrix M^-1 of the linearly transformed cosine\n"
      << "    // (Heitz et al. 2016) in the shading frame: normal +z, view (sin theta, 0, cos theta),\n"
      << "    // tangent +x toward the view. It acts on column vectors: "
      << (glsl ? kLtcMember + std::string(" * v") : "mul(" + std::string(kLtcMember) + ", v)") << " takes a\n"
      << "    // light vertex v to the clamped cosine's frame (code using row vectors, v * M or\n"
      << "    // mul(v, M), as HDRP's LTCSampleMatrix does, needs its transpose).\n"
      << "    // Packing of '" << f.table.id << "', " << f.def->description << ":\n"
      << "    //   M^-1 = [" << rows << "] by rows, of the channels above.\n"
      << "    " << (glsl ? "mat3 " : "float3x3 ") << kLtcMember << ";\n";
    return o.str();
}

std::string ltc_code(const FormContext& f) {
    if (!ltc_matrix_applies(f)) return "";
    const bool glsl = f.lang == ShaderLanguage::glsl;
    const auto el = [&](int r, int c) {
        return matrix_element(f, f.def->shader_matrix[static_cast<std::size_t>(3 * r + c)]);
    };
    std::ostringstream o;
    if (glsl) {
        o << "    // GLSL's mat3 constructor takes columns: column j = (M^-1[0][j], M^-1[1][j], M^-1[2][j]).\n"
          << "    result." << kLtcMember << " = mat3(";
        for (int c = 0; c < 3; ++c)
            o << (c ? ", " : "") << "vec3(" << el(0, c) << ", " << el(1, c) << ", " << el(2, c) << ")";
    } else {
        o << "    // HLSL's float3x3 constructor takes rows: the same matrix as the GLSL function's,\n"
          << "    // its text transposed (row i = (M^-1[i][0], M^-1[i][1], M^-1[i][2]); m[i] is row i).\n"
          << "    result." << kLtcMember << " = float3x3(";
        for (int r = 0; r < 3; ++r)
            o << (r ? ", " : "") << "float3(" << el(r, 0) << ", " << el(r, 1) << ", " << el(r, 2) << ")";
    }
    o << ");\n";
    return o.str();
}

const std::vector<ResultForm>& result_forms() {
    static const std::vector<ResultForm> forms = {{"", "", none, none},
                                                  {"ltc_inverse", kLtcMember, ltc_members, ltc_code}};
    return forms;
}

const TableDefinition* definition(const Table& t) {
    try {
        return &find_table(t.id);
    } catch (const Error&) {
        return nullptr;  // a table not in the catalogue: its channels by name
    }
}

const ResultForm& result_form(const Table& t) {
    const TableDefinition* def = definition(t);
    const std::string name = def ? def->shader_result : "";
    std::string known;
    for (const ResultForm& f : result_forms()) {
        if (f.name == name) return f;
        known += (known.empty() ? "" : ", ") + (f.name.empty() ? std::string("(channels)") : f.name);
    }
    throw Error("table '" + t.id + "': shader result form '" + name + "' is not known; known: " + known);
}

}  // namespace

std::string_view to_string(ShaderLanguage l) { return l == ShaderLanguage::glsl ? "glsl" : "hlsl"; }

ShaderLanguage shader_language_from_string(std::string_view s) {
    if (s == "glsl") return ShaderLanguage::glsl;
    if (s == "hlsl") return ShaderLanguage::hlsl;
    throw Error("shader language '" + std::string(s) + "' is not known; allowed: glsl, hlsl");
}

std::string shader_extension(ShaderLanguage l) { return std::string(to_string(l)); }

ShaderInterface shader_interface(const Table& t) {
    ShaderInterface si;
    const std::string id = cpp_identifier(t.id);
    si.function = "brdflut_" + id;
    si.result_type = "brdflut_" + id + "_value";
    for (const std::string& a : parameter_axes(t)) si.parameters.push_back(parameter_name(a));
    si.fields = field_names(t);
    si.dimensions = t.axes.size() > 2 ? 3 : 2;
    const ResultForm& form = result_form(t);
    if (!form.member.empty() && own_channels(t)) si.matrix = form.member;
    return si;
}

std::string metadata_hash(const Table& t, Storage s) {
    const std::string json = metadata_json(t, s).dump();
    std::uint64_t h = 0xcbf29ce484222325ull;  // FNV-1a 64: offset basis
    for (const char c : json) {
        h ^= static_cast<unsigned char>(c);
        h *= 0x100000001b3ull;  // FNV prime
    }
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

std::string shader_source(const Table& t, Storage storage, ShaderLanguage lang) {
    if (t.axes.empty() || t.axes.size() > 3 || t.channels.empty() || t.channels.size() > 4)
        throw Error("table '" + t.id + "' has " + std::to_string(t.axes.size()) + " axes and " +
                    std::to_string(t.channels.size()) + " channels; a shader lookup needs 1 to 3 and 1 to 4");
    const bool glsl = lang == ShaderLanguage::glsl;
    const ShaderInterface si = shader_interface(t);
    const ResultForm& form = result_form(t);
    static const char* kCoord[3] = {"x", "y", "z"};
    static const char* kComponent[4] = {"r", "g", "b", "a"};
    std::ostringstream o;

    // Header: what the function reads and how to match it with its table.
    o << "// " << si.function << ": lookup of brdflut table '" << t.id << "' (" << kName << " " << kVersion << ").\n"
      << "// Generated with the table; do not edit. Matches the table file whose metadata hash is\n"
      << "//   metadata fnv1a64 " << metadata_hash(t, storage) << "\n"
      << "// = FNV-1a 64-bit of the bytes of the metadata JSON as stored in the file (KTX2 key\n"
      << "// 'brdflut', EXR attribute 'brdflut', PNG iTXt 'brdflut', C++ header metadata[]).\n"
      << "//\n"
      << "// Texture: " << (si.dimensions == 3 ? "3-D, " : "2-D, ") << t.axes[0].count << " x "
      << (t.axes.size() > 1 ? t.axes[1].count : 1);
    if (t.axes.size() > 2) o << " x " << t.axes[2].count;
    o << " texels, " << format_name(storage, t.channel_count()) << ";\n"
      << "// sampler: linear filter, clamp to edge on every axis, one mip level (none generated).\n";
    if (si.dimensions == 3)
        o << "// The files store the z slices stacked as rows (row = z * count_y + y): the same bytes\n"
          << "// uploaded as a width x count_y x count_z 3-D texture.\n";
    o << "// Texture coordinate of an axis: (position + 0.5) / count, position = u count - 0.5\n"
      << "// (placement center) or u (count - 1) (endpoints), count - 1 - position when flipped,\n"
      << "// u the inverse warp of the parameter clamped to the axis' range.\n\n";

    // Result struct.
    o << "struct " << si.result_type << " {\n";
    for (std::size_t c = 0; c < si.fields.size(); ++c)
        o << "    float " << si.fields[c] << ";  // " << kComponent[c] << ": " << t.channels[c] << "\n";
    const FormContext context{t, definition(t), lang};
    o << form.members(context) << "};\n\n";

    // Signature.
    const std::string tex = glsl ? (si.dimensions == 3 ? "sampler3D lut" : "sampler2D lut")
                                 : (si.dimensions == 3 ? "Texture3D<float4> lut, SamplerState lut_sampler"
                                                       : "Texture2D<float4> lut, SamplerState lut_sampler");
    o << si.result_type << " " << si.function << "(" << tex;
    for (const std::string& p : si.parameters) o << ", float " << p;
    o << ")\n{\n";

    // One block per stored axis, in storage order.
    for (std::size_t a = 0; a < t.axes.size(); ++a) {
        const Axis& ax = t.axes[a];
        const std::string p = parameter_name(ax.name);
        const std::string lo = p + "_lo", hi = p + "_hi", v = p + "_v", u = p + "_u";
        const WarpDef& warp = warp_def(ax.warp);
        o << "    // " << kCoord[a] << ": " << ax.name << ", " << ax.count << " texels, placement "
          << to_string(ax.placement) << (ax.flip ? ", stored flipped" : "") << ", warp " << warp.name << ": "
          << ax.name << " = " << warp.formula << ", min = " << comment_number(ax.min)
          << ", max = " << comment_number(ax.max);
        if (ax.has_clamp())
            o << ", clamped to [" << comment_number(ax.clamp_lo) << ", " << comment_number(ax.clamp_hi) << "]";
        o << "\n";
        if (warp.shader_bound) {
            o << "    const float " << lo << " = " << literal(warp.shader_bound(ax.min)) << ";  // " << warp.name
              << " of min\n";
            o << "    const float " << hi << " = " << literal(warp.shader_bound(ax.max)) << ";  // " << warp.name
              << " of max\n";
        } else {
            o << "    const float " << lo << " = " << literal(ax.min) << ";\n";
            o << "    const float " << hi << " = " << literal(ax.max) << ";\n";
        }
        // lowest() and highest(): the range with the axis' clamps applied
        // (an infinite end, which float has but GLSL cannot spell, clamps nothing).
        const double low = ax.lowest(), high = ax.highest();
        o << "    float " << v << " = ";
        if (std::isinf(high) && std::isinf(low)) o << p;
        else if (std::isinf(high)) o << "max(" << p << ", " << literal(low) << ")";
        else if (std::isinf(low)) o << "min(" << p << ", " << literal(high) << ")";
        else o << "clamp(" << p << ", " << literal(low) << ", " << literal(high) << ")";
        o << ";  // the parameters the texels cover\n";
        o << "    float " << u << " = " << substitute(warp.shader_u, v, lo, hi) << ";  // inverse warp\n";
        // A warp whose bounds are spelled in its own coordinate (ior_z: n =
        // 1 + 2e-8 is 1.0 in float, z = 1e-4 is not) clamps there too.
        if (warp.shader_bound && ax.has_clamp())
            o << "    " << u << " = clamp(" << u << ", " << literal(ax.u_of_value(low)) << ", "
              << literal(ax.u_of_value(high)) << ");  // the clamp in " << warp.name << "\n";
        o << "    float " << kCoord[a] << " = ";
        if (ax.placement == Placement::zero_then_endpoints) {
            o << "((" << v << " <= " << literal(ax.min) << " ? " << v << " / " << literal(ax.min) << " : 1.0 + " << u
              << " * " << literal(ax.count - 2) << (ax.shift > 0 ? " - " : " + ") << literal(std::abs(ax.shift))
              << ") + 0.5) / " << literal(ax.count)
              << ";  // zero_then_endpoints: position = p / min up to min (texel 0 holds 0),\n"
              << "    // 1 + u (count - 2) - shift above it; (position + 0.5) / count\n";
        } else if (ax.placement == Placement::split_endpoints) {
            const int h = ax.count / 2, g = ax.count - h;
            o << "((" << u << " < 0.5 ? 2.0 * " << u << " * " << literal(h - 1) << " : " << literal(h) << " + (2.0 * " << u
              << " - 1.0) * " << literal(g - 1) << ") + 0.5) / " << literal(ax.count)
              << ";  // split_endpoints: position = 2u (h - 1) below u = 1/2,\n"
              << "    // h + (2u - 1)(g - 1) from it, h = floor(count/2), g = count - h; (position + 0.5) / count\n";
        } else if (ax.placement == Placement::center && ax.shift == 0.0) {
            o << u << ";  // center: position = u count - 0.5, (position + 0.5) / count = u\n";
        } else if (ax.placement == Placement::center) {
            o << u << (ax.shift > 0 ? " - " : " + ") << literal(std::abs(ax.shift)) << " / " << literal(ax.count)
              << ";  // center, grid shifted by shift texels: position = u count - 0.5 - shift,\n"
              << "    // (position + 0.5) / count = u - shift / count\n";
        } else if (ax.shift == 0.0) {
            o << "(" << u << " * " << literal(ax.count - 1) << " + 0.5) / " << literal(ax.count)
              << ";  // endpoints: position = u (count - 1), (position + 0.5) / count\n";
        } else {
            o << "(" << u << " * " << literal(ax.count - 1) << (ax.shift > 0 ? " - " : " + ")
              << literal(std::abs(ax.shift)) << " + 0.5) / "
              << literal(ax.count) << ";  // endpoints, grid shifted by shift texels:\n"
              << "    // position = u (count - 1) - shift, (position + 0.5) / count\n";
        }
        if (ax.flip)
            o << "    " << kCoord[a] << " = 1.0 - " << kCoord[a]
              << ";  // flipped: position count - 1 - position, coordinate 1 - coordinate\n";
        o << "\n";
    }
    std::string coords;
    for (std::size_t a = 0; a < t.axes.size(); ++a) coords += std::string(a ? ", " : "") + kCoord[a];
    if (t.axes.size() == 1) coords += ", 0.5";  // a one-axis table is a texture of height 1
    const std::string vec = glsl ? (si.dimensions == 3 ? "vec3" : "vec2") : (si.dimensions == 3 ? "float3" : "float2");
    if (glsl)
        o << "    vec4 texel = textureLod(lut, " << vec << "(" << coords << "), 0.0);\n";
    else
        o << "    float4 texel = lut.SampleLevel(lut_sampler, " << vec << "(" << coords << "), 0.0);\n";
    o << "    " << si.result_type << " result;\n";
    for (std::size_t c = 0; c < si.fields.size(); ++c)
        o << "    result." << si.fields[c] << " = texel." << kComponent[c] << ";\n";
    o << form.code(context);
    o << "    return result;\n}\n";
    return o.str();
}

void write_shader(const std::string& path, const Table& table, Storage storage, ShaderLanguage language) {
    write_file_atomically(path, shader_source(table, storage, language));
}

}  // namespace brdflut
