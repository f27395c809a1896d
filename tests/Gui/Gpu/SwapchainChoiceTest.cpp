// Swapchain choices from what surfaces report: lavapipe on X11, a typical NVIDIA desktop, odd drivers.
#include <gtest/gtest.h>

#include "Vulkan/SwapchainChoice.h"

namespace rt::vk
{
namespace
{
constexpr VkColorSpaceKHR kSrgb = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;

SurfaceFacts lavapipeOnX11()
{
    SurfaceFacts f;
    f.capabilities.minImageCount = 3;
    f.capabilities.maxImageCount = 0; // no limit
    f.capabilities.currentExtent = {640, 400};
    f.capabilities.minImageExtent = {1, 1};
    f.capabilities.maxImageExtent = {16384, 16384};
    f.capabilities.supportedUsageFlags = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                         VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_STORAGE_BIT;
    f.formats = {{VK_FORMAT_B8G8R8A8_SRGB, kSrgb}, {VK_FORMAT_B8G8R8A8_UNORM, kSrgb}};
    f.presentModes = {VK_PRESENT_MODE_IMMEDIATE_KHR, VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_FIFO_KHR,
                      VK_PRESENT_MODE_FIFO_RELAXED_KHR};
    return f;
}

TEST(SwapchainChoice, LavapipePicksUnormMailboxAndCopiesAllowed)
{
    const auto c = chooseSwapchain(lavapipeOnX11(), {640, 400});
    ASSERT_TRUE(c);
    EXPECT_EQ(c->format.format, VK_FORMAT_B8G8R8A8_UNORM);
    EXPECT_TRUE(c->shaderEncodesSrgb);
    EXPECT_EQ(c->presentMode, VK_PRESENT_MODE_MAILBOX_KHR);
    EXPECT_EQ(c->imageCount, 4u);
    EXPECT_EQ(c->extent.width, 640u);
    EXPECT_TRUE(c->usage & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
}

TEST(SwapchainChoice, SrgbOnlySurfaceLetsTheFormatEncode)
{
    SurfaceFacts f = lavapipeOnX11();
    f.formats = {{VK_FORMAT_A2B10G10R10_UNORM_PACK32, kSrgb}, {VK_FORMAT_R8G8B8A8_SRGB, kSrgb}};
    const auto c = chooseSwapchain(f, {640, 400});
    ASSERT_TRUE(c);
    EXPECT_EQ(c->format.format, VK_FORMAT_R8G8B8A8_SRGB);
    EXPECT_FALSE(c->shaderEncodesSrgb);
    EXPECT_TRUE(isEightBitColor(c->format.format));
}

TEST(SwapchainChoice, UndefinedFormatMeansAnyAndFifoIsTheFallback)
{
    SurfaceFacts f = lavapipeOnX11();
    f.formats = {{VK_FORMAT_UNDEFINED, kSrgb}};
    f.presentModes = {VK_PRESENT_MODE_FIFO_KHR};
    const auto c = chooseSwapchain(f, {640, 400});
    ASSERT_TRUE(c);
    EXPECT_EQ(c->format.format, VK_FORMAT_B8G8R8A8_UNORM);
    EXPECT_EQ(c->presentMode, VK_PRESENT_MODE_FIFO_KHR);
}

TEST(SwapchainChoice, ExtentFromTheWindowWhereTheSurfaceLeavesItOpen)
{
    SurfaceFacts f = lavapipeOnX11();
    f.capabilities.currentExtent = {0xFFFFFFFFu, 0xFFFFFFFFu};
    f.capabilities.maxImageExtent = {1000, 1000};
    const auto c = chooseSwapchain(f, {1280, 720});
    ASSERT_TRUE(c);
    EXPECT_EQ(c->extent.width, 1000u);
    EXPECT_EQ(c->extent.height, 720u);
}

TEST(SwapchainChoice, MinimisedWindowGetsNoSwapchain)
{
    SurfaceFacts f = lavapipeOnX11();
    EXPECT_FALSE(chooseSwapchain(f, {0, 0}));
    f.capabilities.currentExtent = {0, 0}; // Windows reports this while minimised
    EXPECT_FALSE(chooseSwapchain(f, {640, 400}));
}

TEST(SwapchainChoice, ImageCountWithinTheMaximumAndNoCopiesWhereNotAllowed)
{
    SurfaceFacts f = lavapipeOnX11();
    f.capabilities.minImageCount = 2;
    f.capabilities.maxImageCount = 2;
    f.capabilities.supportedUsageFlags = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    const auto c = chooseSwapchain(f, {640, 400});
    ASSERT_TRUE(c);
    EXPECT_EQ(c->imageCount, 2u);
    EXPECT_FALSE(c->usage & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
}
} // namespace
} // namespace rt::vk
