#include "Vulkan/Swapchain.h"

#include "Vulkan/Check.h"

namespace rt::vk
{
SurfaceFacts querySurface(const Device& device, VkSurfaceKHR surface)
{
    const VkPhysicalDevice physical = device.physical();
    SurfaceFacts facts;
    check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical, surface, &facts.capabilities),
          "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
    std::uint32_t count = 0;
    check(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, nullptr),
          "vkGetPhysicalDeviceSurfaceFormatsKHR");
    facts.formats.resize(count);
    check(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, facts.formats.data()),
          "vkGetPhysicalDeviceSurfaceFormatsKHR");
    facts.formats.resize(count);
    check(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &count, nullptr),
          "vkGetPhysicalDeviceSurfacePresentModesKHR");
    facts.presentModes.resize(count);
    check(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &count, facts.presentModes.data()),
          "vkGetPhysicalDeviceSurfacePresentModesKHR");
    facts.presentModes.resize(count);
    return facts;
}

Swapchain::Swapchain(const Device& device, VkSurfaceKHR surface, const SwapchainChoice& choice, VkSwapchainKHR old)
    : m_choice(choice)
{
    const SurfaceFacts facts = querySurface(device, surface);
    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface;
    info.minImageCount = choice.imageCount;
    info.imageFormat = choice.format.format;
    info.imageColorSpace = choice.format.colorSpace;
    info.imageExtent = choice.extent;
    info.imageArrayLayers = 1;
    info.imageUsage = choice.usage;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE; // one queue renders and presents
    info.preTransform = facts.capabilities.currentTransform;
    // Opaque where allowed; otherwise whatever the compositor offers first (the alpha we write is 1 anyway).
    const VkCompositeAlphaFlagsKHR alphas = facts.capabilities.supportedCompositeAlpha;
    info.compositeAlpha = (alphas & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                              ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                              : static_cast<VkCompositeAlphaFlagBitsKHR>(alphas & (~alphas + 1));
    info.presentMode = choice.presentMode;
    info.clipped = VK_TRUE;
    info.oldSwapchain = old;
    VkSwapchainKHR swapchain = VK_NULL_HANDLE;
    check(vkCreateSwapchainKHR(device.Handle(), &info, nullptr, &swapchain), "vkCreateSwapchainKHR");
    m_swapchain = DeviceHandle<VkSwapchainKHR, &vkDestroySwapchainKHR>(device.Handle(), swapchain);

    std::uint32_t count = 0;
    check(vkGetSwapchainImagesKHR(device.Handle(), swapchain, &count, nullptr), "vkGetSwapchainImagesKHR");
    m_images.resize(count);
    check(vkGetSwapchainImagesKHR(device.Handle(), swapchain, &count, m_images.data()), "vkGetSwapchainImagesKHR");
    for (VkImage image : m_images)
        m_views.emplace_back(device, image, choice.format.format, VK_IMAGE_ASPECT_COLOR_BIT);
}

Swapchain& Swapchain::operator=(Swapchain&& other) noexcept
{
    if (this != &other)
    {
        m_views.clear();
        m_images.clear();
        m_swapchain = std::move(other.m_swapchain);
        m_images = std::move(other.m_images);
        m_views = std::move(other.m_views);
        m_choice = other.m_choice;
    }
    return *this;
}
} // namespace rt::vk
