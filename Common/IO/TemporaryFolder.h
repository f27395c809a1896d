// A fresh folder under the system's temporary directory for files a figure script reads, removed with its
// contents when the scope ends (also when an exception leaves it).
#pragma once

#include <filesystem>
#include <random>
#include <string>

#include <spdlog/fmt/fmt.h>

namespace rt
{
class TemporaryFolder
{
public:
    /// Creates <temp>/<prefix>-<8 random hex digits>, a folder no one else has (a name taken is drawn again).
    /// Throws std::filesystem::filesystem_error when it cannot.
    explicit TemporaryFolder(const std::string& prefix)
    {
        std::random_device random;
        do
            m_path = std::filesystem::temp_directory_path() / fmt::format("{}-{:08x}", prefix, random());
        while (!std::filesystem::create_directory(m_path));
    }
    ~TemporaryFolder()
    {
        std::error_code ignored;
        std::filesystem::remove_all(m_path, ignored);
    }
    TemporaryFolder(const TemporaryFolder&) = delete;
    TemporaryFolder& operator=(const TemporaryFolder&) = delete;
    const std::filesystem::path& path() const { return m_path; }

private:
    std::filesystem::path m_path;
};
} // namespace rt
