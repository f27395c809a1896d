#pragma once

#include <string>

#include "Scene/Scene.h"

namespace rt
{
/// Loads an 8-bit image (PNG, JPEG, ...) as sRGB-encoded RGBA texels through stb_image.
/// `path` is resolved with resolveAsset. Throws AssetError if the file is missing or cannot be decoded.
ImageData loadImage(const std::string& path);
} // namespace rt
