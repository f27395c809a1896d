// The desktop window (GLFW, no client API: Vulkan presents into it). GLFW opens the Vulkan loader by itself;
// it is the same library the engine opened, so its surface belongs to the engine's instance.
#pragma once

#include <string>
#include <vector>

#include "App/Gui/WindowState.h"
#include "Cli/WindowSize.h"
#include "Vulkan/Loader.h"

struct GLFWwindow;

namespace rt::gpu::gui
{
class VulkanWindow final
{
public:
    /// Opens a window of `size` (--window-size), or, with `fitToMonitor`, of `size` cut to the primary
    /// monitor's work area (the default size, made to fit the panel and the image, may not fit the screen).
    /// Throws rt::DeviceError when there is no display or GLFW finds no Vulkan (the message says so and
    /// suggests --headless).
    VulkanWindow(const std::string& title, WindowSize size, bool fitToMonitor);
    ~VulkanWindow();
    VulkanWindow(const VulkanWindow&) = delete;
    VulkanWindow& operator=(const VulkanWindow&) = delete;

    GLFWwindow* handle() const { return m_window; }

    /// The instance extensions GLFW needs to make a surface on this platform (VK_KHR_surface + e.g. xcb).
    static std::vector<std::string> requiredInstanceExtensions();
    /// glfwCreateWindowSurface; throws rt::DeviceError.
    VkSurfaceKHR createSurface(VkInstance instance) const;

    /// The framebuffer's size in pixels; 0 x 0 while minimised.
    Extent framebufferSize() const;
    bool closeRequested() const;

    /// Resizes the window's framebuffer to `size`. 0 x 0 minimises it; since X11 without a window manager
    /// (Xvfb) cannot minimise, the window then reports 0 x 0, as a minimised window does, until the next
    /// resize.
    void resize(Extent size);

    /// Processes window events; waits for one (at most `timeoutSeconds`, 0: none) when asked to.
    void pollEvents() const;
    void waitEvents(double timeoutSeconds) const;

private:
    GLFWwindow* m_window = nullptr;
    bool m_minimisedByRequest = false;
};
} // namespace rt::gpu::gui
