// A VkSurfaceKHR of a window, created by the windowing library (glfwCreateWindowSurface) and owned here. It
// belongs to the instance: destroy it after every swapchain made from it and before the instance.
#pragma once

#include "Vulkan/Loader.h"

namespace rt::vk
{
class Surface final
{
public:
    Surface() = default;
    /// Takes ownership of `surface`, created from `instance`.
    Surface(VkInstance instance, VkSurfaceKHR surface);
    ~Surface();
    Surface(const Surface&) = delete;
    Surface& operator=(const Surface&) = delete;
    Surface(Surface&& other) noexcept;
    Surface& operator=(Surface&& other) noexcept;

    VkSurfaceKHR Handle() const { return m_surface; }

private:
    void destroy();

    VkInstance m_instance = VK_NULL_HANDLE;
    VkSurfaceKHR m_surface = VK_NULL_HANDLE;
};
} // namespace rt::vk
