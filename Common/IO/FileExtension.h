// A path's extension as the checks compare it: ".png" of "OUT.PNG" (the outputs' and scene files' extension tests
// take any case).
#pragma once

#include <cctype>
#include <filesystem>
#include <string>

namespace rt
{
inline std::string lowercaseExtension(const std::filesystem::path& path)
{
    std::string extension = path.extension().string();
    for (char& c : extension)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}
} // namespace rt
