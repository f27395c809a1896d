#include "IO/OutputSet.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <system_error>

#include <spdlog/fmt/fmt.h>

#include "Error.h"
#include "IO/AtomicFile.h"

#ifndef _WIN32
#include <unistd.h>
#endif

namespace rt
{
namespace
{
void removeQuietly(const std::filesystem::path& path)
{
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
}
} // namespace

void checkWritable(const std::filesystem::path& shown, const char* flag)
{
    std::error_code ec;
    if (std::filesystem::is_directory(shown, ec))
        throw OutputError(fmt::format("{} '{}' is a folder, not a file", flag, shown.string()));
    std::filesystem::path path; // where the file lands: the link's target, for a symbolic link
    if (const std::string problem = outputTargetProblem(shown, path); !problem.empty())
        throw OutputError(fmt::format("{} '{}': {}", flag, shown.string(), problem));
    const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    if (!std::filesystem::is_directory(folder, ec))
        throw OutputError(fmt::format("{} '{}': folder '{}' {}", flag, shown.string(), folder.string(),
                                      std::filesystem::exists(folder, ec) ? "is not a folder" : "does not exist"));
#ifndef _WIN32
    // As long as the output's name with its temporaries' (a name past the file system's limit fails here, not after
    // the render).
    std::string probe =
        (folder / (path.filename().string() + ".~" + std::string(kTemporaryNameRoom - 8, 'x') + "XXXXXX")).string();
    const int fd = ::mkstemp(probe.data());
    if (fd < 0)
        throw OutputError(fmt::format("{} '{}': cannot create a file in folder '{}': {}", flag, shown.string(),
                                      folder.string(), std::strerror(errno)));
    ::close(fd);
    ::unlink(probe.c_str());
#endif
}

void OutputSet::add(std::filesystem::path path, Writer write)
{
    std::filesystem::path target = outputTarget(path);
    std::error_code ec;
    const std::filesystem::path resolved = resolvedPath(target, ec);
    for (const Entry& e : m_entries)
        if (std::error_code other; resolvedPath(e.path, other) == resolved && !ec && !other)
            throw OutputError(fmt::format("cannot write '{}': another output of this render is the same file",
                                          path.string()));
    m_entries.push_back({std::move(target), std::move(write), {}});
}

void OutputSet::commit()
{
    std::size_t written = 0; // entries whose temporary exists
    std::size_t placed = 0; // entries renamed into place
    try
    {
        for (; written < m_entries.size(); ++written)
        {
            Entry& entry = m_entries[written];
            entry.pending = createTemporarySibling(entry.path, ".~p");
            try
            {
                entry.write(entry.pending);
            }
            catch (const OutputError& e)
            {
                // The writer names the file it was given, ours: the user named `entry.path`.
                throw OutputError(namingShownFile(e.what(), entry.pending, entry.path));
            }
        }
        for (; placed < m_entries.size(); ++placed)
        {
            std::error_code ec;
            std::filesystem::rename(m_entries[placed].pending, m_entries[placed].path, ec);
            if (ec)
                throw OutputError(fmt::format("cannot write '{}': {}", m_entries[placed].path.string(), ec.message()));
        }
    }
    catch (...)
    {
        for (std::size_t i = 0; i < placed; ++i)
            removeQuietly(m_entries[i].path);
        for (std::size_t i = placed; i < m_entries.size() && i <= written; ++i)
            if (!m_entries[i].pending.empty())
                removeQuietly(m_entries[i].pending);
        throw;
    }
}
} // namespace rt
