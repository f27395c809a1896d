#include "Vulkan/ShaderModule.h"

#include <cstdint>
#include <fstream>
#include <vector>

#include <spdlog/fmt/fmt.h>

#include "Error.h"
#include "Vulkan/Check.h"

namespace rt::vk
{
namespace
{
std::vector<std::uint32_t> readSpirv(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in)
        throw AssetError(fmt::format("shader '{}' not found (the shaders are built into <bin>/shaders beside the "
                                     "executable; --shader-dir names another folder of that layout)",
                                     path.string()));
    const std::streamsize bytes = in.tellg();
    constexpr std::uint32_t kSpirvMagic = 0x07230203u;
    std::vector<std::uint32_t> words(static_cast<std::size_t>(bytes) / 4);
    in.seekg(0);
    in.read(reinterpret_cast<char*>(words.data()), static_cast<std::streamsize>(words.size() * 4));
    if (bytes % 4 != 0 || words.empty() || words[0] != kSpirvMagic || !in)
        throw AssetError(fmt::format("shader '{}' is not a SPIR-V module", path.string()));
    return words;
}
} // namespace

ShaderModule::ShaderModule(const Device& device, const std::filesystem::path& spirvFile)
{
    const std::vector<std::uint32_t> code = readSpirv(spirvFile);
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = code.size() * sizeof(std::uint32_t);
    info.pCode = code.data();
    VkShaderModule module = VK_NULL_HANDLE;
    check(vkCreateShaderModule(device.Handle(), &info, nullptr, &module), "vkCreateShaderModule");
    m_module = DeviceHandle<VkShaderModule, &vkDestroyShaderModule>(device.Handle(), module);
}
} // namespace rt::vk
