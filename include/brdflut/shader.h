// Shader lookup functions: for a table, GLSL or HLSL source with one function
// that takes the physical parameters and the texture, maps them to texture
// coordinates exactly as `brdflut sample` does (the axis' position_of_value:
// README, "Texture coordinates"), samples with the hardware's linear filter
// and returns the channels by name (an LTC matrix table also its inverse matrix).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "brdflut/table.h"

namespace brdflut {

enum class ShaderLanguage { glsl, hlsl };
std::string_view to_string(ShaderLanguage l);
ShaderLanguage shader_language_from_string(std::string_view s);  // throws brdflut::Error
std::string shader_extension(ShaderLanguage l);                  // "glsl", "hlsl" (no dot)

// The interface of a table's generated function.
struct ShaderInterface {
    std::string function;                 // e.g. "brdflut_ggx_dfg"
    std::string result_type;              // the struct returned, e.g. "brdflut_ggx_dfg_value"
    std::vector<std::string> parameters;  // physical parameters, in the order the function takes them
    std::vector<std::string> fields;      // struct members, one per file channel, in channel order
    int dimensions = 2;                   // texture: 2 (sampler2D / Texture2D) or 3 (sampler3D / Texture3D)
    // The member holding an LTC table's inverse matrix M^-1 (GLSL mat3, HLSL
    // float3x3), "inverse_matrix", acting on column vectors in ltc.h's frame:
    // inverse_matrix * v (GLSL), mul(inverse_matrix, v) (HLSL); empty for
    // other tables and for a file storing a channel map.
    std::string matrix;
};
ShaderInterface shader_interface(const Table& table);

// FNV-1a 64-bit hash of the bytes of `metadata_json(table, storage).dump()`,
// the metadata string stored in the table's file, as 16 hex digits.
std::string metadata_hash(const Table& table, Storage storage);

// The source text of the lookup function for `table` stored as `storage`.
std::string shader_source(const Table& table, Storage storage, ShaderLanguage language);

// Writes shader_source() atomically to `path`.
void write_shader(const std::string& path, const Table& table, Storage storage, ShaderLanguage language);

}  // namespace brdflut
