// The Vulkan instance (API 1.2), optionally with the Khronos validation layer and a messenger that counts
// what it reports.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "Vulkan/DebugMessenger.h"
#include "Vulkan/Loader.h"

namespace rt::vk
{
inline constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

class Instance final
{
public:
    /// Opens the loader and creates the instance. With `validation`, enables kValidationLayer when it is
    /// installed (a warning is logged when it is not: see validationEnabled()). `extensions` are added (the
    /// window's surface extensions). Throws rt::DeviceError with a one-line reason when there is no loader, no
    /// driver, no Vulkan 1.2 or one of `extensions` is missing.
    explicit Instance(bool validation, const std::vector<std::string>& extensions = {});
    ~Instance();
    Instance(const Instance&) = delete;
    Instance& operator=(const Instance&) = delete;
    Instance(Instance&& other) noexcept;
    Instance& operator=(Instance&& other) noexcept;

    VkInstance Handle() const { return m_instance; }
    bool validationEnabled() const { return m_log != nullptr; }
    /// Validation warnings and errors so far (0 without validation).
    std::uint64_t validationMessages() const { return m_log ? m_log->total() : 0; }
    /// The counts, shared: they stay readable after the instance is gone, so that what the layer reports while
    /// the device and the instance are destroyed (leaked objects) is counted too. Null without validation.
    std::shared_ptr<const ValidationLog> validationLog() const { return m_log; }

private:
    void destroy();

    VkInstance m_instance = VK_NULL_HANDLE;
    std::shared_ptr<ValidationLog> m_log; // outlives the instance's create/destroy messages
    DebugMessenger m_messenger;
};
} // namespace rt::vk
