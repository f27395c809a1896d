// Error categories. Each carries a one-line, user-facing message naming the problem; the apps print it
// and exit with the category's status, so scripts can tell a typo from a broken GPU.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace rt
{
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
