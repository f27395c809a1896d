// The one way Vulkan results are checked: anything but VK_SUCCESS (and the non-error codes a caller accepts
// explicitly) throws rt::DeviceError naming the call, the VkResult and the source line.
#pragma once

#include <source_location>
#include <string_view>

#include "Vulkan/Loader.h"

namespace rt::vk
{
/// The enumerator's name, e.g. "VK_ERROR_OUT_OF_DEVICE_MEMORY".
const char* resultName(VkResult result);

/// Throws rt::DeviceError("<what> failed: <VkResult> (<file>:<line>)") unless `result` is VK_SUCCESS.
void check(VkResult result, std::string_view what, std::source_location where = std::source_location::current());
} // namespace rt::vk
