#include "SceneFile/GltfImport.h"

#include <algorithm>
#include <chrono>
#include <string_view>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "Error.h"
#include "Scene/SceneBuilder.h"
#include "SceneFile/GltfCamera.h"
#include "SceneFile/GltfFile.h"
#include "SceneFile/GltfMaterials.h"
#include "SceneFile/GltfMeshes.h"
#include "SceneFile/GltfNodes.h"

namespace rt
{
namespace
{
/// Extensions the import reads (materials, GltfMaterials; KHR_mesh_quantization's integer attributes, the
/// accessor reader); any other the file uses is noted.
constexpr std::string_view kReadExtensions[] = {"KHR_materials_emissive_strength", "KHR_materials_transmission",
                                                "KHR_materials_ior", "KHR_mesh_quantization"};

/// glTF 2.0 §3.12: a file that requires an extension must not be loaded by an importer that does not read it.
void refuseUnreadRequired(const GltfDocument& doc)
{
    const std::vector<std::string>& required = doc.model.extensionsRequired;
    for (std::size_t i = 0; i < required.size(); ++i)
        if (std::find(std::begin(kReadExtensions), std::end(kReadExtensions), required[i]) == std::end(kReadExtensions))
            doc.fail(fmt::format("/extensionsRequired/{}", i),
                     fmt::format("the file requires {}, which this importer does not read (glTF 2.0 section 3.12: "
                                 "such a file must not be loaded)",
                                 required[i]));
}

void noteFileWide(const tinygltf::Model& m, GltfNotes& notes)
{
    if (!m.animations.empty())
        notes.add("animations (the scene at rest)");
    if (!m.skins.empty())
        notes.add("skins (meshes in their bind pose)");
    for (const std::string& name : m.extensionsUsed)
        if (std::find(std::begin(kReadExtensions), std::end(kReadExtensions), name) == std::end(kReadExtensions) &&
            !notes.mentions(name))
            notes.add(name);
}
} // namespace

std::string GltfImport::warning() const
{
    std::string out;
    if (!unmapped.empty())
        out = fmt::format("not mapped: {}", unmapped);
    if (skyAdded)
        out += fmt::format("{}nothing in the file emits: lit by a gradient sky", out.empty() ? "" : "; ");
    return out.empty() ? out : fmt::format("{}: {}", scene.id, out);
}

GltfImport readGltf(const std::filesystem::path& file)
{
    const auto start = std::chrono::steady_clock::now();
    GltfNotes notes;
    const GltfDocument doc = loadGltfFile(file, notes);
    refuseUnreadRequired(doc);
    const std::vector<GltfPlacedNode> nodes = gltfSceneNodes(doc);

    SceneBuilder builder(file.string());
    GltfMaterials materials(doc, builder, notes);
    const GltfMeshSummary meshes = addGltfMeshes(doc, nodes, materials, builder, notes);
    if (meshes.triangles == 0)
        throw SceneError(fmt::format("{}: the scene has no triangles to render ({} nodes, {} meshes in the file{}{})",
                                     file.string(), nodes.size(), doc.model.meshes.size(),
                                     notes.empty() ? "" : "; not mapped: ", notes.list()));

    Scene& scene = builder.scene();
    if (const std::optional<GltfCamera> camera = gltfCamera(doc, nodes, notes))
    {
        scene.camera = camera->camera;
        if (camera->aspect)
            scene.defaults.aspect = *camera->aspect;
    }
    else
        scene.camera = gltfFramingCamera(meshes.boundsMin, meshes.boundsMax);
    scene.defaults.estimator = Estimator::NeeMis;
    scene.defaults.sampling = PixelSampling::Sobol;
    scene.defaults.unidirectionalLight = materials.doubleSidedEmitters() == 0;
    if (materials.doubleSidedEmitters() > 0 && materials.singleSidedEmitters() > 0)
        notes.add("single-sided emitters beside double-sided ones (all emit from both sides)");
    noteFileWide(doc.model, notes);

    GltfImport out;
    out.scene = builder.finish(); // its SceneError names the scene, whose id is the file
    if (out.scene.emitterCount() == 0)
    {
        // The books' sky (RTIOW §4.2, Scenes/SharedPieces.cpp's setGradientSky): white below, blue above.
        out.scene.background = {BackgroundType::Gradient, vec3(1.0f), vec3(0.5f, 0.7f, 1.0f)};
        out.skyAdded = true;
    }
    out.unmapped = notes.list();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (seconds > 0.5)
        spdlog::info("{}: {} triangles in {} primitives read in {:.1f} s", file.string(), meshes.triangles,
                     meshes.primitives, seconds);
    return out;
}

Scene importGltf(const std::filesystem::path& file)
{
    GltfImport imported = readGltf(file);
    if (const std::string warning = imported.warning(); !warning.empty())
        spdlog::warn("{}", warning);
    return std::move(imported.scene);
}
} // namespace rt
