#include "Engine/GpuContext.h"

#include <cstdlib>
#include <cstring>

#include <spdlog/spdlog.h>

#include "Error.h"

namespace rt::gpu
{
namespace
{
vk::Device createDevice(const vk::Instance& instance, std::optional<int> deviceIndex, int deviceShare,
                        VkSurfaceKHR surface)
{
    std::vector<vk::PhysicalDevice> devices = vk::enumeratePhysicalDevices(instance.Handle(), surface);
    std::vector<vk::DeviceCandidate> candidates;
    for (const vk::PhysicalDevice& d : devices)
        candidates.push_back(d.candidate);
    const vk::DeviceRequirements requirements{.presentation = surface != VK_NULL_HANDLE};
    const std::size_t chosen = vk::selectDevice(candidates, deviceIndex, requirements, deviceShare);
    spdlog::debug("Vulkan devices:\n{}", vk::describeDevices(candidates, requirements));
    return vk::Device(devices[chosen], requirements.presentation);
}

vk::Instance createInstance(const GpuContextOptions& options)
{
    return vk::Instance(options.validation, options.presentation ? options.presentation->instanceExtensions
                                                                 : std::vector<std::string>{});
}

vk::Surface createSurface(const vk::Instance& instance, const GpuContextOptions& options)
{
    if (!options.presentation)
        return {};
    return vk::Surface(instance.Handle(), options.presentation->createSurface(instance.Handle()));
}
} // namespace

std::string listDevices(std::optional<int> deviceIndex, int deviceShare)
{
    const vk::Instance instance(false, {});
    std::vector<vk::DeviceCandidate> candidates;
    for (const vk::PhysicalDevice& d : vk::enumeratePhysicalDevices(instance.Handle()))
        candidates.push_back(d.candidate);
    std::string out = vk::describeDevices(candidates, {});
    try
    {
        const std::size_t chosen = vk::selectDevice(candidates, deviceIndex, {}, deviceShare);
        out += fmt::format("\n  a headless render takes device {}", chosen);
    }
    catch (const Error& e)
    {
        out += fmt::format("\n  a headless render would fail: {}", e.what());
    }
    return out;
}

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
    : m_instance(createInstance(options)), m_surface(createSurface(m_instance, options)),
      m_device(createDevice(m_instance, options.deviceIndex, options.deviceShare, m_surface.Handle())), m_pool(m_device)
{
}
} // namespace rt::gpu
