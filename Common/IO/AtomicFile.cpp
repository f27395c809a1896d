#include "IO/AtomicFile.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

#include <spdlog/fmt/fmt.h>

#include "Error.h"

#ifndef _WIN32
#include <fcntl.h>
#include <unistd.h>
#endif

namespace rt
{
namespace
{
/// Flushes what was written to `file` to the disk: a file system that accepts writes into its cache and finds
/// no room later (delayed allocation, a network or thin-provisioned disk) says so here. Returns false with
/// errno set.
bool syncToDisk(const std::filesystem::path& file)
{
#ifndef _WIN32
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return false;
    // A file system that cannot sync (some FUSE and shared folders: EINVAL, ENOTSUP) has written what it took.
    const bool synced = ::fsync(fd) == 0 || errno == EINVAL || errno == ENOTSUP;
    const int reason = errno;
    if (::close(fd) != 0 && synced)
        return false;
    errno = reason;
    return synced;
#else
    (void)file;
    return true;
#endif
}

const char* kindOf(const std::filesystem::file_status& status)
{
    switch (status.type())
    {
    case std::filesystem::file_type::directory:
        return "a folder";
    case std::filesystem::file_type::block:
    case std::filesystem::file_type::character:
        return "a device";
    case std::filesystem::file_type::fifo:
        return "a pipe";
    case std::filesystem::file_type::socket:
        return "a socket";
    default:
        return "not a regular file";
    }
}
} // namespace

std::string outputTargetProblem(const std::filesystem::path& path, std::filesystem::path& target)
{
    std::error_code ec;
    target = path;
    if (std::filesystem::is_symlink(std::filesystem::symlink_status(path, ec)))
    {
        target = std::filesystem::canonical(path, ec);
        if (ec)
        {
            target = path;
            std::error_code ignored;
            return fmt::format("it is a symbolic link to '{}', which does not exist",
                               std::filesystem::read_symlink(path, ignored).string());
        }
        const std::filesystem::file_status status = std::filesystem::status(target, ec);
        if (!std::filesystem::is_regular_file(status))
            return fmt::format("it is a symbolic link to '{}', {}: only a regular file is replaced", target.string(),
                               kindOf(status));
        return {};
    }
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
        return fmt::format("it is {}: only a regular file is replaced", kindOf(status));
    return {};
}

std::filesystem::path outputTarget(const std::filesystem::path& path)
{
    std::filesystem::path target;
    if (const std::string problem = outputTargetProblem(path, target); !problem.empty())
        throw OutputError(fmt::format("cannot write '{}': {}", path.string(), problem));
    return target;
}

bool writeBytes(const std::filesystem::path& file, std::string_view bytes)
{
#ifndef _WIN32
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0)
        return false;
    for (std::size_t done = 0; done < bytes.size();)
    {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
        {
            const int reason = n == 0 ? EIO : errno;
            ::close(fd);
            errno = reason;
            return false;
        }
        done += static_cast<std::size_t>(n);
    }
    return ::close(fd) == 0;
#else
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    return static_cast<bool>(out);
#endif
}

void writeAtomically(const std::filesystem::path& shownPath,
                     const std::function<bool(const std::filesystem::path&)>& write)
{
    const std::filesystem::path path = outputTarget(shownPath);
    const std::filesystem::path parent = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    if (!std::filesystem::is_directory(parent))
        throw OutputError(fmt::format("cannot write '{}': folder '{}' does not exist", shownPath.string(), parent.string()));
    std::filesystem::path tmp = path;
    tmp += ".partial";
    std::error_code ec;
    errno = 0;
    if (!write(tmp) || !syncToDisk(tmp))
    {
        // The C library's reason where the writer's stream or the flush set one (a full disk: ENOSPC).
        const int reason = errno;
        std::filesystem::remove(tmp, ec);
        throw OutputError(reason != 0 ? fmt::format("cannot write '{}': {}", shownPath.string(), std::strerror(reason))
                                      : fmt::format("cannot write '{}'", shownPath.string()));
    }
    std::filesystem::rename(tmp, path, ec);
    if (ec)
    {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        throw OutputError(fmt::format("cannot write '{}': {}", shownPath.string(), ec.message()));
    }
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes)
{
    writeAtomically(path, [&](const std::filesystem::path& tmp) { return writeBytes(tmp, bytes); });
}
} // namespace rt
