// Whether a render of a given size fits the device, checked before anything is allocated so that absurd
// requests end with one line naming the limit instead of an allocation failure, a crash or a hang.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace rt::gpu
{
/// The device limits a render target depends on (from vk::DeviceProperties).
struct TargetLimits
{
    std::string deviceName;
    std::uint32_t maxImageDimension2D = 0;
    std::uint64_t deviceLocalBytes = 0; // the largest DEVICE_LOCAL heap
    std::uint64_t maxAllocationBytes = 0; // maxMemoryAllocationSize
    std::uint64_t maxRayDispatchInvocations = 0; // maxRayDispatchInvocationCount: one launch per pixel
};

/// Bytes per pixel of the RGBA32F accumulation image, and of its readback buffer.
inline constexpr std::uint64_t kAccumulationBytesPerPixel = 16;

/// The device-local memory a width x height render needs: its accumulation image and the image of its Kahan
/// compensation, of the same format. (The readback copy is
/// host-visible memory, which discrete GPUs take from system RAM.)
std::uint64_t renderTargetBytes(std::uint32_t width, std::uint32_t height);

/// Empty if a width x height render fits, else one line naming every exceeded limit, e.g.
/// "image 60000x60000 needs 57.6 GB of device memory; device 'llvmpipe' has 23.5 GB".
std::optional<std::string> checkTargetLimits(std::uint32_t width, std::uint32_t height, const TargetLimits& limits);
} // namespace rt::gpu
