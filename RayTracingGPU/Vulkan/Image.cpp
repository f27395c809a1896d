#include "Vulkan/Image.h"

#include "Vulkan/Check.h"

namespace rt::vk
{
Image::Image(const Device& device, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage)
    : m_extent(extent), m_format(format)
{
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {extent.width, extent.height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImage image = VK_NULL_HANDLE;
    check(vkCreateImage(device.Handle(), &info, nullptr, &image), "vkCreateImage");
    m_image = DeviceHandle<VkImage, &vkDestroyImage>(device.Handle(), image);

    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(device.Handle(), image, &requirements);
    m_memory = DeviceMemory(device, requirements, MemoryUse::DeviceLocal, false);
    check(vkBindImageMemory(device.Handle(), image, m_memory.Handle(), 0), "vkBindImageMemory");
}

ImageView::ImageView(const Device& device, const Image& image, VkImageAspectFlags aspect)
    : ImageView(device, image.Handle(), image.format(), aspect)
{
}

ImageView::ImageView(const Device& device, VkImage image, VkFormat format, VkImageAspectFlags aspect)
{
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = image;
    info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    info.format = format;
    info.subresourceRange = {aspect, 0, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    check(vkCreateImageView(device.Handle(), &info, nullptr, &view), "vkCreateImageView");
    m_view = DeviceHandle<VkImageView, &vkDestroyImageView>(device.Handle(), view);
}
} // namespace rt::vk
