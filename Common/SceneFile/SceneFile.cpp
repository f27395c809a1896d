#include "SceneFile/SceneFile.h"

#include <string>

#include <spdlog/fmt/fmt.h>

#include "Error.h"
#include "IO/FileExtension.h"
#include "SceneFile/GltfImport.h"
#include "SceneFile/JsonSceneReader.h"
#include "Scenes/Catalogue.h"

namespace rt
{
bool isSceneFilePath(std::string_view idOrPath)
{
    const std::string ext = lowercaseExtension(std::filesystem::path(idOrPath));
    return ext == ".json" || ext == ".gltf" || ext == ".glb";
}

std::string sceneShortName(std::string_view idOrPath)
{
    return isSceneFilePath(idOrPath) ? std::filesystem::path(idOrPath).stem().string() : std::string(idOrPath);
}

namespace
{
/// Why `file` cannot be read as a scene file, or "" when it is a regular file.
std::string sceneFileProblem(const std::filesystem::path& file)
{
    std::error_code ec;
    if (std::filesystem::is_regular_file(file, ec))
        return {};
    return std::filesystem::is_directory(file, ec) ? fmt::format("scene file '{}' is a folder, not a file", file.string())
           : std::filesystem::exists(file, ec)     ? fmt::format("scene file '{}' is not a regular file", file.string())
                                                   : fmt::format("scene file '{}' not found", file.string());
}
} // namespace

std::string sceneProblem(std::string_view idOrPath)
{
    if (isSceneFilePath(idOrPath))
        return sceneFileProblem(std::filesystem::path(idOrPath));
    return findScene(std::string(idOrPath)) != nullptr
               ? std::string()
               : fmt::format("unknown scene '{}' (--list-scenes lists them)", idOrPath);
}

Scene loadSceneFile(const std::filesystem::path& file)
{
    if (const std::string problem = sceneFileProblem(file); !problem.empty())
        throw SceneError(problem);
    const std::string ext = lowercaseExtension(file);
    return ext == ".json" ? readJsonScene(file) : importGltf(file); // GltfFile tells .gltf from .glb by their bytes
}
} // namespace rt
