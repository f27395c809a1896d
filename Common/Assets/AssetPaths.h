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

/// A user-given path (absolute, or relative to the working directory) if that file exists, else
/// assetRoot()/path. Throws AssetError naming `what` ("texture", "mesh") and every place looked in.
std::filesystem::path resolveAsset(const std::string& path, const std::string& what);
} // namespace rt
