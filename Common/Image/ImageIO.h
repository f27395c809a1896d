// Image files. Every writer goes through a temporary file renamed into place, so a failed or cancelled
// write never leaves a half-written image behind; failures throw OutputError naming the path.
#pragma once

#include <filesystem>
#include <vector>

#include "Image/ExrIO.h"
#include "Image/Image.h"

namespace rt
{
/// 8-bit sRGB PNG of the linear image: clamp to [0, 1], then the sRGB transfer curve (IEC 61966-2-1).
/// NaN pixels are written black. This is the books' "gamma 2" look made exact.
void writePng(const std::filesystem::path& path, const Image& image);

/// 8-bit RGBA pixels already encoded for display (a window's framebuffer), row 0 at the top, as a PNG.
void writePng8(const std::filesystem::path& path, int width, int height, const std::vector<unsigned char>& rgba);

/// Portable Float Map ("PF", little-endian, bottom row first per the format): lossless linear radiance.
void writePfm(const std::filesystem::path& path, const Image& image);

/// What the windows' Save image writes: `png` (writePng) and its linear radiance beside it, the same name with
/// .pfm (writePfm) and with .exr (float OpenEXR, Image/ExrIO.h, for the tools that read no PFM). Returns the
/// linear files' paths, PFM first.
std::vector<std::filesystem::path> writePngWithLinear(const std::filesystem::path& png, const Image& image);

/// Reads a PFM written by writePfm (or any RGB little- or big-endian PFM). Throws AssetError.
Image readPfm(const std::filesystem::path& path);

/// Reads a linear image by its extension: OpenEXR (.exr, Image/ExrIO.h) or else PFM. Throws AssetError.
Image readLinearImage(const std::filesystem::path& path);

/// Writes by extension: .png, .pfm or .exr (half unless `exrType` says float). Throws UsageError for anything
/// else.
void writeImage(const std::filesystem::path& path, const Image& image, ExrPixelType exrType = ExrPixelType::Half);

/// The sRGB-encoded 8-bit value of a linear value in [0, 1].
unsigned char linearToSrgb8(float linear);
/// The linear value of an sRGB-encoded 8-bit value (exact table of the transfer curve).
float srgb8ToLinear(unsigned char encoded);
} // namespace rt
