// Dear ImGui for the window: its context, the GLFW platform backend and the Vulkan renderer backend, drawing
// into the window's render pass with the engine's device and queue (one device per process). The backend is
// compiled with IMGUI_IMPL_VULKAN_NO_PROTOTYPES and loads its entry points through the engine's loader.
#pragma once

#include <string>
#include <vector>

#include "Engine/GpuContext.h"
#include "Vulkan/DescriptorPool.h"

struct GLFWwindow;

namespace rt::gpu::gui
{
class ImGuiLayer final
{
public:
    /// `framesInFlight`: how many frames may be in flight, so that the backend keeps one set of vertex
    /// buffers per frame. Loads ImGui's own font and the installed ones of kFontFiles into one atlas and
    /// uploads it (waits for the device): switching fonts later needs no upload.
    ImGuiLayer(const GpuContext& context, GLFWwindow* window, VkRenderPass renderPass, std::uint32_t framesInFlight);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    /// The fonts loaded, ImGui's own first.
    const std::vector<std::string>& fontNames() const { return m_fontNames; }

    /// Starts a frame of widgets with the given style, font (index into fontNames) and font scale.
    void newFrame(bool darkStyle, int font, float fontScale);
    /// Ends the frame's widgets (always, even when nothing is drawn) and, with `cmd`, records their drawing
    /// inside the render pass.
    void render(VkCommandBuffer cmd);

private:
    vk::DescriptorPool m_pool; // the font texture's set
    std::vector<std::string> m_fontNames;
    bool m_darkStyle = true;
};
} // namespace rt::gpu::gui
