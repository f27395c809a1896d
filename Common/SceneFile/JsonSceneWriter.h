// Writes a Scene in the JSON scene format (docs/SCENES.md) so that readJsonScene gives back the same scene
// bit for bit: every float is written with the fewest digits that read back to the same float, textures,
// materials, meshes, groups and instances keep their order (the light list, and so every random choice of a
// light, follows it), references are indices, meshes are written inline and transforms as matrices.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "Scene/Scene.h"

namespace rt
{
/// The document for `scene`. Image paths (`imagePaths[i]` for image i where given, else the image's own) under
/// the asset folder are written relative to it, others as they are. Throws SceneError for what the format
/// cannot express (a light that is neither an emitter of the scene nor a sphere target).
nlohmann::ordered_json sceneToJson(const Scene& scene, const std::vector<std::string>& imagePaths = {});

/// Writes sceneToJson(scene) to `file` atomically (IO/AtomicFile.h), and beside it, as `<file's stem>.imageN.png`,
/// every image that is not a file of its own (a glTF import's embedded or tinted images). Throws OutputError if
/// it cannot.
void exportScene(const Scene& scene, const std::filesystem::path& file);

/// The double whose shortest decimal form reads back, through double, as exactly `f` (docs/SCENES.md:
/// "0.73" rather than "0.7300000190734863").
double exactFloat(float f);
} // namespace rt
