#include "Vulkan/Pipeline.h"

namespace rt::vk
{
Pipeline::Pipeline(const Device& device, VkPipeline pipeline)
    : m_pipeline(DeviceHandle<VkPipeline, &vkDestroyPipeline>(device.Handle(), pipeline))
{
}
} // namespace rt::vk
