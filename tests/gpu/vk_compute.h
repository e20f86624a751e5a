// A small Vulkan compute harness for the shader tests: uploads one texture,
// runs one compute shader over N points and reads its results back.
//
// Separate from the library on purpose: only the GPU tests link Vulkan.
//
// Descriptor set 0 of every shader it runs:
//   binding 0  combined image sampler (GLSL sampler2D / sampler3D)
//   binding 1  storage buffer, the input floats (read only)
//   binding 2  storage buffer, the output floats
//   binding 3  sampled image (HLSL Texture2D / Texture3D)
//   binding 4  sampler (HLSL SamplerState)
// and a push constant block holding one uint, the number of points.
// Bindings 0, 3 and 4 view the same image with the same sampler: linear
// filtering for magnification and minification, one mip level (mipmap mode
// nearest, maxLod 0), clamp to edge on u, v and w, normalised coordinates.
// The work group size must be 64 in x.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace brdflut::gpu {

// One texture level as a KTX2 file holds it.
struct Texture {
    std::uint32_t vk_format = 0;  // VkFormat
    std::uint32_t width = 0, height = 1, depth = 1;
    bool is_3d = false;           // KTX2 pixelDepth > 0
    std::vector<std::uint8_t> texels;
    std::string metadata;         // the value of key "brdflut" (the metadata JSON), empty if none
};

// Reads the base level of an uncompressed, unsupercompressed KTX2 file
// (KTX File Format Specification 2.0). Throws std::runtime_error.
Texture read_ktx2(const std::string& path);

// FNV-1a 64-bit hash of a string as 16 hex digits (what the generated
// shaders record of their table's metadata).
std::string fnv1a64_hex(const std::string& bytes);

// Compiles a compute shader to SPIR-V with glslangValidator (HLSL through
// its HLSL front end, -D, entry point "main"). Throws std::runtime_error
// with the compiler's output when it fails.
std::vector<std::uint32_t> compile_compute(const std::string& glslang, const std::string& source, bool hlsl,
                                           const std::string& scratch_dir);

class Runner {
public:
    // Opens Mesa's lavapipe (llvmpipe) device; throws std::runtime_error
    // naming the missing piece when there is no Vulkan loader or no lavapipe.
    Runner();
    ~Runner();
    Runner(const Runner&) = delete;
    Runner& operator=(const Runner&) = delete;

    std::string device_name() const;

    // Runs `spirv` over `count` points: `input` is bound at binding 1, and
    // count * outputs_per_point floats are read back from binding 2.
    std::vector<float> run(const Texture& texture, const std::vector<std::uint32_t>& spirv,
                           const std::vector<float>& input, std::uint32_t count, std::uint32_t outputs_per_point);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace brdflut::gpu
