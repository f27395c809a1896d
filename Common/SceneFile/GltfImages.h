// The images of a glTF file (glTF 2.0 spec §3.8.3 "Images") as the engines' textures take them: 8-bit sRGB RGBA
// decoded by the project's stb, from a bufferView (a .glb's embedded PNG or JPEG), a data URI, or a file the URI
// names relative to the glTF file's folder.
#pragma once

#include "Math/Math.h"
#include "Scene/Scene.h"
#include "SceneFile/GltfFile.h"

namespace rt
{
/// Image `index` of `doc`, decoded. Its path (for messages and --export-scene) is the file it came from, or
/// "<gltf file>#/images/N" for an embedded one. Throws SceneError for an index or bufferView out of range or an
/// image with no data, AssetError naming the image (/images/N) for a file that is missing, a URI that is not
/// a file (http:), or bytes stb cannot decode.
ImageData readGltfImage(const GltfDocument& doc, int index);

/// `image` with each texel's colour multiplied by `factor` (linear RGB in [0, 1]): the texels are sRGB-encoded,
/// so each is decoded, multiplied and encoded again (8 bits; alpha kept). The engines' image textures have no
/// factor of their own: glTF's baseColorFactor is applied here, once, at import.
ImageData tintedImage(ImageData image, const vec3& factor);

/// A URI's percent-escapes decoded ("my%20file.png" -> "my file.png"; RFC 3986 §2.1); a malformed escape is kept.
std::string percentDecoded(const std::string& uri);
} // namespace rt
