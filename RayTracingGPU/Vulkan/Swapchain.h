// The window's swapchain: images of the surface's chosen format and size, one view each. Recreated (with the
// old one handed to the driver) whenever the window's size changes or presentation reports it out of date.
#pragma once

#include <vector>

#include "Vulkan/DeviceHandle.h"
#include "Vulkan/Image.h"
#include "Vulkan/SwapchainChoice.h"

namespace rt::vk
{
/// The surface's capabilities, formats and present modes on the device's physical device.
SurfaceFacts querySurface(const Device& device, VkSurfaceKHR surface);

class Swapchain final
{
public:
    Swapchain() = default;
    /// Creates the swapchain `choice` describes on `surface`; `old` (may be null) is retired by the driver.
    Swapchain(const Device& device, VkSurfaceKHR surface, const SwapchainChoice& choice,
              VkSwapchainKHR old = VK_NULL_HANDLE);
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;
    Swapchain(Swapchain&&) noexcept = default;
    /// Destroys this swapchain's views before the swapchain itself, then takes `other`'s.
    Swapchain& operator=(Swapchain&& other) noexcept;
    ~Swapchain() = default;

    VkSwapchainKHR Handle() const { return m_swapchain.get(); }
    const SwapchainChoice& choice() const { return m_choice; }
    VkExtent2D extent() const { return m_choice.extent; }
    VkFormat format() const { return m_choice.format.format; }
    std::uint32_t imageCount() const { return static_cast<std::uint32_t>(m_images.size()); }
    VkImage image(std::uint32_t index) const { return m_images.at(index); }
    VkImageView view(std::uint32_t index) const { return m_views.at(index).Handle(); }

private:
    SwapchainChoice m_choice;
    DeviceHandle<VkSwapchainKHR, &vkDestroySwapchainKHR> m_swapchain;
    std::vector<VkImage> m_images; // owned by the swapchain
    std::vector<ImageView> m_views; // declared last: destroyed before the swapchain
};
} // namespace rt::vk
