#include "IO/AtomicFile.h"

#include <fstream>
#include <system_error>

#include <spdlog/fmt/fmt.h>

#include "Error.h"

namespace rt
{
void writeAtomically(const std::filesystem::path& path, const std::function<bool(const std::filesystem::path&)>& write)
{
    const std::filesystem::path parent = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    if (!std::filesystem::is_directory(parent))
        throw OutputError(fmt::format("cannot write '{}': folder '{}' does not exist", path.string(), parent.string()));
    std::filesystem::path tmp = path;
    tmp += ".partial";
    std::error_code ec;
    if (!write(tmp))
    {
        std::filesystem::remove(tmp, ec);
        throw OutputError(fmt::format("cannot write '{}'", path.string()));
    }
    std::filesystem::rename(tmp, path, ec);
    if (ec)
    {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        throw OutputError(fmt::format("cannot write '{}': {}", path.string(), ec.message()));
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
