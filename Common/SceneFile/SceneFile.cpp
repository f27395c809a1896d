#include "SceneFile/SceneFile.h"

#include <algorithm>
#include <cctype>
#include <string>

#include <spdlog/fmt/fmt.h>

#include "Error.h"
#include "Scene/SceneTransform.h"
#include "SceneFile/GltfImport.h"
#include "SceneFile/JsonSceneReader.h"
#include "Scenes/Catalogue.h"

namespace rt
{
namespace
{
std::string lowerExtension(std::string_view path)
{
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}
} // namespace

bool isSceneFilePath(std::string_view idOrPath)
{
    const std::string ext = lowerExtension(idOrPath);
    return ext == ".json" || ext == ".gltf" || ext == ".glb";
}

std::string sceneShortName(std::string_view idOrPath)
{
    return isSceneFilePath(idOrPath) ? std::filesystem::path(idOrPath).stem().string() : std::string(idOrPath);
}

std::string sceneProblem(std::string_view idOrPath)
{
    if (isSceneFilePath(idOrPath))
        return std::filesystem::is_regular_file(std::filesystem::path(idOrPath))
                   ? std::string()
                   : fmt::format("scene file '{}' not found", idOrPath);
    return findScene(std::string(idOrPath)) != nullptr
               ? std::string()
               : fmt::format("unknown scene '{}' (--list-scenes lists them)", idOrPath);
}

Scene loadSceneFile(const std::filesystem::path& file)
{
    if (!std::filesystem::is_regular_file(file))
        throw SceneError(fmt::format("scene file '{}' not found", file.string()));
    const std::string ext = lowerExtension(file.string());
    // .gltf or .glb: GltfFile tells them apart by their first bytes
    Scene scene = ext == ".json" ? readJsonScene(file) : importGltf(file);
    checkFloatReach(scene, file.string());
    return scene;
}
} // namespace rt
