// Presentation: the swapchain, the render pass every frame draws in (colour: the swapchain image, depth: for
// the rasterised preview), and the frames in flight.
//
// Synchronisation, indexed the way each object is used (the thesis app indexed command buffers by swapchain
// image but fenced them by frame in flight, a race):
//   per frame in flight (kFramesInFlight): command buffer, fence, image-available semaphore: beginFrame waits
//       for the slot's fence before its command buffer (and the uniforms the caller keeps per slot) is reused;
//   per swapchain image: framebuffer and render-finished semaphore: the semaphore a present waits on stays in
//       use until that image is acquired again, which a per-slot semaphore could not guarantee.
// The swapchain is recreated when presentation reports it out of date or suboptimal and whenever the
// framebuffer's size differs from it; a 0 x 0 framebuffer (minimised) draws nothing and keeps the old one.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "App/Gui/WindowState.h"
#include "Engine/GpuContext.h"
#include "Vulkan/Buffer.h"
#include "Vulkan/CommandBuffer.h"
#include "Vulkan/Fence.h"
#include "Vulkan/Framebuffer.h"
#include "Vulkan/RenderPass.h"
#include "Vulkan/Semaphore.h"
#include "Vulkan/Swapchain.h"

namespace rt::gpu::gui
{
inline constexpr std::uint32_t kFramesInFlight = 2;

/// One frame being recorded.
struct Frame
{
    std::uint32_t slot = 0; // frame in flight
    std::uint32_t imageIndex = 0; // swapchain image
    VkCommandBuffer commands = VK_NULL_HANDLE; // begun
    VkExtent2D extent{};
};

class Presenter final
{
public:
    /// Throws rt::DeviceError when the surface offers nothing usable.
    Presenter(const GpuContext& context, Extent framebuffer);
    ~Presenter();
    Presenter(const Presenter&) = delete;
    Presenter& operator=(const Presenter&) = delete;

    VkRenderPass renderPass() const { return m_renderPass.Handle(); }
    /// The swapchain stores what shaders write (UNORM): they encode sRGB themselves.
    bool shaderEncodesSrgb() const { return m_choice.shaderEncodesSrgb; }
    VkFormat format() const { return m_choice.format.format; }
    VkPresentModeKHR presentMode() const { return m_swapchain.choice().presentMode; }
    std::uint32_t imageCount() const { return m_swapchain.imageCount(); }
    /// What a screenshot needs: an 8-bit format and a swapchain that allows transfers from its images.
    bool canScreenshot() const;

    /// Waits for this slot's previous frame, acquires a swapchain image and begins the slot's command buffer.
    /// Empty when nothing can be drawn: the framebuffer is 0 x 0, or the swapchain was out of date (it is
    /// recreated; the next call draws).
    std::optional<Frame> beginFrame(Extent framebuffer);
    /// The render pass over the frame's image, cleared to black (depth to far).
    void beginRenderPass(const Frame& frame) const;
    void endRenderPass(const Frame& frame) const;
    /// Records the copy of the frame's image (as the window will show it) into host memory; after
    /// endRenderPass. screenshotPixels() returns it once the frame is done.
    void recordScreenshot(const Frame& frame);
    /// Ends and submits the frame and presents it; recreates the swapchain when needed.
    void endFrame(const Frame& frame, Extent framebuffer);
    /// The last recorded screenshot as RGBA8 rows, top row first (waits for the device).
    std::vector<unsigned char> screenshotPixels(int& width, int& height) const;

    void waitIdle() const;

private:
    void recreate(Extent framebuffer);

    const GpuContext* m_context;
    vk::SwapchainChoice m_choice; // of the first swapchain: the render pass and pipelines depend on its format
    VkFormat m_depthFormat;
    vk::RenderPass m_renderPass;
    vk::Swapchain m_swapchain;
    vk::Image m_depth;
    vk::ImageView m_depthView;
    std::vector<vk::Framebuffer> m_framebuffers; // per swapchain image
    std::vector<vk::Semaphore> m_renderFinished; // per swapchain image; only grows (see the file comment)
    std::vector<vk::CommandBuffer> m_commands; // per frame in flight
    std::vector<vk::Fence> m_inFlight;
    std::vector<vk::Semaphore> m_imageAvailable;
    std::uint32_t m_frame = 0; // frames submitted; slot = m_frame % kFramesInFlight
    vk::Buffer m_screenshot;
    VkExtent2D m_screenshotExtent{};
};
} // namespace rt::gpu::gui
