// Reads this project's JSON scene format (docs/SCENES.md) into a Scene. Every value is checked where it is
// read, so a problem is reported with the file and the JSON pointer of the value (or line and column for a
// syntax error) and what was expected, before anything is rendered.
#pragma once

#include <filesystem>
#include <string>

#include "Scene/Scene.h"

namespace rt
{
/// The format's version this build reads and writes.
inline constexpr int kSceneFormatVersion = 1;

/// Reads and builds the scene in `file`. Relative paths inside it (textures, OBJ meshes) are looked up next
/// to the file first, then in the asset folder (Assets/AssetPaths.h). The scene's id is `file` as given.
/// Throws SceneError "<file>:<line>:<column>: ..." for a syntax error, "<file>: <pointer>: ..." for a
/// value that is missing, of the wrong type, out of range, unknown or inconsistent, and AssetError (with the
/// pointer) for a texture or mesh that is missing or malformed.
Scene readJsonScene(const std::filesystem::path& file);

/// readJsonScene for a file's contents already in memory (`file` names it in errors and anchors its paths).
Scene readJsonSceneText(const std::string& text, const std::filesystem::path& file);
} // namespace rt
