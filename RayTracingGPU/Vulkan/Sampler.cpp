#include "Vulkan/Sampler.h"

#include "Vulkan/Check.h"

namespace rt::vk
{
Sampler::Sampler(const Device& device)
{
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = VK_FILTER_NEAREST;
    info.minFilter = VK_FILTER_NEAREST;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.maxLod = 0.0f;
    VkSampler sampler = VK_NULL_HANDLE;
    check(vkCreateSampler(device.Handle(), &info, nullptr, &sampler), "vkCreateSampler");
    m_sampler = DeviceHandle<VkSampler, &vkDestroySampler>(device.Handle(), sampler);
}
} // namespace rt::vk
