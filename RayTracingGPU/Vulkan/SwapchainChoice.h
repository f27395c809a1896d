// What a swapchain is created with, chosen from what the surface reports (never assumed: lavapipe on X11 offers
// B8G8R8A8 UNORM and SRGB with four present modes, other drivers differ). Pure logic on plain Vulkan structs,
// tested without a device.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "Vulkan/Loader.h"

namespace rt::vk
{
/// What vkGetPhysicalDeviceSurface*KHR report for one surface.
struct SurfaceFacts
{
    VkSurfaceCapabilitiesKHR capabilities{};
    std::vector<VkSurfaceFormatKHR> formats;
    std::vector<VkPresentModeKHR> presentModes;
};

struct SwapchainChoice
{
    VkSurfaceFormatKHR format{};
    /// The format stores what it is given (UNORM): shaders write sRGB-encoded values themselves, and Dear
    /// ImGui's colours (sRGB already) pass unchanged. False for an _SRGB format, which encodes on write.
    bool shaderEncodesSrgb = true;
    VkPresentModeKHR presentMode = VK_PRESENT_MODE_FIFO_KHR;
    VkExtent2D extent{};
    std::uint32_t imageCount = 0;
    VkImageUsageFlags usage = 0; // colour attachment, and transfer source where the surface allows it
};

/// Prefers 8-bit BGRA/RGBA UNORM in the sRGB colour space, then 8-bit _SRGB, then the first format reported.
VkSurfaceFormatKHR chooseSurfaceFormat(const std::vector<VkSurfaceFormatKHR>& formats);

/// True for the formats whose writes are sRGB-encoded by the hardware.
bool isSrgbFormat(VkFormat format);

/// True for the 8-bit four-channel formats a screenshot can be read from (BGRA or RGBA, UNORM or SRGB).
bool isEightBitColor(VkFormat format);

/// MAILBOX (newest frame, no tearing, the renderer never waits for vertical blank) when offered, else FIFO,
/// which every device supports.
VkPresentModeKHR choosePresentMode(const std::vector<VkPresentModeKHR>& modes);

/// The surface's current extent, or the window's framebuffer size clamped to the allowed range where the
/// surface leaves it to the swapchain (currentExtent = 0xFFFFFFFF).
VkExtent2D chooseExtent(const VkSurfaceCapabilitiesKHR& capabilities, VkExtent2D framebuffer);

/// One more than the minimum (so acquiring never waits on the presentation engine), within the maximum.
std::uint32_t chooseImageCount(const VkSurfaceCapabilitiesKHR& capabilities);

/// Everything together; empty when the extent is 0 x 0 (a minimised window), when no swapchain may exist.
std::optional<SwapchainChoice> chooseSwapchain(const SurfaceFacts& facts, VkExtent2D framebuffer);
} // namespace rt::vk
