#include "Compare/CacheEntry.h"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string_view>

namespace rt::compare
{
std::filesystem::path cacheFolder(const char* variable, const char* folder)
{
    if (const char* dir = std::getenv(variable))
        return std::string_view(dir) == "off" ? std::filesystem::path() : std::filesystem::path(dir);
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
        return std::filesystem::path(xdg) / "ray-tracing" / folder;
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".cache" / "ray-tracing" / folder;
    return {};
}

std::optional<nlohmann::json> readCacheEntry(const std::filesystem::path& file, const std::string& key)
{
    std::ifstream in(file);
    if (!in)
        return std::nullopt;
    std::stringstream text;
    text << in.rdbuf();
    nlohmann::json stored = nlohmann::json::parse(text.str(), nullptr, false);
    if (stored.is_discarded() || !stored.is_object() || !stored.contains("key") ||
        stored["key"] != nlohmann::json::parse(key))
        return std::nullopt;
    return stored;
}
} // namespace rt::compare
