#include "Render/MemoryBudget.h"

#include <fstream>
#include <limits>
#include <sstream>

#include <spdlog/fmt/fmt.h>

#include "Error.h"

#ifndef _WIN32
#include <unistd.h>
#endif

namespace rt
{
namespace
{
std::uint64_t saturatingMultiply(std::uint64_t a, std::uint64_t b)
{
    if (a != 0 && b > std::numeric_limits<std::uint64_t>::max() / a)
        return std::numeric_limits<std::uint64_t>::max();
    return a * b;
}

std::string gigabytes(std::uint64_t bytes) { return fmt::format("{:.1f} GB", double(bytes) * 1e-9); }
} // namespace

std::uint64_t renderBytes(std::uint64_t pixels, std::uint64_t sceneObjects)
{
    const std::uint64_t image = saturatingMultiply(pixels, kRenderBytesPerPixel);
    const std::uint64_t scene = saturatingMultiply(sceneObjects, kSceneBytesPerObject);
    return image > std::numeric_limits<std::uint64_t>::max() - scene ? std::numeric_limits<std::uint64_t>::max()
                                                                       : image + scene;
}

std::uint64_t renderBytes(const RenderSettings& settings, std::uint64_t sceneObjects)
{
    const std::uint64_t pixels = std::uint64_t(settings.width) * std::uint64_t(settings.height());
    const std::uint64_t restirPixels =
        settings.estimator == Estimator::RestirDi ? pixels * (kRestirBytesPerPixel / kRenderBytesPerPixel) : 0;
    return renderBytes(pixels + restirPixels, sceneObjects);
}

std::string describeBytes(std::uint64_t bytes)
{
    return bytes >= 1'000'000'000 ? gigabytes(bytes) : fmt::format("{:.1f} MB", double(bytes) * 1e-6);
}

std::uint64_t availableMemoryBytes()
{
    std::ifstream meminfo("/proc/meminfo");
    std::string line;
    while (std::getline(meminfo, line))
        if (line.rfind("MemAvailable:", 0) == 0)
        {
            std::istringstream words(line.substr(13));
            std::uint64_t kilobytes = 0;
            if (words >> kilobytes)
                return kilobytes * 1024;
        }
#ifndef _WIN32
    const long pages = ::sysconf(_SC_AVPHYS_PAGES);
    const long pageSize = ::sysconf(_SC_PAGESIZE);
    if (pages > 0 && pageSize > 0)
        return std::uint64_t(pages) * std::uint64_t(pageSize);
#endif
    return 0;
}

std::uint64_t availableMemoryBytesReplacing(std::uint64_t heldBytes)
{
    const std::uint64_t available = availableMemoryBytes();
    return available > 0 ? available + heldBytes : 0;
}

void checkMemory(std::uint64_t neededBytes, const std::string& what, std::uint64_t availableBytes)
{
    if (availableBytes == 0 || neededBytes <= availableBytes)
        return;
    throw UsageError(fmt::format("{} needs about {} of memory; this machine has {} available", what,
                                 gigabytes(neededBytes), gigabytes(availableBytes)));
}
} // namespace rt
