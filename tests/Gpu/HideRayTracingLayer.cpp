// A Vulkan layer for tests (VK_LAYER_RT_hide_ray_tracing): every physical device loses the ray-tracing
// extensions from its extension list, so GpuApp.NoRayTracingDeviceListsWhatEachLacks can run the app on a
// machine whose only device (lavapipe, or an NVIDIA GPU) has them, and see what a machine without one sees.
// Loader–layer interface: Khronos, "Architecture of the Vulkan Loader Interfaces", LoaderLayerInterface.md
// (the instance chain is advanced in vkCreateInstance; device creation is not intercepted: the app must stop
// at device selection).
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include <vulkan/vk_layer.h>
#include <vulkan/vulkan.h>

namespace
{
PFN_vkGetInstanceProcAddr g_nextGetInstanceProcAddr = nullptr;
PFN_vkEnumerateDeviceExtensionProperties g_nextEnumerateDeviceExtensions = nullptr;

bool hidden(const char* extension)
{
    for (const char* name : {VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME, VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
                             VK_KHR_RAY_QUERY_EXTENSION_NAME})
        if (std::strcmp(extension, name) == 0)
            return true;
    return false;
}

VKAPI_ATTR VkResult VKAPI_CALL createInstance(const VkInstanceCreateInfo* info, const VkAllocationCallbacks* allocator,
                                              VkInstance* instance)
{
    auto* link = static_cast<VkLayerInstanceCreateInfo*>(const_cast<void*>(info->pNext));
    while (link && !(link->sType == VK_STRUCTURE_TYPE_LOADER_INSTANCE_CREATE_INFO && link->function == VK_LAYER_LINK_INFO))
        link = static_cast<VkLayerInstanceCreateInfo*>(const_cast<void*>(link->pNext));
    if (!link)
        return VK_ERROR_INITIALIZATION_FAILED;
    g_nextGetInstanceProcAddr = link->u.pLayerInfo->pfnNextGetInstanceProcAddr;
    link->u.pLayerInfo = link->u.pLayerInfo->pNext; // the next layer finds its own link
    const auto next = reinterpret_cast<PFN_vkCreateInstance>(g_nextGetInstanceProcAddr(VK_NULL_HANDLE, "vkCreateInstance"));
    const VkResult result = next(info, allocator, instance);
    if (result == VK_SUCCESS)
        g_nextEnumerateDeviceExtensions = reinterpret_cast<PFN_vkEnumerateDeviceExtensionProperties>(
            g_nextGetInstanceProcAddr(*instance, "vkEnumerateDeviceExtensionProperties"));
    return result;
}

VKAPI_ATTR VkResult VKAPI_CALL enumerateDeviceExtensions(VkPhysicalDevice device, const char* layerName,
                                                         std::uint32_t* count, VkExtensionProperties* properties)
{
    if (layerName && std::strcmp(layerName, "VK_LAYER_RT_hide_ray_tracing") == 0)
    {
        *count = 0;
        return VK_SUCCESS;
    }
    std::uint32_t n = 0;
    if (const VkResult r = g_nextEnumerateDeviceExtensions(device, layerName, &n, nullptr); r != VK_SUCCESS)
        return r;
    std::vector<VkExtensionProperties> all(n);
    if (const VkResult r = g_nextEnumerateDeviceExtensions(device, layerName, &n, all.data()); r < 0)
        return r;
    all.resize(n);
    all.erase(std::remove_if(all.begin(), all.end(), [](const VkExtensionProperties& e) { return hidden(e.extensionName); }),
              all.end());
    const auto kept = static_cast<std::uint32_t>(all.size());
    if (!properties)
    {
        *count = kept;
        return VK_SUCCESS;
    }
    const std::uint32_t copied = std::min(*count, kept);
    std::copy_n(all.begin(), copied, properties);
    *count = copied;
    return copied < kept ? VK_INCOMPLETE : VK_SUCCESS;
}
} // namespace

extern "C" VK_LAYER_EXPORT VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL vkGetInstanceProcAddr(VkInstance instance,
                                                                                          const char* name)
{
    if (std::strcmp(name, "vkGetInstanceProcAddr") == 0)
        return reinterpret_cast<PFN_vkVoidFunction>(&vkGetInstanceProcAddr);
    if (std::strcmp(name, "vkCreateInstance") == 0)
        return reinterpret_cast<PFN_vkVoidFunction>(&createInstance);
    if (std::strcmp(name, "vkEnumerateDeviceExtensionProperties") == 0)
        return reinterpret_cast<PFN_vkVoidFunction>(&enumerateDeviceExtensions);
    return g_nextGetInstanceProcAddr ? g_nextGetInstanceProcAddr(instance, name) : nullptr;
}
