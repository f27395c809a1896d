#include "IO/AtomicFile.h"

#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <system_error>

#include <spdlog/fmt/fmt.h>

#include "Error.h"

#ifndef _WIN32
#include <fcntl.h>
#include <unistd.h>
#else
#include <fcntl.h>
#include <io.h>
#include <process.h>
#include <share.h>
#include <sys/stat.h>
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

std::filesystem::path resolvedPath(const std::filesystem::path& path, std::error_code& ec)
{
    return std::filesystem::weakly_canonical(std::filesystem::absolute(path, ec), ec);
}

std::string namingShownFile(std::string message, const std::filesystem::path& temporary,
                            const std::filesystem::path& shown)
{
    const std::string from = temporary.string(), to = shown.string();
    for (std::size_t at = message.find(from); at != std::string::npos; at = message.find(from, at + to.size()))
        message.replace(at, from.size(), to);
    return message;
}

std::filesystem::path createTemporarySibling(const std::filesystem::path& path, const char* suffix)
{
    // The process and a counter, in hex: two writers of one process, or two processes, never share a name; a name
    // taken by anything else (a user's file, a link planted to redirect the write) is skipped, not followed. Short
    // (a temporary of a temporary is kTemporaryNameRoom longer than its file at most: checkWritable probes that).
    static std::atomic<std::uint64_t> counter = 0;
    const std::filesystem::path parent = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    if (std::error_code ec; !std::filesystem::is_directory(parent, ec))
        throw OutputError(fmt::format("cannot write '{}': folder '{}' does not exist", path.string(), parent.string()));
#ifndef _WIN32
    const auto process = static_cast<unsigned long>(::getpid());
#else
    const auto process = static_cast<unsigned long>(::_getpid());
#endif
    for (int attempt = 0; attempt < 1000; ++attempt)
    {
        std::filesystem::path candidate = path;
        candidate += fmt::format("{}{:x}-{:x}", suffix, process, counter++);
#ifndef _WIN32
        const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
#else
        int fd = -1;
        ::_wsopen_s(&fd, candidate.c_str(), _O_WRONLY | _O_CREAT | _O_EXCL | _O_BINARY, _SH_DENYNO,
                    _S_IREAD | _S_IWRITE);
#endif
        if (fd >= 0)
        {
#ifndef _WIN32
            ::close(fd);
#else
            ::_close(fd);
#endif
            return candidate;
        }
        if (errno != EEXIST)
            throw OutputError(fmt::format("cannot write '{}': {}", path.string(), std::strerror(errno)));
    }
    throw OutputError(fmt::format("cannot write '{}': no free temporary name beside it", path.string()));
}

bool writeBytes(const std::filesystem::path& file, std::string_view bytes)
{
#ifndef _WIN32
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0666);
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
    const std::filesystem::path tmp = createTemporarySibling(path, ".~w");
    std::error_code ec;
    errno = 0;
    bool written = false;
    try
    {
        written = write(tmp);
    }
    catch (const OutputError& e)
    {
        // The writer names the file it was given, ours: the user named `shownPath`.
        std::filesystem::remove(tmp, ec);
        throw OutputError(namingShownFile(e.what(), tmp, shownPath));
    }
    catch (...)
    {
        std::filesystem::remove(tmp, ec);
        throw;
    }
    if (!written || !syncToDisk(tmp))
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
