// Scenes from files, beside the built-in catalogue: wherever a scene id is taken, a path ending in .json
// (this project's format, docs/SCENES.md) or .gltf/.glb (glTF 2.0) names a file instead.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "Scene/Scene.h"

namespace rt
{
/// True if `idOrPath` names a scene file by its extension (case-insensitive), whether or not it exists.
bool isSceneFilePath(std::string_view idOrPath);

/// Why `idOrPath` names no scene, or empty when it names one: "scene file 'F' not found" for a scene file's path
/// that is no file, "unknown scene 'ID' (--list-scenes lists them)" for an id the catalogue lacks. What both windows
/// and --actions check before they take a scene.
std::string sceneProblem(std::string_view idOrPath);

/// A name for output files and window titles: a catalogue id as it is, a scene file's stem
/// ("scenes/lamp.json" gives "lamp").
std::string sceneShortName(std::string_view idOrPath);

/// Reads the scene in `file` by its extension: .json (JsonSceneReader.h), .gltf or .glb (GltfImport.h: what it
/// could not map is logged as one warning line). Throws SceneError (missing, malformed or inconsistent file,
/// with its location), AssetError (a texture, mesh, buffer or image file it names).
Scene loadSceneFile(const std::filesystem::path& file);
} // namespace rt
