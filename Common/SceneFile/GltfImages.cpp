#include "SceneFile/GltfImages.h"

#include <fstream>
#include <iterator>

#include <spdlog/fmt/fmt.h>

#include "Assets/ImageLoader.h"
#include "Assets/AssetPaths.h"
#include "Error.h"
#include "Image/ImageIO.h"

namespace rt
{
namespace
{
int hexDigit(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return -1;
}

ImageData fromFile(const GltfDocument& doc, int index, const std::string& uri)
{
    const std::string pointer = fmt::format("/images/{}/uri", index);
    if (const auto colon = uri.find(':'); colon != std::string::npos && colon > 1 && uri.find('/') > colon)
        throw AssetError(fmt::format("{}: {}: '{}' is not a file (only relative paths and data URIs are read)",
                                     doc.file.string(), pointer, uri));
    const std::filesystem::path path = doc.file.parent_path() / percentDecoded(uri);
    if (!std::filesystem::is_regular_file(path))
        throw AssetError(fmt::format("{}: {}: image file '{}' not found", doc.file.string(), pointer, path.string()));
    if (const std::string outside = outsideSceneFolders(path, doc.file.parent_path()); !outside.empty())
        throw SceneError(fmt::format("{}: {}: '{}': {}", doc.file.string(), pointer, uri, outside));
    std::ifstream in(path, std::ios::binary);
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    try
    {
        return decodeImage(bytes.data(), bytes.size(), path.string());
    }
    catch (const AssetError& e)
    {
        throw AssetError(fmt::format("{}: {}: {}", doc.file.string(), pointer, e.what()));
    }
}
} // namespace

std::string percentDecoded(const std::string& uri)
{
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i)
    {
        if (uri[i] == '%' && i + 2 < uri.size() && hexDigit(uri[i + 1]) >= 0 && hexDigit(uri[i + 2]) >= 0)
        {
            out += static_cast<char>(16 * hexDigit(uri[i + 1]) + hexDigit(uri[i + 2]));
            i += 2;
        }
        else
            out += uri[i];
    }
    return out;
}

ImageData readGltfImage(const GltfDocument& doc, int index)
{
    const tinygltf::Model& m = doc.model;
    if (index < 0 || static_cast<std::size_t>(index) >= m.images.size())
        doc.fail("/images", fmt::format("image {} does not exist (the file has {})", index, m.images.size()));
    const tinygltf::Image& image = m.images[static_cast<std::size_t>(index)];
    const std::string name = fmt::format("{}#/images/{}", doc.file.string(), index);
    const auto decode = [&](const std::uint8_t* bytes, std::size_t size) {
        try
        {
            return decodeImage(bytes, size, name);
        }
        catch (const AssetError& e)
        {
            throw AssetError(fmt::format("{}: /images/{}: {}", doc.file.string(), index, e.what()));
        }
    };
    if (image.bufferView >= 0)
    {
        const std::string pointer = fmt::format("/images/{}/bufferView", index);
        if (static_cast<std::size_t>(image.bufferView) >= m.bufferViews.size())
            doc.fail(pointer, fmt::format("bufferView {} does not exist (the file has {})", image.bufferView,
                                          m.bufferViews.size()));
        const tinygltf::BufferView& view = m.bufferViews[static_cast<std::size_t>(image.bufferView)];
        if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= m.buffers.size())
            doc.fail(fmt::format("/bufferViews/{}/buffer", image.bufferView),
                     fmt::format("buffer {} does not exist (the file has {})", view.buffer, m.buffers.size()));
        const std::vector<unsigned char>& data = m.buffers[static_cast<std::size_t>(view.buffer)].data;
        if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
            doc.fail(fmt::format("/bufferViews/{}", image.bufferView),
                     fmt::format("bytes {} to {} lie beyond buffer {} ({} bytes)", view.byteOffset,
                                 view.byteOffset + view.byteLength, view.buffer, data.size()));
        return decode(data.data() + view.byteOffset, view.byteLength);
    }
    if (!image.image.empty()) // a data URI's bytes, kept encoded by GltfFile
        return decode(image.image.data(), image.image.size());
    if (!image.uri.empty())
        return fromFile(doc, index, image.uri);
    doc.fail(fmt::format("/images/{}", index), "the image has no data (no bufferView, no uri)");
}

ImageData tintedImage(ImageData image, const vec3& factor)
{
    for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4)
        for (int c = 0; c < 3; ++c)
            image.rgba[i + c] = linearToSrgb8(srgb8ToLinear(image.rgba[i + c]) * factor[c]);
    return image;
}
} // namespace rt
