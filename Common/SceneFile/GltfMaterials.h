// glTF materials (glTF 2.0 spec §3.9.2 "Metallic-Roughness Material" and the KHR_materials_* extensions named
// below) mapped onto the books' materials, first match wins:
//
//   | glTF                                                         | material                                   |
//   |--------------------------------------------------------------|--------------------------------------------|
//   | emissiveFactor x KHR_materials_emissive_strength > 0         | diffuse_light, radiance = their product    |
//   | KHR_materials_transmission transmissionFactor > 0.5          | dielectric, ior = KHR_materials_ior (1.5)  |
//   | metallicFactor >= 0.5                                        | metal, albedo = base colour, fuzz = roughness |
//   | otherwise                                                    | lambertian, albedo = base colour           |
//   | no material                                                  | lambertian, grey (0.8)                     |
//
// The base colour is baseColorFactor's RGB, times baseColorTexture's texels (on TEXCOORD_0) where it has one:
// the factor is multiplied into a copy of the image (GltfImages' tintedImage). Everything else a material
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
    /// base colour image (GltfImages).
    std::uint32_t material(int index, const std::string& usedAs);

    /// Whether the scene's material `material` samples an image through the surface's texture coordinates, and
    /// if so how its sampler wraps them.
    std::optional<GltfWrapModes> textured(std::uint32_t material) const;

    /// The emitting materials made so far: how many are single-sided, how many double-sided (§3.9.5).
    int singleSidedEmitters() const { return m_singleSidedEmitters; }
    int doubleSidedEmitters() const { return m_doubleSidedEmitters; }

private:
    std::uint32_t make(int index);
    /// The albedo texture: the factor's colour, or the base colour image times the factor (then `wrap` is set
    /// to its sampler's wrap modes).
    std::uint32_t baseColor(const tinygltf::Material& m, const std::string& pointer, const std::string& where,
                            const vec3& factor, std::optional<GltfWrapModes>& wrap);

    const GltfDocument& m_doc;
    SceneBuilder& m_builder;
    GltfNotes& m_notes;
    std::map<int, std::uint32_t> m_made; // glTF material (-1: none) -> scene material
    std::map<std::pair<int, std::array<float, 3>>, std::uint32_t> m_imageTextures; // (image, factor) -> texture
    std::map<std::uint32_t, GltfWrapModes> m_texturedMaterials; // scene material -> its texture's wrapping
    int m_singleSidedEmitters = 0;
    int m_doubleSidedEmitters = 0;
};

/// "material 'Name'" or "material 3" for messages and notes.
std::string gltfMaterialName(const GltfDocument& doc, int index);
} // namespace rt
