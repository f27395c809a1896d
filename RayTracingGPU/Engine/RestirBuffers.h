// restir-di's memory on the GPU (Shaders/Restir/): per pixel of a frame, its resampled vertex (RestirSurface, 64
// bytes), its reservoir after the candidates pass and after spatial reuse (Reservoir, 32 bytes each: 64 bytes of
// reservoirs per pixel, the bound) and the slot in which a ray names the camera sample it is traced as
// (8 bytes). Bound at kBindingRestirSurfaces .. kBindingRestirTraced of every descriptor set the tracer makes; a
// frame of another estimator binds the tracer's buffers of one pixel.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "Shared/HostDevice.h"
#include "Vulkan/Buffer.h"

namespace rt::gpu
{
class RestirBuffers final
{
public:
    static constexpr std::uint64_t kReservoirBytesPerPixel = 2 * sizeof(shader::Reservoir);
    static constexpr std::uint64_t kSurfaceBytesPerPixel = sizeof(shader::RestirSurface);
    static constexpr std::uint64_t kTracedBytesPerPixel = 2 * sizeof(std::uint32_t);

    /// Buffers for `pixels` pixels (at least 1). Throws rt::DeviceError when the device cannot allocate them.
    RestirBuffers(const vk::Device& device, std::uint64_t pixels);
    RestirBuffers(RestirBuffers&&) noexcept = default;
    RestirBuffers& operator=(RestirBuffers&&) noexcept = default;

    std::uint64_t pixels() const { return m_pixels; }
    const vk::Buffer& surfaces() const { return m_surfaces; }
    const vk::Buffer& temporal() const { return m_temporal; }
    const vk::Buffer& final() const { return m_final; }
    const vk::Buffer& traced() const { return m_traced; }

    /// Why `pixels` pixels do not fit one storage buffer of `device` (its largest binding range), or nothing.
    static std::optional<std::string> tooLargeFor(const vk::Device& device, std::uint64_t pixels);
    /// "reservoirs" and "surfaces" bytes per pixel (RenderEngine::frameBytesPerPixel).
    static std::map<std::string, std::uint64_t> bytesPerPixel();

private:
    std::uint64_t m_pixels;
    vk::Buffer m_surfaces;
    vk::Buffer m_temporal;
    vk::Buffer m_final;
    vk::Buffer m_traced;
};
} // namespace rt::gpu
