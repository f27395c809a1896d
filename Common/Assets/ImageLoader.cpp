#include "Assets/ImageLoader.h"

#include <cstring>

#include <spdlog/fmt/fmt.h>
#include <stb_image.h>

#include "Assets/AssetPaths.h"
#include "Error.h"

namespace rt
{
ImageData loadImage(const std::string& path)
{
    const std::filesystem::path file = resolveAsset(path, "texture");
    int width = 0, height = 0, channels = 0;
    stbi_uc* texels = stbi_load(file.string().c_str(), &width, &height, &channels, 4);
    if (!texels)
        throw AssetError(fmt::format("texture '{}' cannot be decoded: {}", file.string(), stbi_failure_reason()));
    ImageData image;
    image.path = file.string();
    image.width = width;
    image.height = height;
    image.rgba.resize(std::size_t(width) * height * 4);
    std::memcpy(image.rgba.data(), texels, image.rgba.size());
    stbi_image_free(texels);
    return image;
}
} // namespace rt
