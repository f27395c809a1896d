// VK_EXT_debug_utils messenger that counts and logs what the validation layers report. Tests assert that a
// render produced no warning and no error; the count lives outside the messenger so it survives moves.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>

#include "Vulkan/Loader.h"

namespace rt::vk
{
/// Counts of validation messages at warning severity or above, shared with the messenger callback.
struct ValidationLog
{
    std::atomic<std::uint64_t> warnings{0};
    std::atomic<std::uint64_t> errors{0};

    std::uint64_t total() const { return warnings.load() + errors.load(); }
};

/// The create info of a messenger that writes into `log`; also chained into VkInstanceCreateInfo so that
/// vkCreateInstance and vkDestroyInstance are covered.
VkDebugUtilsMessengerCreateInfoEXT messengerCreateInfo(ValidationLog& log);

class DebugMessenger final
{
public:
    DebugMessenger() = default;
    DebugMessenger(VkInstance instance, ValidationLog& log);
    ~DebugMessenger();
    DebugMessenger(const DebugMessenger&) = delete;
    DebugMessenger& operator=(const DebugMessenger&) = delete;
    DebugMessenger(DebugMessenger&& other) noexcept;
    DebugMessenger& operator=(DebugMessenger&& other) noexcept;

    VkDebugUtilsMessengerEXT Handle() const { return m_messenger; }

private:
    void destroy();

    VkInstance m_instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT m_messenger = VK_NULL_HANDLE;
};
} // namespace rt::vk
