#include "Vulkan/Loader.h"

#include <mutex>

#include <spdlog/fmt/fmt.h>

#include "Error.h"

#ifdef _WIN32
#include <windows.h>
#else
#include <dlfcn.h>
#endif

namespace rt
{
#define RT_VK_DEFINE(name) PFN_##name name = nullptr;
RT_VK_GLOBAL_FUNCTIONS(RT_VK_DEFINE)
RT_VK_INSTANCE_FUNCTIONS(RT_VK_DEFINE)
RT_VK_DEVICE_FUNCTIONS(RT_VK_DEFINE)
#undef RT_VK_DEFINE
} // namespace rt

namespace rt::vk
{
namespace
{
PFN_vkGetInstanceProcAddr g_getInstanceProcAddr = nullptr;

#ifdef _WIN32
constexpr const char* kLoaderNames[] = {"vulkan-1.dll"};
#else
// The versioned name is what the runtime package installs; the bare name exists only with the -dev package.
constexpr const char* kLoaderNames[] = {"libvulkan.so.1", "libvulkan.so"};
#endif

PFN_vkGetInstanceProcAddr openLoader()
{
    for (const char* name : kLoaderNames)
    {
#ifdef _WIN32
        if (HMODULE module = LoadLibraryA(name))
            return reinterpret_cast<PFN_vkGetInstanceProcAddr>(GetProcAddress(module, "vkGetInstanceProcAddr"));
#else
        // Never closed: the function pointers must outlive every static destructor that might use them.
        if (void* library = dlopen(name, RTLD_NOW | RTLD_LOCAL))
            return reinterpret_cast<PFN_vkGetInstanceProcAddr>(dlsym(library, "vkGetInstanceProcAddr"));
#endif
    }
    return nullptr;
}
} // namespace

void loadGlobalFunctions()
{
    static std::once_flag once;
    std::call_once(once, [] { g_getInstanceProcAddr = openLoader(); });
    if (!g_getInstanceProcAddr)
        throw DeviceError(fmt::format("no Vulkan loader: {} is missing or has no vkGetInstanceProcAddr (install "
                                      "the Vulkan runtime, e.g. libvulkan1, and a driver)",
                                      kLoaderNames[0]));
#define RT_VK_LOAD(name) name = reinterpret_cast<PFN_##name>(g_getInstanceProcAddr(nullptr, #name));
    RT_VK_GLOBAL_FUNCTIONS(RT_VK_LOAD)
#undef RT_VK_LOAD
    if (!vkCreateInstance || !vkEnumerateInstanceExtensionProperties)
        throw DeviceError("the Vulkan loader lacks vkCreateInstance: the installation is broken");
}

void loadInstanceFunctions(VkInstance instance)
{
#define RT_VK_LOAD(name) name = reinterpret_cast<PFN_##name>(g_getInstanceProcAddr(instance, #name));
    RT_VK_INSTANCE_FUNCTIONS(RT_VK_LOAD)
#undef RT_VK_LOAD
}

PFN_vkVoidFunction instanceProcAddr(VkInstance instance, const char* name)
{
    return g_getInstanceProcAddr ? g_getInstanceProcAddr(instance, name) : nullptr;
}

void loadDeviceFunctions(VkDevice device)
{
#define RT_VK_LOAD(name) name = reinterpret_cast<PFN_##name>(vkGetDeviceProcAddr(device, #name));
    RT_VK_DEVICE_FUNCTIONS(RT_VK_LOAD)
#undef RT_VK_LOAD
}
} // namespace rt::vk
