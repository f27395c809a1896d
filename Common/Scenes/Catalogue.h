// The scene registry: every scene of shared/spec/scenes.md by id, each built from one description that
// both engines render. Scenes with a size parameter (white-spheres) or a mesh (mesh-in-one-weekend,
// cornell-box-and-mesh) take it from SceneOptions.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "Scene/Scene.h"
#include "Scene/SceneTransform.h"

namespace rt
{
struct SceneOptions
{
    int count = -1; // number of objects for scenes that scale (white-spheres); < 0 = the scene's default
    std::string meshPath = "meshes/bunny.obj"; // OBJ for the mesh scenes (asset-relative or a real path)
    SceneTransform transform; // the stress knobs --translate-scene, --scale-scene: applied after building
    std::optional<shader::FresnelModel> fresnel; // --fresnel: every dielectric's model; empty: the scene's own
    float roughnessScale = 1.0f; // --roughness-scale: every microfacet material's GGX alpha times this (at most 1)

    bool operator==(const SceneOptions&) const = default;
};

/// Which SceneOptions a scene reads (bit flags); it ignores the others, and the command line says so.
enum SceneTakes : unsigned
{
    kTakesNothing = 0u,
    kTakesCount = 1u, // SceneOptions::count
    kTakesMesh = 2u, // SceneOptions::meshPath
};

struct SceneInfo
{
    std::string id;
    std::string title;
    std::string source; // book chapter or thesis section the scene comes from
    Scene (*build)(const SceneOptions&);
    unsigned takes = kTakesNothing; // SceneTakes
};

const std::vector<SceneInfo>& sceneCatalogue();

/// nullptr if unknown.
const SceneInfo* findScene(const std::string& id);

/// The names of SceneOptions::fresnel's values, as --fresnel, the windows' actions and --stats write them:
/// "scene" (empty: every dielectric keeps its own model), "schlick", "exact".
const char* fresnelOptionName(const std::optional<shader::FresnelModel>& fresnel);

/// Reads a name fresnelOptionName gives into `fresnel`; false (and `fresnel` untouched) for any other text.
bool parseFresnelOption(std::string_view text, std::optional<shader::FresnelModel>& fresnel);

/// The range of SceneOptions::roughnessScale (--roughness-scale, the windows' slider).
inline constexpr float kMinRoughnessScale = 0.01f;
inline constexpr float kMaxRoughnessScale = 100.0f;

/// Builds scene `id` (a catalogue id, or a scene file: SceneFile/SceneFile.h), placed by options.transform
/// (placeScene: the scale in its coordinates, the translation in Scene::origin), with options.fresnel's model on
/// every dielectric if given and every microfacet material's alpha (conductor, rough dielectric, glTF
/// metallic-roughness: both tangents, and through it a roughness texture's) times options.roughnessScale, at
/// most 1; in the scene's own coordinates, as --export-scene writes it. Throws SceneError naming the id and
/// listing the known ones if unknown, AssetError if a texture or mesh it needs is missing, UsageError if the
/// transform is refused.
Scene placedScene(const std::string& id, const SceneOptions& options = {});

/// placedScene's scene in render space (Scene/RenderSpace.h: the camera at the origin), what both engines
/// render. Throws as placedScene, and SceneError when float32 cannot hold the scene in render space
/// (checkFloatReach: far from its camera for its size, or too small or large).
Scene makeScene(const std::string& id, const SceneOptions& options = {});

/// The white furnace: the camera inside a closed sphere of Lambertian albedo `albedo` that emits `radiance`
/// everywhere; every pixel converges to radiance / (1 - albedo) (research notes §4.5).
Scene makeFurnace(float albedo, float radiance);
} // namespace rt
