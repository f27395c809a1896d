// The Vulkan objects every GPU workload needs: instance (with validation when asked), the selected device,
// its queue and a command pool. Shared by the engine and the GPU tests' compute kernels. In window mode it
// also holds the window's surface, and the device is chosen among those that can present to it.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "Vulkan/CommandPool.h"
#include "Vulkan/Device.h"
#include "Vulkan/Instance.h"
#include "Vulkan/Surface.h"

namespace rt::gpu
{
/// What a window needs from the context: the platform's surface extensions on the instance, and its surface
/// made from that instance before the device is chosen (the device must be able to present to it).
struct Presentation
{
    std::vector<std::string> instanceExtensions; // glfwGetRequiredInstanceExtensions
    /// Called once with the new instance; returns the window's surface, which the context then owns.
    std::function<VkSurfaceKHR(VkInstance)> createSurface;
};

struct GpuContextOptions
{
    std::optional<int> deviceIndex; // --device N; empty: the preferred suitable device
    int deviceShare = 0; // without deviceIndex, which of the preferred devices (vk::selectDevice): an MPI rank's
                         // index on its host
    bool validation = false; // VK_LAYER_KHRONOS_validation with a counting messenger
    std::optional<Presentation> presentation; // window mode; headless requires nothing of the kind
};

/// True in Debug builds and when the environment has RT_VULKAN_VALIDATION=1.
bool validationWanted();

/// --list-devices: every Vulkan device this process sees, what each lacks for the ray tracer, and which one a
/// headless render with `deviceIndex` and `deviceShare` (GpuContextOptions) takes, or why none. Throws
/// rt::DeviceError when Vulkan has no loader or driver.
std::string listDevices(std::optional<int> deviceIndex, int deviceShare);

class GpuContext final
{
public:
    /// Throws rt::DeviceError (no loader, no driver, no suitable device: every device and what it lacks) or
    /// rt::UsageError (a --device index that does not exist).
    explicit GpuContext(const GpuContextOptions& options);
    GpuContext(const GpuContext&) = delete;
    GpuContext& operator=(const GpuContext&) = delete;
    GpuContext(GpuContext&&) noexcept = default;
    GpuContext& operator=(GpuContext&&) noexcept = default;
    ~GpuContext() = default;

    const vk::Instance& instance() const { return m_instance; }
    const vk::Device& device() const { return m_device; }
    const vk::CommandPool& commandPool() const { return m_pool; }
    /// The window's surface (null without presentation).
    VkSurfaceKHR surface() const { return m_surface.Handle(); }
    bool validationEnabled() const { return m_instance.validationEnabled(); }
    std::uint64_t validationMessages() const { return m_instance.validationMessages(); }

private:
    vk::Instance m_instance; // members are destroyed bottom-up: pool, device, surface, then the instance
    vk::Surface m_surface;
    vk::Device m_device;
    vk::CommandPool m_pool;
};
} // namespace rt::gpu
