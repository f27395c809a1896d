// A SPIR-V shader module loaded from a file compiled at build time (Shaders/CMakeLists.txt).
#pragma once

#include <filesystem>

#include "Vulkan/Device.h"
#include "Vulkan/DeviceHandle.h"

namespace rt::vk
{
class ShaderModule final
{
public:
    ShaderModule() = default;
    /// Throws rt::AssetError when the file is missing or not SPIR-V, rt::DeviceError when the driver rejects it.
    ShaderModule(const Device& device, const std::filesystem::path& spirvFile);
    RT_VK_MOVE_ONLY(ShaderModule)
    ~ShaderModule() = default;

    VkShaderModule Handle() const { return m_module.get(); }

private:
    DeviceHandle<VkShaderModule, &vkDestroyShaderModule> m_module;
};
} // namespace rt::vk
