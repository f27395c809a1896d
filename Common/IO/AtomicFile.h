#pragma once

#include <filesystem>
#include <functional>
#include <string_view>

namespace rt
{
/// Runs `write` on a sibling temporary file and renames it over `path` (over its target, for a symbolic link:
/// outputTarget) only if `write` returned true, so a failed, cancelled or crashed write never leaves a
/// half-written file behind. Throws OutputError naming `path` and, where the C library gave one, the reason
/// (missing folder, write failure, rename failure).
void writeAtomically(const std::filesystem::path& path, const std::function<bool(const std::filesystem::path&)>& write);

/// Where writing `path` must land: the file a symbolic link points to (followed to its end), so that the
/// rename of writeAtomically and OutputSet replaces the target and keeps the link; `path` itself otherwise.
std::filesystem::path outputTarget(const std::filesystem::path& path);

/// writeAtomically for a text or binary blob.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);
} // namespace rt
