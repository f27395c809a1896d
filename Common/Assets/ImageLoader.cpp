#include "Assets/ImageLoader.h"

#include <climits>
#include <cstring>

#include <spdlog/fmt/fmt.h>
#include <stb_image.h>

#include "Assets/AssetPaths.h"
#include "Error.h"

namespace rt
{
namespace
{
/// Takes stb's RGBA texels (freed here) into an ImageData.
ImageData adopt(stbi_uc* texels, int width, int height, const std::string& path)
{
    ImageData image;
    image.path = path;
    image.width = width;
    image.height = height;
    image.rgba.resize(std::size_t(width) * height * 4);
    std::memcpy(image.rgba.data(), texels, image.rgba.size());
    stbi_image_free(texels);
    return image;
}
} // namespace

ImageData loadImage(const std::string& path)
{
    const std::filesystem::path file = resolveAsset(path, "texture");
    int width = 0, height = 0, channels = 0;
    stbi_uc* texels = stbi_load(file.string().c_str(), &width, &height, &channels, 4);
    if (!texels)
        throw AssetError(fmt::format("texture '{}' cannot be decoded: {}", file.string(), stbi_failure_reason()));
    return adopt(texels, width, height, file.string());
}

ImageData decodeImage(const std::uint8_t* bytes, std::size_t size, const std::string& name)
{
    if (size == 0 || size > std::size_t(INT_MAX))
        throw AssetError(fmt::format("image '{}' cannot be decoded: {} bytes", name, size));
    int width = 0, height = 0, channels = 0;
    stbi_uc* texels = stbi_load_from_memory(bytes, static_cast<int>(size), &width, &height, &channels, 4);
    if (!texels)
        throw AssetError(fmt::format("image '{}' cannot be decoded: {}", name, stbi_failure_reason()));
    return adopt(texels, width, height, name);
}
} // namespace rt
