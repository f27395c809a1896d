#include "Vulkan/Check.h"

#include <filesystem>

#include <spdlog/fmt/fmt.h>

#include "Error.h"

namespace rt::vk
{
const char* resultName(VkResult result)
{
    switch (result)
    {
#define RT_CASE(name)                                                                                          \
    case name: return #name;
        RT_CASE(VK_SUCCESS)
        RT_CASE(VK_NOT_READY)
        RT_CASE(VK_TIMEOUT)
        RT_CASE(VK_EVENT_SET)
        RT_CASE(VK_EVENT_RESET)
        RT_CASE(VK_INCOMPLETE)
        RT_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
        RT_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        RT_CASE(VK_ERROR_INITIALIZATION_FAILED)
        RT_CASE(VK_ERROR_DEVICE_LOST)
        RT_CASE(VK_ERROR_MEMORY_MAP_FAILED)
        RT_CASE(VK_ERROR_LAYER_NOT_PRESENT)
        RT_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
        RT_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
        RT_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
        RT_CASE(VK_ERROR_TOO_MANY_OBJECTS)
        RT_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
        RT_CASE(VK_ERROR_FRAGMENTED_POOL)
        RT_CASE(VK_ERROR_UNKNOWN)
        RT_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
        RT_CASE(VK_ERROR_INVALID_EXTERNAL_HANDLE)
        RT_CASE(VK_ERROR_FRAGMENTATION)
        RT_CASE(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
        RT_CASE(VK_PIPELINE_COMPILE_REQUIRED)
        RT_CASE(VK_THREAD_IDLE_KHR)
        RT_CASE(VK_THREAD_DONE_KHR)
        RT_CASE(VK_OPERATION_DEFERRED_KHR)
        RT_CASE(VK_OPERATION_NOT_DEFERRED_KHR)
#undef RT_CASE
    default: return "unknown VkResult";
    }
}

void check(VkResult result, std::string_view what, std::source_location where)
{
    if (result == VK_SUCCESS)
        return;
    throw DeviceError(fmt::format("{} failed: {} ({}:{})", what, resultName(result),
                                  std::filesystem::path(where.file_name()).filename().string(), where.line()));
}
} // namespace rt::vk
