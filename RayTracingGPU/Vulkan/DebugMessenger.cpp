#include "Vulkan/DebugMessenger.h"

#include <cstring>
#include <utility>

#include <spdlog/spdlog.h>

#include "Vulkan/Check.h"

namespace rt::vk
{
namespace
{
VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                         VkDebugUtilsMessageTypeFlagsEXT, const VkDebugUtilsMessengerCallbackDataEXT* data,
                                         void* user)
{
    auto& log = *static_cast<ValidationLog*>(user);
    const char* message = data && data->pMessage ? data->pMessage : "(no message)";
    // The loader's own messages (no driver manifest, a driver that failed to load) are about the machine, not
    // about our use of the API: the app reports a missing device in its own words (DeviceError).
    if (data && data->pMessageIdName && std::strcmp(data->pMessageIdName, "Loader Message") == 0)
    {
        spdlog::debug("Vulkan loader: {}", message);
        return VK_FALSE;
    }
    if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT)
    {
        log.errors.fetch_add(1);
        spdlog::error("Vulkan validation: {}", message);
    }
    else if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT)
    {
        log.warnings.fetch_add(1);
        spdlog::warn("Vulkan validation: {}", message);
    }
    return VK_FALSE; // never abort the call: the count is what tests look at
}
} // namespace

VkDebugUtilsMessengerCreateInfoEXT messengerCreateInfo(ValidationLog& log)
{
    VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = onMessage;
    info.pUserData = &log;
    return info;
}

DebugMessenger::DebugMessenger(VkInstance instance, ValidationLog& log) : m_instance(instance)
{
    const VkDebugUtilsMessengerCreateInfoEXT info = messengerCreateInfo(log);
    check(vkCreateDebugUtilsMessengerEXT(instance, &info, nullptr, &m_messenger), "vkCreateDebugUtilsMessengerEXT");
}

DebugMessenger::~DebugMessenger() { destroy(); }

DebugMessenger::DebugMessenger(DebugMessenger&& other) noexcept
    : m_instance(std::exchange(other.m_instance, VK_NULL_HANDLE)),
      m_messenger(std::exchange(other.m_messenger, VK_NULL_HANDLE))
{
}

DebugMessenger& DebugMessenger::operator=(DebugMessenger&& other) noexcept
{
    if (this != &other)
    {
        destroy();
        m_instance = std::exchange(other.m_instance, VK_NULL_HANDLE);
        m_messenger = std::exchange(other.m_messenger, VK_NULL_HANDLE);
    }
    return *this;
}

void DebugMessenger::destroy()
{
    if (m_messenger != VK_NULL_HANDLE)
        vkDestroyDebugUtilsMessengerEXT(m_instance, m_messenger, nullptr);
    m_messenger = VK_NULL_HANDLE;
}
} // namespace rt::vk
