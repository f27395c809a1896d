// A sampler for the scene's image textures: nearest texel, clamped, no mipmaps. The shaders read texels with
// texelFetch at the CPU engine's integer texel coordinates, so the filter never decides a texel; the sampler
// exists because a combined image sampler needs one.
#pragma once

#include "Vulkan/Device.h"
#include "Vulkan/DeviceHandle.h"

namespace rt::vk
{
class Sampler final
{
public:
    Sampler() = default;
    explicit Sampler(const Device& device);
    RT_VK_MOVE_ONLY(Sampler)
    ~Sampler() = default;

    VkSampler Handle() const { return m_sampler.get(); }

private:
    DeviceHandle<VkSampler, &vkDestroySampler> m_sampler;
};
} // namespace rt::vk
