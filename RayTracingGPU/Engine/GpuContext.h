// The Vulkan objects every GPU workload needs: instance (with validation when asked), the selected device,
// its queue and a command pool. Shared by the engine and the GPU tests' compute kernels.
#pragma once

#include <optional>

#include "Vulkan/CommandPool.h"
#include "Vulkan/Device.h"
#include "Vulkan/Instance.h"

namespace rt::gpu
{
struct GpuContextOptions
{
    std::optional<int> deviceIndex; // --device N; empty: the preferred suitable device
    bool validation = false; // VK_LAYER_KHRONOS_validation with a counting messenger
};

/// True in Debug builds and when the environment has RT_VULKAN_VALIDATION=1.
bool validationWanted();

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

    const vk::Device& device() const { return m_device; }
    const vk::CommandPool& commandPool() const { return m_pool; }
    bool validationEnabled() const { return m_instance.validationEnabled(); }
    std::uint64_t validationMessages() const { return m_instance.validationMessages(); }

private:
    vk::Instance m_instance; // members are destroyed bottom-up: pool, device, then the instance
    vk::Device m_device;
    vk::CommandPool m_pool;
};
} // namespace rt::gpu
