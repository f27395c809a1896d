// Noticing that a scene file changed on disk, so that a window can show a scene while its author edits it.
// Polling the file's status (modification time and size) twice a second is portable, costs one stat() per
// poll, and needs no thread; inotify/ReadDirectoryChangesW would add a platform layer for no visible gain.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace rt
{
/// The version of the scene file `idOrPath` as the file system reports it: its modification time (ticks of
/// std::filesystem::file_time_type's clock) mixed with its size, so that a rewrite within the clock's
/// resolution that changes the length still counts as a new version. 0 for a catalogue id (not a scene file
/// path, SceneFile.h); -1 for a file whose status cannot be read (missing, no permission). Never throws.
std::int64_t sceneFileVersion(std::string_view idOrPath);

/// Polls one scene file for new versions. A version is reported once: a file that fails to load is tried
/// again only after it changes again, so a window keeps its last good scene without retrying every poll.
class SceneFileWatch
{
public:
    using Clock = std::chrono::steady_clock;

    explicit SceneFileWatch(Clock::duration interval = std::chrono::milliseconds(500)) : m_interval(interval) {}

    /// Watches `idOrPath` from now on, whose version `seen` (sceneFileVersion) is the one on screen or being
    /// loaded. A catalogue id stops the watch.
    void watch(const std::string& idOrPath, std::int64_t seen);

    /// The file's version when it differs from the last one seen and at least the interval has passed since
    /// the last poll; nullopt otherwise (also for a catalogue id). The version returned counts as seen.
    std::optional<std::int64_t> poll(Clock::time_point now);

    const std::string& path() const { return m_path; }

private:
    Clock::duration m_interval;
    std::string m_path; // empty: nothing to watch
    std::int64_t m_seen = 0;
    Clock::time_point m_lastPoll{};
};
} // namespace rt
