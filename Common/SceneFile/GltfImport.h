// glTF 2.0 scenes (.gltf, .glb) imported into the scene description, wherever a scene id or a JSON scene file
// is taken (SceneFile.h). What is read, how materials map and which camera is used: docs/SCENES.md, "glTF".
//
//   GltfFile       tinygltf's load, its errors on one line          GltfNodes      the node hierarchy, transforms
//   GltfAccessors  typed, bounds-checked accessor reads             GltfMeshes     primitives -> world-space meshes
//   GltfMaterials  PBR materials -> the books' materials            GltfImages     images -> 8-bit sRGB textures
//   GltfCamera     the file's first perspective camera, or framing  GltfNotes      what could not be mapped
#pragma once

#include <filesystem>
#include <string>

#include "Scene/Scene.h"

namespace rt
{
struct GltfImport
{
    Scene scene;
    /// What the import could not map, each feature once with where it was met ("normal textures (material
    /// 'Floor'), LINES primitives (skipped) (mesh 3)"); empty when everything was.
    std::string unmapped;
    /// Nothing in the file emits: the scene is lit by the books' gradient sky (white at the horizon and below,
    /// blue overhead) so that it is visible at all.
    bool skyAdded = false;

    /// The one warning line's text (without "warning: "), or "" when there is nothing to say:
    /// "<file>: not mapped: <unmapped>; nothing in the file emits: lit by a gradient sky".
    std::string warning() const;
};

/// Reads `file` and builds its scene: every triangle primitive of the default scene's nodes, in world space
/// (glTF's units and axes: +Y up, one unit a metre), with the materials, images and camera GltfMaterials and
/// GltfCamera describe; render defaults as the JSON format's (600 wide, 100 spp, depth 50, NEE + MIS), the
/// camera's aspect ratio if it gives one; emitters emit from their front side only unless a double-sided
/// emissive material is used (the scene's setting is one for all emitters). The scene's id is `file` as given.
/// Logs "reading <file> (N MB)" for a file over 16 MB and "<file>: N triangles ... read in S s" when that took
/// over half a second; logs nothing else (the caller reports the warning).
/// Throws SceneError "<file>: <JSON pointer>: <what>" (or tinygltf's message) for a malformed file, an index or
/// accessor out of range, a value out of the spec's range, a scene with no triangles; AssetError for a buffer
/// or image file that is missing or an image that cannot be decoded.
GltfImport readGltf(const std::filesystem::path& file);

/// readGltf, with its warning (if any) logged as one `warning:` line. Throws as readGltf.
Scene importGltf(const std::filesystem::path& file);
} // namespace rt
