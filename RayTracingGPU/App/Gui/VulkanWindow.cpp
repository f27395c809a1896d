#include "App/Gui/VulkanWindow.h"

#include <GLFW/glfw3.h>
#include <spdlog/fmt/fmt.h>

#include "Error.h"

namespace rt::gpu::gui
{
namespace
{
std::string g_lastGlfwError;

void onGlfwError(int, const char* description) { g_lastGlfwError = description ? description : "unknown error"; }
} // namespace

VulkanWindow::VulkanWindow(const std::string& title, WindowSize size, bool fitToMonitor)
{
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit())
        throw DeviceError(fmt::format("cannot open a window ({}); use --headless to render without one",
                                      g_lastGlfwError));
    if (!glfwVulkanSupported())
    {
        glfwTerminate();
        throw DeviceError("cannot open a window: GLFW finds no Vulkan loader with a surface extension for this "
                          "display; use --headless");
    }
    if (fitToMonitor)
        if (GLFWmonitor* monitor = glfwGetPrimaryMonitor())
        {
            WindowSize workArea;
            glfwGetMonitorWorkarea(monitor, nullptr, nullptr, &workArea.width, &workArea.height);
            size = fitWindowSize(size, workArea);
        }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    m_window = glfwCreateWindow(size.width, size.height, title.c_str(), nullptr, nullptr);
    if (!m_window)
    {
        glfwTerminate();
        throw DeviceError(fmt::format("cannot open a window ({}); use --headless", g_lastGlfwError));
    }
}

VulkanWindow::~VulkanWindow()
{
    glfwDestroyWindow(m_window);
    glfwTerminate();
}

std::vector<std::string> VulkanWindow::requiredInstanceExtensions()
{
    std::uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (!names)
        throw DeviceError(fmt::format("cannot present to a window: Vulkan offers no surface extension for this "
                                      "display ({})",
                                      g_lastGlfwError.empty() ? "is a Vulkan driver installed?" : g_lastGlfwError));
    return {names, names + count};
}

VkSurfaceKHR VulkanWindow::createSurface(VkInstance instance) const
{
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    const VkResult result = glfwCreateWindowSurface(instance, m_window, nullptr, &surface);
    if (result != VK_SUCCESS)
        throw DeviceError(fmt::format("glfwCreateWindowSurface failed ({}): {}", static_cast<int>(result),
                                      g_lastGlfwError));
    return surface;
}

Extent VulkanWindow::framebufferSize() const
{
    if (m_minimisedByRequest || glfwGetWindowAttrib(m_window, GLFW_ICONIFIED))
        return {};
    Extent size;
    glfwGetFramebufferSize(m_window, &size.width, &size.height);
    return size;
}

bool VulkanWindow::closeRequested() const { return glfwWindowShouldClose(m_window); }

void VulkanWindow::resize(Extent size)
{
    m_minimisedByRequest = size.width == 0 || size.height == 0;
    if (m_minimisedByRequest)
    {
        glfwIconifyWindow(m_window);
        return;
    }
    glfwRestoreWindow(m_window);
    glfwSetWindowSize(m_window, size.width, size.height);
}

void VulkanWindow::pollEvents() const { glfwPollEvents(); }

void VulkanWindow::waitEvents(double timeoutSeconds) const
{
    if (timeoutSeconds > 0.0)
        glfwWaitEventsTimeout(timeoutSeconds);
    else
        glfwWaitEvents();
}
} // namespace rt::gpu::gui
