#include "SceneFile/SceneFileWatch.h"

#include <filesystem>
#include <system_error>

#include "SceneFile/SceneFile.h"

namespace rt
{
std::int64_t sceneFileVersion(std::string_view idOrPath)
{
    if (!isSceneFilePath(idOrPath))
        return 0;
    const std::filesystem::path file(idOrPath);
    std::error_code ec;
    const auto time = std::filesystem::last_write_time(file, ec);
    if (ec)
        return -1;
    const std::uintmax_t size = std::filesystem::file_size(file, ec);
    if (ec)
        return -1;
    // Odd multiplier: distinct sizes at one time give distinct versions; never 0 or -1 in practice.
    const auto ticks = static_cast<std::uint64_t>(time.time_since_epoch().count());
    const std::uint64_t version = ticks ^ (static_cast<std::uint64_t>(size) * 0x9E3779B97F4A7C15ull);
    return static_cast<std::int64_t>(version & 0x7FFFFFFFFFFFFFFFull) | 1;
}

void SceneFileWatch::watch(const std::string& idOrPath, std::int64_t seen)
{
    m_path = isSceneFilePath(idOrPath) ? idOrPath : std::string();
    m_seen = seen;
}

std::optional<std::int64_t> SceneFileWatch::poll(Clock::time_point now)
{
    if (m_path.empty() || now - m_lastPoll < m_interval)
        return std::nullopt;
    m_lastPoll = now;
    const std::int64_t version = sceneFileVersion(m_path);
    if (version == m_seen)
        return std::nullopt;
    m_seen = version;
    return version;
}
} // namespace rt
