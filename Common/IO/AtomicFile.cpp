#include "IO/AtomicFile.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

#include <spdlog/fmt/fmt.h>

#include "Error.h"

namespace rt
{
std::filesystem::path outputTarget(const std::filesystem::path& path)
{
    std::error_code ec;
    if (!std::filesystem::is_symlink(path, ec))
        return path;
    const std::filesystem::path target = std::filesystem::weakly_canonical(path, ec);
    return ec ? path : target;
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
    if (!write(tmp))
    {
        // The C library's reason where the writer's stream set one (a full disk: ENOSPC).
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
    writeAtomically(path, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.close();
        return static_cast<bool>(out);
    });
}
} // namespace rt
