#include "Vulkan/SwapchainChoice.h"

#include <algorithm>

namespace rt::vk
{
namespace
{
bool isUnorm8(VkFormat format) { return format == VK_FORMAT_B8G8R8A8_UNORM || format == VK_FORMAT_R8G8B8A8_UNORM; }
} // namespace

bool isSrgbFormat(VkFormat format)
{
    switch (format)
    {
    case VK_FORMAT_B8G8R8A8_SRGB:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_A8B8G8R8_SRGB_PACK32:
    case VK_FORMAT_B8G8R8_SRGB:
    case VK_FORMAT_R8G8B8_SRGB: return true;
    default: return false;
    }
}

bool isEightBitColor(VkFormat format)
{
    return isUnorm8(format) || format == VK_FORMAT_B8G8R8A8_SRGB || format == VK_FORMAT_R8G8B8A8_SRGB;
}

VkSurfaceFormatKHR chooseSurfaceFormat(const std::vector<VkSurfaceFormatKHR>& formats)
{
    // A single UNDEFINED entry (old drivers) means that any format may be used.
    if (formats.empty() || (formats.size() == 1 && formats[0].format == VK_FORMAT_UNDEFINED))
        return {VK_FORMAT_B8G8R8A8_UNORM, VK_COLOR_SPACE_SRGB_NONLINEAR_KHR};
    for (bool (*wanted)(VkFormat) : {isUnorm8, +[](VkFormat f) { return isEightBitColor(f) && isSrgbFormat(f); }})
        for (const VkSurfaceFormatKHR& f : formats)
            if (wanted(f.format) && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR)
                return f;
    return formats.front();
}

VkPresentModeKHR choosePresentMode(const std::vector<VkPresentModeKHR>& modes)
{
    return std::find(modes.begin(), modes.end(), VK_PRESENT_MODE_MAILBOX_KHR) != modes.end()
               ? VK_PRESENT_MODE_MAILBOX_KHR
               : VK_PRESENT_MODE_FIFO_KHR;
}

VkExtent2D chooseExtent(const VkSurfaceCapabilitiesKHR& capabilities, VkExtent2D framebuffer)
{
    if (capabilities.currentExtent.width != 0xFFFFFFFFu)
        return capabilities.currentExtent;
    return {std::clamp(framebuffer.width, capabilities.minImageExtent.width, capabilities.maxImageExtent.width),
            std::clamp(framebuffer.height, capabilities.minImageExtent.height, capabilities.maxImageExtent.height)};
}

std::uint32_t chooseImageCount(const VkSurfaceCapabilitiesKHR& capabilities)
{
    const std::uint32_t wanted = capabilities.minImageCount + 1;
    return capabilities.maxImageCount > 0 ? std::min(wanted, capabilities.maxImageCount) : wanted;
}

std::optional<SwapchainChoice> chooseSwapchain(const SurfaceFacts& facts, VkExtent2D framebuffer)
{
    SwapchainChoice c;
    c.extent = chooseExtent(facts.capabilities, framebuffer);
    if (c.extent.width == 0 || c.extent.height == 0 || framebuffer.width == 0 || framebuffer.height == 0)
        return std::nullopt;
    c.format = chooseSurfaceFormat(facts.formats);
    c.shaderEncodesSrgb = !isSrgbFormat(c.format.format);
    c.presentMode = choosePresentMode(facts.presentModes);
    c.imageCount = chooseImageCount(facts.capabilities);
    c.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
              (facts.capabilities.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    return c;
}
} // namespace rt::vk
