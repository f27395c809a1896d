#pragma once

#include <filesystem>
#include <string>

namespace rt
{
/// Folder of the running executable (resolved through /proc/self/exe or GetModuleFileName).
std::filesystem::path executableDir();

/// Root of the asset folder: $RT_ASSET_DIR if set, else the first of <exe>/Assets, <exe>/../Assets and the
/// source tree's Assets that exists. Never the working directory: a render must not depend on where it starts.
std::filesystem::path assetRoot();

/// Why a scene file may not read `file`, or "" when it may: a scene reads files only inside its own folder
/// `sceneFolder` or the asset folder (assetRoot), judged after `..` and symbolic links are resolved, so that a
/// reference such as "../../etc/passwd" cannot read (nor --export-scene copy) a file outside them.
std::string outsideSceneFolders(const std::filesystem::path& file, const std::filesystem::path& sceneFolder);

/// A user-given path (absolute, or relative to the working directory) if that file exists, else
/// assetRoot()/path. Throws AssetError naming `what` ("texture", "mesh") and every place looked in.
std::filesystem::path resolveAsset(const std::string& path, const std::string& what);
} // namespace rt
