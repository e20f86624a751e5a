#include "vk_compute.h"

#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace brdflut::gpu {
namespace {

void check(VkResult r, const char* what) {
    if (r != VK_SUCCESS) throw std::runtime_error(std::string(what) + " failed: VkResult " + std::to_string(r));
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open '" + path + "'");
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

template <class T>
T load(const std::string& bytes, std::size_t at) {
    if (at + sizeof(T) > bytes.size()) throw std::runtime_error("KTX2 file is truncated");
    T v;
    std::memcpy(&v, bytes.data() + at, sizeof v);  // little-endian host (x86-64, aarch64)
    return v;
}

// Bytes of one texel of the formats brdflut writes.
std::uint32_t texel_bytes(std::uint32_t vk_format) {
    switch (vk_format) {
        case VK_FORMAT_R16_SFLOAT: return 2;
        case VK_FORMAT_R16G16_SFLOAT: return 4;
        case VK_FORMAT_R16G16B16A16_SFLOAT: return 8;
        case VK_FORMAT_R32_SFLOAT: return 4;
        case VK_FORMAT_R32G32_SFLOAT: return 8;
        case VK_FORMAT_R32G32B32A32_SFLOAT: return 16;
        default: throw std::runtime_error("KTX2 vkFormat " + std::to_string(vk_format) + " is not a brdflut format");
    }
}

}  // namespace

Texture read_ktx2(const std::string& path) {
    const std::string b = slurp(path);
    static const char kId[12] = {'\xAB', 'K', 'T', 'X', ' ', '2', '0', '\xBB', '\r', '\n', '\x1A', '\n'};
    if (b.size() < 80 || std::memcmp(b.data(), kId, 12) != 0) throw std::runtime_error("'" + path + "' is not KTX2");
    Texture t;
    t.vk_format = load<std::uint32_t>(b, 12);
    t.width = load<std::uint32_t>(b, 20);
    const std::uint32_t h = load<std::uint32_t>(b, 24), d = load<std::uint32_t>(b, 28);
    t.height = h ? h : 1;
    t.depth = d ? d : 1;
    t.is_3d = d > 0;
    if (load<std::uint32_t>(b, 32) > 1 || load<std::uint32_t>(b, 36) != 1 || load<std::uint32_t>(b, 44) != 0)
        throw std::runtime_error("'" + path + "': only single-layer, single-face, uncompressed KTX2 files");
    // Level index of level 0 follows the 48-byte header and 32-byte index.
    const auto offset = load<std::uint64_t>(b, 80), length = load<std::uint64_t>(b, 88);
    const std::uint64_t want = std::uint64_t{t.width} * t.height * t.depth * texel_bytes(t.vk_format);
    if (length != want || offset + length > b.size())
        throw std::runtime_error("'" + path + "': level 0 holds " + std::to_string(length) + " bytes, expected " +
                                 std::to_string(want));
    // Key/value data: entries of keyAndValueByteLength, key, NUL, value, padding.
    const std::uint32_t kvd = load<std::uint32_t>(b, 56), kvd_length = load<std::uint32_t>(b, 60);
    for (std::size_t at = kvd; at + 4 <= std::size_t{kvd} + kvd_length;) {
        const std::uint32_t n = load<std::uint32_t>(b, at);
        if (at + 4 + n > b.size()) throw std::runtime_error("'" + path + "': key/value data is truncated");
        const std::string entry = b.substr(at + 4, n);
        const std::size_t nul = entry.find('\0');
        if (nul != std::string::npos && entry.substr(0, nul) == "brdflut") {
            t.metadata = entry.substr(nul + 1);
            if (!t.metadata.empty() && t.metadata.back() == '\0') t.metadata.pop_back();
        }
        at += 4 + (n + 3) / 4 * 4;
    }
    t.texels.assign(b.begin() + static_cast<std::ptrdiff_t>(offset),
                    b.begin() + static_cast<std::ptrdiff_t>(offset + length));
    return t;
}

std::string fnv1a64_hex(const std::string& bytes) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (const char c : bytes) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

std::vector<std::uint32_t> compile_compute(const std::string& glslang, const std::string& source, bool hlsl,
                                           const std::string& scratch_dir) {
    const std::string src = scratch_dir + (hlsl ? "/shader.comp.hlsl" : "/shader.comp");
    const std::string spv = scratch_dir + "/shader.spv", log = scratch_dir + "/glslang.txt";
    {
        std::ofstream out(src, std::ios::binary);
        out << source;
    }
    // -V: SPIR-V for Vulkan; -S comp: compute stage; -D: HLSL front end
    // with entry point main.
    const std::string cmd = "'" + glslang + "' -V -S comp " + (hlsl ? "-D -e main " : "") + "-o '" + spv + "' '" +
                            src + "' >'" + log + "' 2>&1";
    if (std::system(cmd.c_str()) != 0)
        throw std::runtime_error("glslangValidator failed on " + src + ":\n" + slurp(log) + "\n--- source ---\n" +
                                 source);
    const std::string bytes = slurp(spv);
    std::vector<std::uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), words.size() * 4);
    return words;
}

struct Runner::Impl {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    std::uint32_t queue_family = 0;
    VkPhysicalDeviceMemoryProperties memory{};
    std::string name;

    // Objects of one run, destroyed at its end (in reverse order).
    struct Buffer {
        VkBuffer buffer = VK_NULL_HANDLE;
        VkDeviceMemory memory = VK_NULL_HANDLE;
        void* mapped = nullptr;
    };

    std::uint32_t memory_type(std::uint32_t bits, VkMemoryPropertyFlags want) const {
        for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i)
            if ((bits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & want) == want) return i;
        throw std::runtime_error("no Vulkan memory type with the properties needed");
    }

    Buffer make_buffer(VkDeviceSize size, VkBufferUsageFlags usage) {
        Buffer b;
        VkBufferCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
        info.size = size;
        info.usage = usage;
        info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
        check(vkCreateBuffer(device, &info, nullptr, &b.buffer), "vkCreateBuffer");
        VkMemoryRequirements req;
        vkGetBufferMemoryRequirements(device, b.buffer, &req);
        VkMemoryAllocateInfo alloc{};
        alloc.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
        alloc.allocationSize = req.size;
        alloc.memoryTypeIndex =
            memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
        check(vkAllocateMemory(device, &alloc, nullptr, &b.memory), "vkAllocateMemory");
        check(vkBindBufferMemory(device, b.buffer, b.memory, 0), "vkBindBufferMemory");
        check(vkMapMemory(device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped), "vkMapMemory");
        return b;
    }
    void destroy(Buffer& b) {
        if (b.memory) vkFreeMemory(device, b.memory, nullptr);  // unmaps implicitly
        if (b.buffer) vkDestroyBuffer(device, b.buffer, nullptr);
        b = {};
    }
};

Runner::Runner() : impl_(std::make_unique<Impl>()) {
    Impl& v = *impl_;
    VkApplicationInfo app{};
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = "brdflut shader tests";
    app.apiVersion = VK_API_VERSION_1_1;
    VkInstanceCreateInfo ici{};
    ici.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    ici.pApplicationInfo = &app;
    const VkResult r = vkCreateInstance(&ici, nullptr, &v.instance);
    if (r != VK_SUCCESS)
        throw std::runtime_error("cannot create a Vulkan instance (VkResult " + std::to_string(r) +
                                 "): install mesa-vulkan-drivers (lavapipe) and libvulkan1");
    std::uint32_t n = 0;
    vkEnumeratePhysicalDevices(v.instance, &n, nullptr);
    std::vector<VkPhysicalDevice> devices(n);
    vkEnumeratePhysicalDevices(v.instance, &n, devices.data());
    std::string seen;
    for (VkPhysicalDevice d : devices) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(d, &p);
        seen += std::string(seen.empty() ? "" : ", ") + p.deviceName;
        // lavapipe reports itself as "llvmpipe (LLVM ...)", a CPU device.
        if (p.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU && std::strncmp(p.deviceName, "llvmpipe", 8) == 0) {
            v.physical = d;
            v.name = p.deviceName;
            break;
        }
    }
    if (!v.physical)
        throw std::runtime_error("no lavapipe (llvmpipe) Vulkan device; devices found: " +
                                 (seen.empty() ? std::string("none") : seen) + ". Install mesa-vulkan-drivers");
    vkGetPhysicalDeviceMemoryProperties(v.physical, &v.memory);

    std::uint32_t qn = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(v.physical, &qn, nullptr);
    std::vector<VkQueueFamilyProperties> families(qn);
    vkGetPhysicalDeviceQueueFamilyProperties(v.physical, &qn, families.data());
    bool found = false;
    for (std::uint32_t i = 0; i < qn && !found; ++i)
        if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) v.queue_family = i, found = true;
    if (!found) throw std::runtime_error("lavapipe has no compute queue");
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo qci{};
    qci.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    qci.queueFamilyIndex = v.queue_family;
    qci.queueCount = 1;
    qci.pQueuePriorities = &priority;
    VkDeviceCreateInfo dci{};
    dci.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    dci.queueCreateInfoCount = 1;
    dci.pQueueCreateInfos = &qci;
    check(vkCreateDevice(v.physical, &dci, nullptr, &v.device), "vkCreateDevice");
    vkGetDeviceQueue(v.device, v.queue_family, 0, &v.queue);
}

Runner::~Runner() {
    if (impl_->device) vkDestroyDevice(impl_->device, nullptr);
    if (impl_->instance) vkDestroyInstance(impl_->instance, nullptr);
}

std::string Runner::device_name() const { return impl_->name; }

std::vector<float> Runner::run(const Texture& tex, const std::vector<std::uint32_t>& spirv,
                               const std::vector<float>& input, std::uint32_t count,
                               std::uint32_t outputs_per_point) {
    Impl& v = *impl_;
    VkDevice dev = v.device;
    const VkFormat format = static_cast<VkFormat>(tex.vk_format);
    VkFormatProperties fp;
    vkGetPhysicalDeviceFormatProperties(v.physical, format, &fp);
    if (!(fp.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT))
        throw std::runtime_error("the device cannot filter VkFormat " + std::to_string(tex.vk_format) + " linearly");

    // Everything created below is released by this guard, whatever throws.
    struct Objects {
        VkDevice dev;
        Impl* impl;
        Impl::Buffer staging, in, out;
        VkImage image = VK_NULL_HANDLE;
        VkDeviceMemory image_memory = VK_NULL_HANDLE;
        VkImageView view = VK_NULL_HANDLE;
        VkSampler sampler = VK_NULL_HANDLE;
        VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
        VkPipelineLayout pipeline_layout = VK_NULL_HANDLE;
        VkShaderModule module = VK_NULL_HANDLE;
        VkPipeline pipeline = VK_NULL_HANDLE;
        VkDescriptorPool pool = VK_NULL_HANDLE;
        VkCommandPool commands = VK_NULL_HANDLE;
        VkFence fence = VK_NULL_HANDLE;
        Objects(VkDevice d, Impl* i) : dev(d), impl(i) {}
        Objects(const Objects&) = delete;
        Objects& operator=(const Objects&) = delete;
        ~Objects() {
            if (fence) vkDestroyFence(dev, fence, nullptr);
            if (commands) vkDestroyCommandPool(dev, commands, nullptr);
            if (pool) vkDestroyDescriptorPool(dev, pool, nullptr);
            if (pipeline) vkDestroyPipeline(dev, pipeline, nullptr);
            if (module) vkDestroyShaderModule(dev, module, nullptr);
            if (pipeline_layout) vkDestroyPipelineLayout(dev, pipeline_layout, nullptr);
            if (set_layout) vkDestroyDescriptorSetLayout(dev, set_layout, nullptr);
            if (sampler) vkDestroySampler(dev, sampler, nullptr);
            if (view) vkDestroyImageView(dev, view, nullptr);
            if (image) vkDestroyImage(dev, image, nullptr);
            if (image_memory) vkFreeMemory(dev, image_memory, nullptr);
            impl->destroy(out);
            impl->destroy(in);
            impl->destroy(staging);
        }
    } o(dev, &v);

    // The texture: optimal tiling, filled from a staging buffer.
    o.staging = v.make_buffer(tex.texels.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    std::memcpy(o.staging.mapped, tex.texels.data(), tex.texels.size());
    VkImageCreateInfo ii{};
    ii.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
    ii.imageType = tex.is_3d ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D;
    ii.format = format;
    ii.extent = {tex.width, tex.height, tex.depth};
    ii.mipLevels = 1;
    ii.arrayLayers = 1;
    ii.samples = VK_SAMPLE_COUNT_1_BIT;
    ii.tiling = VK_IMAGE_TILING_OPTIMAL;
    ii.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    ii.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    check(vkCreateImage(dev, &ii, nullptr, &o.image), "vkCreateImage");
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(dev, o.image, &req);
    VkMemoryAllocateInfo alloc{};
    alloc.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = v.memory_type(req.memoryTypeBits, 0);
    check(vkAllocateMemory(dev, &alloc, nullptr, &o.image_memory), "vkAllocateMemory");
    check(vkBindImageMemory(dev, o.image, o.image_memory, 0), "vkBindImageMemory");
    VkImageViewCreateInfo vi{};
    vi.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
    vi.image = o.image;
    vi.viewType = tex.is_3d ? VK_IMAGE_VIEW_TYPE_3D : VK_IMAGE_VIEW_TYPE_2D;
    vi.format = format;
    vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    check(vkCreateImageView(dev, &vi, nullptr, &o.view), "vkCreateImageView");

    VkSamplerCreateInfo si{};

    si.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
    si.magFilter = VK_FILTER_LINEAR;
    si.minFilter = VK_FILTER_LINEAR;
    si.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    si.addressModeU = si.addressModeV = si.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    si.minLod = 0.0f;
    si.maxLod = 0.0f;
    si.unnormalizedCoordinates = VK_FALSE;
    check(vkCreateSampler(dev, &si, nullptr, &o.sampler), "vkCreateSampler");

    // Buffers (at least 4 bytes each: a zero-sized buffer is invalid).
    const VkDeviceSize in_bytes = std::max<VkDeviceSize>(4, input.size() * sizeof(float));
    const VkDeviceSize out_bytes = std::max<VkDeviceSize>(4, VkDeviceSize{count} * outputs_per_point * sizeof(float));
    o.in = v.make_buffer(in_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    if (!input.empty()) std::memcpy(o.in.mapped, input.data(), input.size() * sizeof(float));
    o.out = v.make_buffer(out_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    std::memset(o.out.mapped, 0xFF, out_bytes);  // NaN: a value never written shows

    // Pipeline.
    const VkDescriptorSetLayoutBinding bindings[5] = {
        {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
        {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
        {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
        {3, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
        {4, VK_DESCRIPTOR_TYPE_SAMPLER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr}};
    VkDescriptorSetLayoutCreateInfo dl{};
    dl.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    dl.bindingCount = 5;
    dl.pBindings = bindings;
    check(vkCreateDescriptorSetLayout(dev, &dl, nullptr, &o.set_layout), "vkCreateDescriptorSetLayout");
    const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, 4};
    VkPipelineLayoutCreateInfo pl{};
    pl.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    pl.setLayoutCount = 1;
    pl.pSetLayouts = &o.set_layout;
    pl.pushConstantRangeCount = 1;
    pl.pPushConstantRanges = &push;
    check(vkCreatePipelineLayout(dev, &pl, nullptr, &o.pipeline_layout), "vkCreatePipelineLayout");
    VkShaderModuleCreateInfo smi{};
    smi.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    smi.codeSize = spirv.size() * 4;
    smi.pCode = spirv.data();
    check(vkCreateShaderModule(dev, &smi, nullptr, &o.module), "vkCreateShaderModule");
    VkComputePipelineCreateInfo cpi{};
    cpi.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
    cpi.stage = {};
    cpi.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    cpi.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    cpi.stage.module = o.module;
    cpi.stage.pName = "main";
    cpi.layout = o.pipeline_layout;
    check(vkCreateComputePipelines(dev, VK_NULL_HANDLE, 1, &cpi, nullptr, &o.pipeline), "vkCreateComputePipelines");

    const VkDescriptorPoolSize sizes[4] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1},
                                           {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2},
                                           {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, 1},
                                           {VK_DESCRIPTOR_TYPE_SAMPLER, 1}};
    VkDescriptorPoolCreateInfo dpi{};
    dpi.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    dpi.maxSets = 1;
    dpi.poolSizeCount = 4;
    dpi.pPoolSizes = sizes;
    check(vkCreateDescriptorPool(dev, &dpi, nullptr, &o.pool), "vkCreateDescriptorPool");
    VkDescriptorSetAllocateInfo dsa{};
    dsa.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    dsa.descriptorPool = o.pool;
    dsa.descriptorSetCount = 1;
    dsa.pSetLayouts = &o.set_layout;
    VkDescriptorSet set;
    check(vkAllocateDescriptorSets(dev, &dsa, &set), "vkAllocateDescriptorSets");
    const VkDescriptorImageInfo image_info{o.sampler, o.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    const VkDescriptorBufferInfo in_info{o.in.buffer, 0, VK_WHOLE_SIZE}, out_info{o.out.buffer, 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet w[5];
    for (int i = 0; i < 5; ++i) {
        w[i] = {};
        w[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        w[i].dstSet = set;
        w[i].dstBinding = static_cast<std::uint32_t>(i);
        w[i].descriptorCount = 1;
        w[i].descriptorType = bindings[i].descriptorType;
    }
    w[0].pImageInfo = w[3].pImageInfo = w[4].pImageInfo = &image_info;
    w[1].pBufferInfo = &in_info;
    w[2].pBufferInfo = &out_info;
    vkUpdateDescriptorSets(dev, 5, w, 0, nullptr);

    // Commands: upload, transition, dispatch, make the results visible.
    VkCommandPoolCreateInfo cp{};
    cp.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    cp.queueFamilyIndex = v.queue_family;
    check(vkCreateCommandPool(dev, &cp, nullptr, &o.commands), "vkCreateCommandPool");
    VkCommandBufferAllocateInfo cba{};
    cba.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    cba.commandPool = o.commands;
    cba.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    cba.commandBufferCount = 1;
    VkCommandBuffer cmd;
    check(vkAllocateCommandBuffers(dev, &cba, &cmd), "vkAllocateCommandBuffers");
    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");

    VkImageMemoryBarrier to_dst{};

    to_dst.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
    to_dst.srcAccessMask = 0;
    to_dst.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    to_dst.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    to_dst.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    to_dst.srcQueueFamilyIndex = to_dst.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    to_dst.image = o.image;
    to_dst.subresourceRange = vi.subresourceRange;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0,
                         nullptr, 1, &to_dst);
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = ii.extent;
    vkCmdCopyBufferToImage(cmd, o.staging.buffer, o.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
    VkImageMemoryBarrier to_read = to_dst;
    to_read.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    to_read.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
    to_read.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    to_read.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 0, nullptr,
                         0, nullptr, 1, &to_read);

    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, o.pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, o.pipeline_layout, 0, 1, &set, 0, nullptr);
    vkCmdPushConstants(cmd, o.pipeline_layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, 4, &count);
    vkCmdDispatch(cmd, (count + 63) / 64, 1, 1);
    VkMemoryBarrier to_host{};
    to_host.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    to_host.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &to_host, 0,
                         nullptr, 0, nullptr);
    check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");

    VkFenceCreateInfo fi{};

    fi.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    check(vkCreateFence(dev, &fi, nullptr, &o.fence), "vkCreateFence");
    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    check(vkQueueSubmit(v.queue, 1, &submit, o.fence), "vkQueueSubmit");
    check(vkWaitForFences(dev, 1, &o.fence, VK_TRUE, 60ull * 1000 * 1000 * 1000), "vkWaitForFences");

    std::vector<float> result(std::size_t{count} * outputs_per_point);
    std::memcpy(result.data(), o.out.mapped, result.size() * sizeof(float));
    return result;
}

}  // namespace brdflut::gpu
