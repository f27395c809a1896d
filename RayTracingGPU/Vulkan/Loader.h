// The Vulkan loader, opened at run time (dlopen / LoadLibrary) rather than linked, so that a machine without
// Vulkan gets a one-line rt::DeviceError instead of a dynamic-linker failure before main().
//
// Entry points are process-wide function pointers named like the C prototypes (in namespace rt), so engine
// code reads like the plain C API. Instance- and device-level pointers are (re)loaded when an instance or a
// device is created; the engine uses one instance and one device at a time.
#pragma once

#ifndef VK_NO_PROTOTYPES
#define VK_NO_PROTOTYPES
#endif
#include <vulkan/vulkan.h>

#include "Vulkan/Functions.inl"

namespace rt
{
#define RT_VK_DECLARE(name) extern PFN_##name name;
RT_VK_GLOBAL_FUNCTIONS(RT_VK_DECLARE)
RT_VK_INSTANCE_FUNCTIONS(RT_VK_DECLARE)
RT_VK_DEVICE_FUNCTIONS(RT_VK_DECLARE)
#undef RT_VK_DECLARE
} // namespace rt

namespace rt::vk
{
/// Opens the Vulkan loader library once per process and loads the global entry points.
/// Throws rt::DeviceError naming the library when it cannot be opened.
void loadGlobalFunctions();

/// Loads every instance-level entry point for `instance` (extension functions the instance lacks stay null).
void loadInstanceFunctions(VkInstance instance);

/// Loads every device-level entry point for `device` through vkGetDeviceProcAddr.
void loadDeviceFunctions(VkDevice device);

/// The loader's vkGetInstanceProcAddr, for libraries that load their own entry points (Dear ImGui's Vulkan
/// backend). Null before loadGlobalFunctions().
PFN_vkVoidFunction instanceProcAddr(VkInstance instance, const char* name);
} // namespace rt::vk
