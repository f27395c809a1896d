#include "Vulkan/Instance.h"

#include <cstring>
#include <utility>
#include <vector>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "Error.h"
#include "Vulkan/Check.h"

namespace rt::vk
{
namespace
{
bool instanceExtensionAvailable(const std::string& name)
{
    std::uint32_t count = 0;
    if (vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr) != VK_SUCCESS)
        return false;
    std::vector<VkExtensionProperties> extensions(count);
    vkEnumerateInstanceExtensionProperties(nullptr, &count, extensions.data());
    for (const VkExtensionProperties& extension : extensions)
        if (name == extension.extensionName)
            return true;
    return false;
}

bool layerAvailable(const char* name)
{
    std::uint32_t count = 0;
    if (vkEnumerateInstanceLayerProperties(&count, nullptr) != VK_SUCCESS)
        return false;
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    for (const VkLayerProperties& layer : layers)
        if (std::strcmp(layer.layerName, name) == 0)
            return true;
    return false;
}

std::uint32_t loaderApiVersion()
{
    std::uint32_t version = VK_API_VERSION_1_0; // a 1.0 loader has no vkEnumerateInstanceVersion
    if (vkEnumerateInstanceVersion)
        vkEnumerateInstanceVersion(&version);
    return version;
}
} // namespace

Instance::Instance(bool validation, const std::vector<std::string>& wantedExtensions)
{
    loadGlobalFunctions();
    const std::uint32_t loaderVersion = loaderApiVersion();
    if (loaderVersion < VK_API_VERSION_1_2)
        throw DeviceError(fmt::format("the Vulkan loader supports only API {}.{}; ray tracing needs 1.2",
                                      VK_API_VERSION_MAJOR(loaderVersion), VK_API_VERSION_MINOR(loaderVersion)));

    std::vector<const char*> layers;
    std::vector<const char*> extensions;
    for (const std::string& name : wantedExtensions)
    {
        if (!instanceExtensionAvailable(name))
            throw DeviceError(fmt::format("the Vulkan instance lacks {}, which the window needs to present", name));
        extensions.push_back(name.c_str());
    }
    if (validation)
    {
        if (layerAvailable(kValidationLayer))
        {
            layers.push_back(kValidationLayer);
            extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
            m_log = std::make_shared<ValidationLog>();
        }
        else
            spdlog::warn("Vulkan validation was asked for but {} is not installed; running without it",
                         kValidationLayer);
    }

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "LightSamplingLab";
    app.pEngineName = "rt_gpu";
    app.apiVersion = VK_API_VERSION_1_2;

    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{};
    if (m_log)
    {
        messengerInfo = messengerCreateInfo(*m_log);
        info.pNext = &messengerInfo;
    }

    const VkResult result = vkCreateInstance(&info, nullptr, &m_instance);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
        throw DeviceError("no Vulkan driver found (vkCreateInstance: VK_ERROR_INCOMPATIBLE_DRIVER); install a "
                          "Vulkan ICD, e.g. your GPU's driver or mesa-vulkan-drivers");
    check(result, "vkCreateInstance");
    loadInstanceFunctions(m_instance);
    if (m_log)
        m_messenger = DebugMessenger(m_instance, *m_log);
}

Instance::~Instance() { destroy(); }

Instance::Instance(Instance&& other) noexcept
    : m_instance(std::exchange(other.m_instance, VK_NULL_HANDLE)), m_log(std::move(other.m_log)),
      m_messenger(std::move(other.m_messenger))
{
}

Instance& Instance::operator=(Instance&& other) noexcept
{
    if (this != &other)
    {
        destroy();
        m_instance = std::exchange(other.m_instance, VK_NULL_HANDLE);
        m_log = std::move(other.m_log);
        m_messenger = std::move(other.m_messenger);
    }
    return *this;
}

void Instance::destroy()
{
    m_messenger = DebugMessenger();
    if (m_instance != VK_NULL_HANDLE)
        vkDestroyInstance(m_instance, nullptr);
    m_instance = VK_NULL_HANDLE;
    m_log.reset();
}
} // namespace rt::vk
