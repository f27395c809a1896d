#include "Engine/RenderLimits.h"

#include <spdlog/fmt/fmt.h>

namespace rt::gpu
{
namespace
{
std::string gigabytes(std::uint64_t bytes) { return fmt::format("{:.1f} GB", double(bytes) * 1e-9); }
} // namespace

std::uint64_t renderTargetBytes(std::uint32_t width, std::uint32_t height)
{
    return 2 * kAccumulationBytesPerPixel * std::uint64_t(width) * height; // the sum and its compensation
}

std::optional<std::string> checkTargetLimits(std::uint32_t width, std::uint32_t height, const TargetLimits& limits)
{
    std::string problems;
    const auto add = [&problems](const std::string& text) { problems += (problems.empty() ? "" : "; ") + text; };
    const std::string image = fmt::format("image {}x{}", width, height);
    if (width > limits.maxImageDimension2D || height > limits.maxImageDimension2D)
        add(fmt::format("{} exceeds maxImageDimension2D {} of device '{}'", image, limits.maxImageDimension2D,
                        limits.deviceName));
    const std::uint64_t needed = renderTargetBytes(width, height);
    if (needed > limits.deviceLocalBytes)
        add(fmt::format("{} needs {} of device memory; device '{}' has {}", image, gigabytes(needed),
                        limits.deviceName, gigabytes(limits.deviceLocalBytes)));
    else if (const std::uint64_t oneImage = kAccumulationBytesPerPixel * std::uint64_t(width) * height;
             oneImage > limits.maxAllocationBytes) // fits the heap, but an image is one allocation
        add(fmt::format("{} needs one allocation of {}; maxMemoryAllocationSize of device '{}' is {}", image,
                        gigabytes(oneImage), limits.deviceName, gigabytes(limits.maxAllocationBytes)));
    if (std::uint64_t(width) * height > limits.maxRayDispatchInvocations)
        add(fmt::format("{} needs {} ray-generation invocations per trace; maxRayDispatchInvocationCount of "
                        "device '{}' is {}",
                        image, std::uint64_t(width) * height, limits.deviceName, limits.maxRayDispatchInvocations));
    if (problems.empty())
        return std::nullopt;
    return problems;
}
} // namespace rt::gpu
