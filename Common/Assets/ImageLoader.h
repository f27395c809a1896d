#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "Scene/Scene.h"

namespace rt
{
/// Loads an 8-bit image (PNG, JPEG, ...) as sRGB-encoded RGBA texels through stb_image.
/// `path` is resolved with resolveAsset. Throws AssetError if the file is missing or cannot be decoded.
ImageData loadImage(const std::string& path);

/// Decodes an 8-bit image held in memory (a glTF file's embedded PNG or JPEG) as loadImage does; `name` is the
/// image's path in the result and names it in errors. Throws AssetError if the bytes cannot be decoded.
ImageData decodeImage(const std::uint8_t* bytes, std::size_t size, const std::string& name);
} // namespace rt
