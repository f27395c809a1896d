// glTF materials (glTF 2.0 spec §3.9.2 "Metallic-Roughness Material", Appendix B, and the KHR_materials_*
// extensions named below) mapped onto the scene's materials, first match wins:
//
//   | glTF                                                  | material                                          |
//   |-------------------------------------------------------|---------------------------------------------------|
//   | emissiveFactor x KHR_materials_emissive_strength > 0  | diffuse_light, radiance = their product           |
//   | transmissionFactor x (1 - metallicFactor) > 0.5       | rough_dielectric, alpha = roughnessFactor^2,      |
//   | (KHR_materials_transmission: metals do not transmit)  | ior = KHR_materials_ior's (default 1.5)           |
//   | otherwise                                             | gltf_pbr: base colour, metallic = metallicFactor, |
//   |                                                       | alpha = roughnessFactor^2, the metallic-roughness |
//   |                                                       | texture (g roughness, b metallic; linear), ior    |
//   | no material                                           | lambertian, grey (0.8)                            |
//
// The base colour is baseColorFactor's RGB, times baseColorTexture's texels (on TEXCOORD_0) where it has one:
// the factor is multiplied into a copy of the image (GltfImages' tintedImage). The metallic-roughness texture
// (TEXCOORD_0 too) is an image texture marked linear (TextureData::linear: its texels are data, not sRGB); its
// factors stay the material's (Shading/Scatter.h microfacetBsdfAt multiplies them). KHR_materials_transmission
// weighs the dielectric BRDF only (its §"BTDF"): the transmitted share is transmissionFactor (1 - metallicFactor),
// and one between 0 and 1 is rounded to glass or to opaque with a note. Everything else a material
// says - other textures, alpha, other extensions, texture transforms - goes to the import's notes.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "Scene/SceneBuilder.h"
#include "SceneFile/GltfFile.h"
#include "SceneFile/GltfTexcoords.h"

namespace rt
{
class GltfMaterials
{
public:
    /// Albedo of the material a primitive without one gets (the brief's grey; glTF's own default is white metal).
    static constexpr float kDefaultGrey = 0.8f;

    GltfMaterials(const GltfDocument& doc, SceneBuilder& builder, GltfNotes& notes);

    /// The scene's material for glTF material `index` (-1: none), made on first use. `usedAs` is the referring
    /// value's JSON pointer. Throws SceneError for an index out of range or a value out of the spec's range
    /// (a factor of the wrong length or outside [0, 1], a negative emission, an ior below 1), AssetError for its
    /// base colour or metallic-roughness image (GltfImages).
    std::uint32_t material(int index, const std::string& usedAs);

    /// Whether the scene's material `material` samples an image through the surface's texture coordinates, and
    /// if so how its sampler wraps them.
    std::optional<GltfWrapModes> textured(std::uint32_t material) const;

    /// The emitting materials made so far: how many are single-sided, how many double-sided (§3.9.5).
    int singleSidedEmitters() const { return m_singleSidedEmitters; }
    int doubleSidedEmitters() const { return m_doubleSidedEmitters; }

private:
    std::uint32_t make(int index);
    /// The image and the sampler's wrap modes of texture reference `info` (at `pointer`), or none, noted, where
    /// the import cannot use it (`what` textures on another TEXCOORD_n, no PNG or JPEG source: `fallback`).
    struct Source
    {
        int image;
        GltfWrapModes wrap;
    };
    std::optional<Source> source(const tinygltf::TextureInfo& info, const std::string& pointer,
                                 const std::string& where, const char* what, const char* fallback);
    /// The albedo texture: the factor's colour, or the base colour image times the factor (then `wrap` is set
    /// to its sampler's wrap modes).
    std::uint32_t baseColor(const tinygltf::Material& m, const std::string& pointer, const std::string& where,
                            const vec3& factor, std::optional<GltfWrapModes>& wrap);
    /// The metallic-roughness texture (linear), kNoIndex if none; sets `wrap` if the base colour did not.
    std::uint32_t metallicRoughness(const tinygltf::Material& m, const std::string& pointer, const std::string& where,
                                    std::optional<GltfWrapModes>& wrap);
    /// A new image texture of `image`, its own image of the scene (--export-scene writes one path per texture).
    std::uint32_t imageTexture(ImageData image, bool linear);

    const GltfDocument& m_doc;
    SceneBuilder& m_builder;
    GltfNotes& m_notes;
    std::map<int, std::uint32_t> m_made; // glTF material (-1: none) -> scene material
    std::map<std::pair<int, std::array<float, 3>>, std::uint32_t> m_imageTextures; // (image, factor) -> texture
    std::map<int, std::uint32_t> m_linearTextures; // image -> its metallic-roughness texture
    std::map<std::uint32_t, GltfWrapModes> m_texturedMaterials; // scene material -> its texture's wrapping
    int m_singleSidedEmitters = 0;
    int m_doubleSidedEmitters = 0;
};

/// "material 'Name'" or "material 3" for messages and notes.
std::string gltfMaterialName(const GltfDocument& doc, int index);
} // namespace rt
