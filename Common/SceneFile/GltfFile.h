// A glTF 2.0 file read into tinygltf's model: a .gltf (JSON, its buffers in files beside it or in data URIs) or a
// .glb (the binary container of the glTF 2.0 spec §4, "GLB File Format Specification"), told apart by the
// file's first bytes. Every later check of the import fails through GltfDocument::fail, which names the file
// and the place in it as a JSON pointer (RFC 6901) into the file's JSON, as the JSON scene reader does.
#pragma once

#include <filesystem>
#include <string>

#include "SceneFile/GltfNotes.h"
#include "SceneFile/TinyGltf.h"

namespace rt
{
struct GltfDocument
{
    tinygltf::Model model;
    std::filesystem::path file; // as given: the name messages start with; its folder anchors relative URIs

    /// Throws SceneError "<file>: <pointer>: <what>" (pointer e.g. "/accessors/3/count").
    [[noreturn]] void fail(const std::string& pointer, const std::string& what) const;
};

/// Reads `file` and the buffers it names (relative URIs from the file's folder; data URIs decoded). Images are
/// left encoded (SceneFile/GltfImages.h decodes those a material uses). tinygltf's warnings, and the errors it
/// read past (it leaves a value of the wrong type at its default and carries on), go to `notes`.
/// Logs "reading <file> (N MB)" for a file over 16 MB.
/// Throws AssetError "<file>: buffer file '<path>' not found" for a missing buffer file, SceneError
/// "<file>: <tinygltf's error, on one line>" for anything else tinygltf refuses: not glTF, malformed JSON (with
/// line and column), a GLB with a bad header or chunk, a buffer of the wrong length, a missing required property.
GltfDocument loadGltfFile(const std::filesystem::path& file, GltfNotes& notes);

/// `text` on one line: its lines, trimmed, joined with "; " (tinygltf ends each message with a newline).
std::string gltfOneLine(const std::string& text);
} // namespace rt
