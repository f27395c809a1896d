// What --compare's on-disk caches (ReferenceCache.h, StrategyCache.h) share: where a cache's folder is, and an
// entry's JSON file read back only when it is whole and was written under the same key (its file name is a hash of
// the key, Fnv1a.h, so two keys may share a name).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace rt::compare
{
/// $`variable` ('off': none, an empty path), else $XDG_CACHE_HOME/ray-tracing/`folder`, else
/// ~/.cache/ray-tracing/`folder`; empty where none of them is set.
std::filesystem::path cacheFolder(const char* variable, const char* folder);

/// The JSON object in `file` when it parses and its "key" is `key` (JSON text); nullopt for a file missing,
/// damaged or of another key: the caller renders (or measures) anew.
std::optional<nlohmann::json> readCacheEntry(const std::filesystem::path& file, const std::string& key);
} // namespace rt::compare
