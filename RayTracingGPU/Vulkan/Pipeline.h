#pragma once

#include "Vulkan/Device.h"
#include "Vulkan/DeviceHandle.h"

namespace rt::vk
{
/// A pipeline of any kind (ray tracing, compute), created by its builder and owned here.
class Pipeline final
{
public:
    Pipeline() = default;
    Pipeline(const Device& device, VkPipeline pipeline);
    RT_VK_MOVE_ONLY(Pipeline)
    ~Pipeline() = default;

    VkPipeline Handle() const { return m_pipeline.get(); }

private:
    DeviceHandle<VkPipeline, &vkDestroyPipeline> m_pipeline;
};
} // namespace rt::vk
