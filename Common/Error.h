// Error categories. Each carries a one-line, user-facing message naming the problem; the apps print it
// and exit with the category's status, so scripts can tell a typo from a broken GPU.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace rt
{
/// `text` safe for a terminal: control characters (a scene file's or a flag's raw bytes, which a message may
/// quote) written as \xNN, so that no input can move the cursor or clear the screen. Line breaks and tabs stay
/// (a message may list devices one per line); bytes of 0x80 and above (UTF-8) are kept.
inline std::string printableLine(std::string_view text)
{
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    for (const char c : text)
    {
        const auto byte = static_cast<unsigned char>(c);
        if ((byte < 0x20 && c != '\n' && c != '\t') || byte == 0x7f)
        {
            out += "\\x";
            out += kHex[byte >> 4];
            out += kHex[byte & 15];
        }
        else
            out += c;
    }
    return out;
}

class Error : public std::runtime_error
{
public:
    using std::runtime_error::runtime_error;
    virtual int exitCode() const { return 1; }
};

/// Bad command-line or settings value (spp 0, negative width, unknown flag).
class UsageError : public Error
{
public:
    using Error::Error;
    int exitCode() const override { return 2; }
};

/// Unknown scene id or an inconsistent scene description.
class SceneError : public Error
{
public:
    using Error::Error;
    int exitCode() const override { return 3; }
};

/// A missing or malformed file: texture, mesh.
class AssetError : public Error
{
public:
    using Error::Error;
    int exitCode() const override { return 4; }
};

/// No usable Vulkan device, or a device limit the request exceeds.
class DeviceError : public Error
{
public:
    using Error::Error;
    int exitCode() const override { return 5; }
};

/// Output that could not be written.
class OutputError : public Error
{
public:
    using Error::Error;
    int exitCode() const override { return 6; }
};
} // namespace rt
