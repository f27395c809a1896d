// Ownership of one handle created from a VkDevice and destroyed by vkDestroyXxx(device, handle, nullptr).
// The RAII classes of this folder hold one each, which makes them non-copyable and movable (the moved-from
// handle is null) without repeating the move code in every class.
#pragma once

#include <utility>

#include "Vulkan/Loader.h"

namespace rt::vk
{
/// `Destroy` is the address of the loader's function pointer (e.g. &rt::vkDestroyFence), read at destruction.
template <typename Handle, auto* Destroy>
class DeviceHandle final
{
public:
    DeviceHandle() = default;
    DeviceHandle(VkDevice device, Handle handle) : m_device(device), m_handle(handle) {}
    ~DeviceHandle() { reset(); }
    DeviceHandle(const DeviceHandle&) = delete;
    DeviceHandle& operator=(const DeviceHandle&) = delete;
    DeviceHandle(DeviceHandle&& other) noexcept
        : m_device(std::exchange(other.m_device, VK_NULL_HANDLE)), m_handle(std::exchange(other.m_handle, Handle{}))
    {
    }
    DeviceHandle& operator=(DeviceHandle&& other) noexcept
    {
        if (this != &other)
        {
            reset();
            m_device = std::exchange(other.m_device, VK_NULL_HANDLE);
            m_handle = std::exchange(other.m_handle, Handle{});
        }
        return *this;
    }

    Handle get() const { return m_handle; }
    VkDevice device() const { return m_device; }

    void reset()
    {
        if (m_handle != Handle{})
            (*Destroy)(m_device, m_handle, nullptr);
        m_handle = Handle{};
    }

private:
    VkDevice m_device = VK_NULL_HANDLE;
    Handle m_handle{};
};

/// The move-only boilerplate of a class whose members are DeviceHandles and values.
#define RT_VK_MOVE_ONLY(Class)                                                                                 \
    Class(const Class&) = delete;                                                                              \
    Class& operator=(const Class&) = delete;                                                                   \
    Class(Class&&) noexcept = default;                                                                         \
    Class& operator=(Class&&) noexcept = default;
} // namespace rt::vk
