#include "Engine/GpuContext.h"

#include <cstdlib>
#include <cstring>

#include <spdlog/spdlog.h>

namespace rt::gpu
{
namespace
{
vk::Device createDevice(const vk::Instance& instance, std::optional<int> deviceIndex)
{
    std::vector<vk::PhysicalDevice> devices = vk::enumeratePhysicalDevices(instance.Handle());
    std::vector<vk::DeviceCandidate> candidates;
    for (const vk::PhysicalDevice& d : devices)
        candidates.push_back(d.candidate);
    const std::size_t chosen = vk::selectDevice(candidates, deviceIndex);
    spdlog::debug("Vulkan devices:\n{}", vk::describeDevices(candidates));
    return vk::Device(devices[chosen]);
}
} // namespace

bool validationWanted()
{
#ifndef NDEBUG
    return true;
#else
    const char* env = std::getenv("RT_VULKAN_VALIDATION");
    return env && std::strcmp(env, "1") == 0;
#endif
}

GpuContext::GpuContext(const GpuContextOptions& options)
    : m_instance(options.validation), m_device(createDevice(m_instance, options.deviceIndex)), m_pool(m_device)
{
}
} // namespace rt::gpu
