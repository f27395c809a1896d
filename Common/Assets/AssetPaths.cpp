#include "Assets/AssetPaths.h"

#include <cstdlib>
#include <system_error>

#include <spdlog/fmt/fmt.h>

#include "Error.h"

#ifdef _WIN32
#include <windows.h>
#endif

namespace rt
{
std::filesystem::path executableDir()
{
#ifdef _WIN32
    wchar_t buffer[MAX_PATH];
    const DWORD n = GetModuleFileNameW(nullptr, buffer, MAX_PATH);
    return std::filesystem::path(std::wstring(buffer, n)).parent_path();
#else
    std::error_code ec;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::filesystem::current_path() : exe.parent_path();
#endif
}

std::filesystem::path assetRoot()
{
    if (const char* env = std::getenv("RT_ASSET_DIR"); env && *env)
        return env;
    const std::filesystem::path exe = executableDir();
    for (const auto& candidate : {exe / "Assets", exe.parent_path() / "Assets"})
        if (std::filesystem::is_directory(candidate))
            return candidate;
#ifdef RT_SOURCE_ASSET_DIR
    return RT_SOURCE_ASSET_DIR;
#else
    return exe / "Assets";
#endif
}

namespace
{
bool isInside(const std::filesystem::path& file, const std::filesystem::path& folder)
{
    std::error_code ec;
    const std::filesystem::path root = std::filesystem::weakly_canonical(folder, ec);
    if (ec || root.empty())
        return false;
    const std::filesystem::path relative = file.lexically_relative(root);
    return !relative.empty() && *relative.begin() != "..";
}
} // namespace

std::string outsideSceneFolders(const std::filesystem::path& file, const std::filesystem::path& sceneFolder)
{
    std::error_code ec;
    const std::filesystem::path resolved = std::filesystem::weakly_canonical(file, ec);
    if (!ec && (isInside(resolved, sceneFolder.empty() ? std::filesystem::path(".") : sceneFolder) ||
                isInside(resolved, assetRoot())))
        return {};
    return fmt::format("'{}' lies outside the scene's folder and the asset folder (a scene reads files only from "
                       "there)",
                       ec ? file.string() : resolved.string());
}

std::filesystem::path resolveAsset(const std::string& path, const std::string& what)
{
    const std::filesystem::path given(path);
    if (std::filesystem::is_regular_file(given))
        return given;
    const std::filesystem::path inRoot = assetRoot() / given;
    if (std::filesystem::is_regular_file(inRoot))
        return inRoot;
    // A folder, a pipe or a device is named as what it is: "not found" would send the user looking elsewhere.
    for (const std::filesystem::path& p : {given, inRoot})
        if (std::error_code ec; std::filesystem::exists(p, ec))
            throw AssetError(fmt::format("{} file '{}' is not a regular file", what, p.string()));
    throw AssetError(fmt::format("{} file not found: '{}' (looked in the working directory and in '{}')", what,
                                 path, assetRoot().string()));
}
} // namespace rt
