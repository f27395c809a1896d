#include "Vulkan/Surface.h"

#include <utility>

namespace rt::vk
{
Surface::Surface(VkInstance instance, VkSurfaceKHR surface) : m_instance(instance), m_surface(surface) {}

Surface::~Surface() { destroy(); }

Surface::Surface(Surface&& other) noexcept
    : m_instance(std::exchange(other.m_instance, VK_NULL_HANDLE)),
      m_surface(std::exchange(other.m_surface, VK_NULL_HANDLE))
{
}

Surface& Surface::operator=(Surface&& other) noexcept
{
    if (this != &other)
    {
        destroy();
        m_instance = std::exchange(other.m_instance, VK_NULL_HANDLE);
        m_surface = std::exchange(other.m_surface, VK_NULL_HANDLE);
    }
    return *this;
}

void Surface::destroy()
{
    if (m_surface != VK_NULL_HANDLE)
        vkDestroySurfaceKHR(m_instance, m_surface, nullptr);
    m_surface = VK_NULL_HANDLE;
}
} // namespace rt::vk
