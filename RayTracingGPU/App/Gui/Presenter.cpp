#include "App/Gui/Presenter.h"

#include <array>
#include <cstring>
#include <limits>

#include <spdlog/fmt/fmt.h>

#include "Error.h"
#include "Vulkan/Barriers.h"
#include "Vulkan/Check.h"

namespace rt::gpu::gui
{
namespace
{
VkExtent2D toVk(Extent e) { return {static_cast<std::uint32_t>(e.width), static_cast<std::uint32_t>(e.height)}; }

VkFormat chooseDepthFormat(const vk::Device& device)
{
    // D16 is the one depth format every device supports as an attachment; the others are more precise.
    for (VkFormat format : {VK_FORMAT_D32_SFLOAT, VK_FORMAT_X8_D24_UNORM_PACK32, VK_FORMAT_D16_UNORM})
    {
        VkFormatProperties properties;
        vkGetPhysicalDeviceFormatProperties(device.physical(), format, &properties);
        if (properties.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT)
            return format;
    }
    throw DeviceError("the device has no depth attachment format");
}

vk::RenderPass createRenderPass(const vk::Device& device, VkFormat color, VkFormat depth)
{
    VkAttachmentDescription attachments[2]{};
    attachments[0].format = color;
    attachments[0].samples = VK_SAMPLE_COUNT_1_BIT;
    attachments[0].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    attachments[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachments[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachments[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[0].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    attachments[0].finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    attachments[1] = attachments[0];
    attachments[1].format = depth;
    attachments[1].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    const VkAttachmentReference colorRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    const VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &colorRef;
    subpass.pDepthStencilAttachment = &depthRef;

    constexpr VkPipelineStageFlags kAttachmentStages = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                                       VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                                       VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    VkSubpassDependency dependencies[2]{};
    // In: the image-available semaphore is waited on at COLOR_ATTACHMENT_OUTPUT, so the layout transition
    // waits for it; the one depth image is reused by every frame (write after write).
    dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[0].dstSubpass = 0;
    dependencies[0].srcStageMask = kAttachmentStages;
    dependencies[0].dstStageMask = kAttachmentStages;
    dependencies[0].srcAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    dependencies[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                                    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    // Out: the screenshot's copy reads what the pass wrote, after the transition to PRESENT_SRC.
    dependencies[1].srcSubpass = 0;
    dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    dependencies[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    dependencies[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    dependencies[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;

    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = 2;
    info.pAttachments = attachments;
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = 2;
    info.pDependencies = dependencies;
    return vk::RenderPass(device, info);
}

vk::SwapchainChoice firstChoice(const GpuContext& context, Extent framebuffer)
{
    const vk::SurfaceFacts facts = vk::querySurface(context.device(), context.surface());
    if (facts.formats.empty() || facts.presentModes.empty())
        throw DeviceError("the window's surface reports no format or no present mode");
    // A window that opens minimised still needs a format for the render pass: any extent will do for that.
    const VkExtent2D size = framebuffer.width > 0 && framebuffer.height > 0 ? toVk(framebuffer) : VkExtent2D{1, 1};
    if (const auto choice = vk::chooseSwapchain(facts, size))
        return *choice;
    vk::SwapchainChoice choice;
    choice.format = vk::chooseSurfaceFormat(facts.formats);
    choice.shaderEncodesSrgb = !vk::isSrgbFormat(choice.format.format);
    return choice;
}
} // namespace

Presenter::Presenter(const GpuContext& context, Extent framebuffer)
    : m_context(&context), m_choice(firstChoice(context, framebuffer)),
      m_depthFormat(chooseDepthFormat(context.device())),
      m_renderPass(createRenderPass(context.device(), m_choice.format.format, m_depthFormat))
{
    const vk::Device& device = context.device();
    for (std::uint32_t slot = 0; slot < kFramesInFlight; ++slot)
    {
        m_commands.emplace_back(device, context.commandPool());
        m_inFlight.emplace_back(device, true); // signalled: the first wait of each slot returns at once
        m_imageAvailable.emplace_back(device);
    }
    recreate(framebuffer);
}

Presenter::~Presenter() { waitIdle(); }

void Presenter::waitIdle() const { vk::check(vkDeviceWaitIdle(m_context->device().Handle()), "vkDeviceWaitIdle"); }

bool Presenter::canScreenshot() const
{
    return vk::isEightBitColor(m_choice.format.format) && (m_swapchain.choice().usage & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
}

void Presenter::recreate(Extent framebuffer)
{
    const vk::Device& device = m_context->device();
    const auto choice = vk::chooseSwapchain(vk::querySurface(device, m_context->surface()), toVk(framebuffer));
    if (!choice)
        return; // minimised: no swapchain may have a zero extent; the old one waits unused
    if (choice->format.format != m_choice.format.format)
        throw DeviceError(fmt::format("the window's surface changed its format ({} to {}) while the app ran",
                                      static_cast<int>(m_choice.format.format),
                                      static_cast<int>(choice->format.format)));
    waitIdle();
    m_framebuffers.clear();
    m_depthView = vk::ImageView();
    m_depth = vk::Image();
    m_swapchain = vk::Swapchain(device, m_context->surface(), *choice, m_swapchain.Handle());
    m_depth = vk::Image(device, choice->extent, m_depthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
    m_depthView = vk::ImageView(device, m_depth, VK_IMAGE_ASPECT_DEPTH_BIT);
    for (std::uint32_t i = 0; i < m_swapchain.imageCount(); ++i)
        m_framebuffers.emplace_back(device, m_renderPass.Handle(),
                                    std::vector<VkImageView>{m_swapchain.view(i), m_depthView.Handle()},
                                    choice->extent);
    while (m_renderFinished.size() < m_swapchain.imageCount())
        m_renderFinished.emplace_back(device);
}

std::optional<Frame> Presenter::beginFrame(Extent framebuffer)
{
    if (framebuffer.width == 0 || framebuffer.height == 0)
        return std::nullopt;
    const VkExtent2D current = m_swapchain.extent();
    if (m_swapchain.Handle() == VK_NULL_HANDLE || current.width != static_cast<std::uint32_t>(framebuffer.width) ||
        current.height != static_cast<std::uint32_t>(framebuffer.height))
        recreate(framebuffer);
    if (m_swapchain.Handle() == VK_NULL_HANDLE)
        return std::nullopt;

    const vk::Device& device = m_context->device();
    Frame frame;
    frame.slot = m_frame % kFramesInFlight;
    m_inFlight[frame.slot].wait();
    const VkResult acquired =
        vkAcquireNextImageKHR(device.Handle(), m_swapchain.Handle(), std::numeric_limits<std::uint64_t>::max(),
                              m_imageAvailable[frame.slot].Handle(), VK_NULL_HANDLE, &frame.imageIndex);
    if (acquired == VK_ERROR_OUT_OF_DATE_KHR)
    {
        // Nothing was signalled: the slot's semaphore and fence are untouched and stay usable.
        recreate(framebuffer);
        return std::nullopt;
    }
    if (acquired != VK_SUBOPTIMAL_KHR) // suboptimal still acquired: draw, present, then recreate
        vk::check(acquired, "vkAcquireNextImageKHR");

    const VkFence fence = m_inFlight[frame.slot].Handle();
    vk::check(vkResetFences(device.Handle(), 1, &fence), "vkResetFences");
    frame.commands = m_commands[frame.slot].Handle();
    frame.extent = m_swapchain.extent();
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vk::check(vkBeginCommandBuffer(frame.commands, &begin), "vkBeginCommandBuffer");
    return frame;
}

void Presenter::beginRenderPass(const Frame& frame) const
{
    VkClearValue clear[2]{};
    clear[1].depthStencil = {1.0f, 0};
    VkRenderPassBeginInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    info.renderPass = m_renderPass.Handle();
    info.framebuffer = m_framebuffers.at(frame.imageIndex).Handle();
    info.renderArea = {{0, 0}, frame.extent};
    info.clearValueCount = 2;
    info.pClearValues = clear;
    vkCmdBeginRenderPass(frame.commands, &info, VK_SUBPASS_CONTENTS_INLINE);
}

void Presenter::endRenderPass(const Frame& frame) const { vkCmdEndRenderPass(frame.commands); }

void Presenter::recordScreenshot(const Frame& frame)
{
    if (!canScreenshot())
        throw DeviceError(fmt::format("cannot take a screenshot: the swapchain's format ({}) is not 8-bit RGBA/BGRA "
                                      "or its images cannot be copied from",
                                      static_cast<int>(m_choice.format.format)));
    const VkDeviceSize bytes = VkDeviceSize(4) * frame.extent.width * frame.extent.height;
    if (m_screenshot.size() != bytes)
        m_screenshot = vk::Buffer(m_context->device(), bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUse::Readback);
    m_screenshotExtent = frame.extent;

    // Source access 0: the render pass's outgoing dependency made its writes visible to transfers. Back to
    // PRESENT_SRC with nothing to wait for: presentation waits for the semaphore, not for memory.
    vk::recordImageReadback(frame.commands, m_swapchain.image(frame.imageIndex), frame.extent, m_screenshot.Handle(),
                            VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                            VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0);
}

void Presenter::endFrame(const Frame& frame, Extent framebuffer)
{
    vk::check(vkEndCommandBuffer(frame.commands), "vkEndCommandBuffer");
    const VkSemaphore waitFor = m_imageAvailable[frame.slot].Handle();
    const VkSemaphore signal = m_renderFinished[frame.imageIndex].Handle();
    // The swapchain image is first touched by the render pass (colour attachment output); the ray tracing
    // and clears before it do not need the image and need not wait.
    const VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.waitSemaphoreCount = 1;
    submit.pWaitSemaphores = &waitFor;
    submit.pWaitDstStageMask = &waitStage;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &frame.commands;
    submit.signalSemaphoreCount = 1;
    submit.pSignalSemaphores = &signal;
    vk::check(vkQueueSubmit(m_context->device().queue(), 1, &submit, m_inFlight[frame.slot].Handle()), "vkQueueSubmit");
    ++m_frame;

    const VkSwapchainKHR swapchain = m_swapchain.Handle();
    VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    present.waitSemaphoreCount = 1;
    present.pWaitSemaphores = &signal;
    present.swapchainCount = 1;
    present.pSwapchains = &swapchain;
    present.pImageIndices = &frame.imageIndex;
    const VkResult presented = vkQueuePresentKHR(m_context->device().queue(), &present);
    const bool sizeChanged = frame.extent.width != static_cast<std::uint32_t>(framebuffer.width) ||
                             frame.extent.height != static_cast<std::uint32_t>(framebuffer.height);
    if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR || sizeChanged)
        recreate(framebuffer);
    else
        vk::check(presented, "vkQueuePresentKHR");
}

std::vector<unsigned char> Presenter::screenshotPixels(int& width, int& height) const
{
    waitIdle();
    width = static_cast<int>(m_screenshotExtent.width);
    height = static_cast<int>(m_screenshotExtent.height);
    std::vector<unsigned char> rgba(std::size_t(4) * width * height);
    if (!rgba.empty())
        std::memcpy(rgba.data(), m_screenshot.mapped(), rgba.size());
    const VkFormat format = m_choice.format.format;
    if (format == VK_FORMAT_B8G8R8A8_UNORM || format == VK_FORMAT_B8G8R8A8_SRGB)
        for (std::size_t i = 0; i < rgba.size(); i += 4)
            std::swap(rgba[i], rgba[i + 2]);
    for (std::size_t i = 3; i < rgba.size(); i += 4)
        rgba[i] = 255; // what the window shows is opaque, whatever alpha the passes left
    return rgba;
}
} // namespace rt::gpu::gui
