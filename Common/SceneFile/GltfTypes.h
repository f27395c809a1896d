// The types of a glTF file's properties, checked before tinygltf reads it: tinygltf leaves a property of the
// wrong type at its default without a word (an array for "pbrMetallicRoughness" rendered the default material),
// so a file that says something else than what renders is refused, naming the property.
#pragma once

#include <filesystem>
#include <string_view>

namespace rt
{
/// Throws SceneError ("file: /materials/0/pbrMetallicRoughness: expected an object, got an array") at the first
/// property of the glTF 2.0 schema (the parts this importer reads, and the lists' items) whose JSON type is not
/// the schema's; absent properties pass, as do properties it does not know. `json`: the file's JSON (a .glb's
/// first chunk), nested no deeper than kMaxJsonNesting (checkJsonNesting); a syntax error passes here, for
/// tinygltf to report.
void checkGltfTypes(std::string_view json, const std::filesystem::path& file);
} // namespace rt
