// A 2-D, single-mip, optimal-tiling VkImage with its own device-local memory.
#pragma once

#include "Vulkan/DeviceMemory.h"

namespace rt::vk
{
class Image final
{
public:
    Image() = default;
    Image(const Device& device, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage);
    RT_VK_MOVE_ONLY(Image)
    ~Image() = default;

    VkImage Handle() const { return m_image.get(); }
    VkExtent2D extent() const { return m_extent; }
    VkFormat format() const { return m_format; }

private:
    DeviceMemory m_memory; // declared first: freed after the image is destroyed
    DeviceHandle<VkImage, &vkDestroyImage> m_image;
    VkExtent2D m_extent{};
    VkFormat m_format = VK_FORMAT_UNDEFINED;
};

/// A view of a whole single-mip, single-layer image: colour by default, depth for depth attachments.
class ImageView final
{
public:
    ImageView() = default;
    ImageView(const Device& device, const Image& image, VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT);
    /// A view of an image owned elsewhere (a swapchain's).
    ImageView(const Device& device, VkImage image, VkFormat format, VkImageAspectFlags aspect);
    RT_VK_MOVE_ONLY(ImageView)
    ~ImageView() = default;

    VkImageView Handle() const { return m_view.get(); }

private:
    DeviceHandle<VkImageView, &vkDestroyImageView> m_view;
};

/// The colour subresource range of a single-mip, single-layer image.
inline constexpr VkImageSubresourceRange kColorRange{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
} // namespace rt::vk
