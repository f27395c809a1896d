#include "SceneFile/GltfMaterials.h"

#include <algorithm>
#include <cmath>

#include <spdlog/fmt/fmt.h>

#include "SceneFile/GltfImages.h"

namespace rt
{
namespace
{
constexpr float kMaxRadiance = 1e30f; // as the JSON reader: finite with room for the engines' sums
constexpr double kMinIor = 1.0; // KHR_materials_ior's minimum
constexpr double kMaxIor = 100.0; // the JSON reader's maximum

const char* const kMappedExtensions[] = {"KHR_materials_emissive_strength", "KHR_materials_transmission",
                                         "KHR_materials_ior"};

/// `values` (a factor of `length` numbers, each in [lo, hi]) or `fallback` when the file leaves it out.
std::vector<double> factor(const GltfDocument& doc, const std::string& pointer, const std::vector<double>& values,
                           std::size_t length, double lo, double hi, std::vector<double> fallback)
{
    if (values.empty())
        return fallback;
    if (values.size() != length)
        doc.fail(pointer, fmt::format("expected {} numbers, got {}", length, values.size()));
    for (std::size_t i = 0; i < length; ++i)
        if (!(values[i] >= lo && values[i] <= hi))
            doc.fail(fmt::format("{}/{}", pointer, i), fmt::format("expected a number in [{}, {}], got {}", lo, hi,
                                                                   values[i]));
    return values;
}

double number(const GltfDocument& doc, const std::string& pointer, double value, double lo, double hi)
{
    if (!(value >= lo && value <= hi))
        doc.fail(pointer, fmt::format("expected a number in [{}, {}], got {}", lo, hi, value));
    return value;
}

/// Member `key` of extension object `ext` (a number in [lo, hi]), or `fallback` if it has none.
double extensionNumber(const GltfDocument& doc, const std::string& pointer, const tinygltf::Value& ext,
                       const char* key, double fallback, double lo, double hi)
{
    if (!ext.Has(key))
        return fallback;
    const tinygltf::Value& v = ext.Get(key);
    if (!v.IsNumber())
        doc.fail(pointer + "/" + key, "expected a number");
    return number(doc, pointer + "/" + key, v.GetNumberAsDouble(), lo, hi);
}

const tinygltf::Value* extension(const tinygltf::Material& m, const char* name)
{
    const auto it = m.extensions.find(name);
    return it == m.extensions.end() ? nullptr : &it->second;
}
} // namespace

std::string gltfMaterialName(const GltfDocument& doc, int index)
{
    const std::string& name = doc.model.materials[static_cast<std::size_t>(index)].name;
    return name.empty() ? fmt::format("material {}", index) : fmt::format("material '{}'", name);
}

GltfMaterials::GltfMaterials(const GltfDocument& doc, SceneBuilder& builder, GltfNotes& notes)
    : m_doc(doc), m_builder(builder), m_notes(notes)
{
}

std::uint32_t GltfMaterials::material(int index, const std::string& usedAs)
{
    if (index >= 0 && static_cast<std::size_t>(index) >= m_doc.model.materials.size())
        m_doc.fail(usedAs, fmt::format("material {} does not exist (the file has {})", index,
                                       m_doc.model.materials.size()));
    if (index < 0)
        index = -1;
    if (const auto it = m_made.find(index); it != m_made.end())
        return it->second;
    const std::uint32_t made = index < 0 ? m_builder.lambertian(vec3(kDefaultGrey)) : make(index);
    m_made.emplace(index, made);
    return made;
}

std::optional<GltfWrapModes> GltfMaterials::textured(std::uint32_t material) const
{
    const auto it = m_texturedMaterials.find(material);
    return it == m_texturedMaterials.end() ? std::nullopt : std::optional(it->second);
}

std::uint32_t GltfMaterials::make(int index)
{
    const tinygltf::Material& m = m_doc.model.materials[static_cast<std::size_t>(index)];
    const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
    const std::string pointer = fmt::format("/materials/{}", index);
    const std::string where = gltfMaterialName(m_doc, index);

    for (const auto& [name, value] : m.extensions)
        if (std::find(std::begin(kMappedExtensions), std::end(kMappedExtensions), name) == std::end(kMappedExtensions))
            m_notes.add(name, where);
    if (m.normalTexture.index >= 0)
        m_notes.add("normal textures", where);
    if (m.occlusionTexture.index >= 0)
        m_notes.add("occlusion textures", where);
    if (m.alphaMode != "OPAQUE")
        m_notes.add(fmt::format("alphaMode {} (surfaces opaque)", m.alphaMode), where);

    // Emission first: a glTF emitter also has a base colour, which a diffuse light does not use.
    const std::vector<double> emissive =
        factor(m_doc, pointer + "/emissiveFactor", m.emissiveFactor, 3, 0.0, 1.0, {0.0, 0.0, 0.0});
    double strength = 1.0;
    if (const tinygltf::Value* ext = extension(m, "KHR_materials_emissive_strength"))
        strength = extensionNumber(m_doc, pointer + "/extensions/KHR_materials_emissive_strength", *ext,
                                   "emissiveStrength", 1.0, 0.0, kMaxRadiance);
    const vec3 radiance(static_cast<float>(emissive[0] * strength), static_cast<float>(emissive[1] * strength),
                        static_cast<float>(emissive[2] * strength));
    if (glm::any(glm::greaterThan(radiance, vec3(0.0f))))
    {
        if (m.emissiveTexture.index >= 0)
            m_notes.add("emissive textures (the emissive factor emits uniformly)", where);
        ++(m.doubleSided ? m_doubleSidedEmitters : m_singleSidedEmitters);
        return m_builder.diffuseLight(glm::min(radiance, vec3(kMaxRadiance)));
    }

    double transmission = 0.0;
    if (const tinygltf::Value* ext = extension(m, "KHR_materials_transmission"))
    {
        const std::string p = pointer + "/extensions/KHR_materials_transmission";
        transmission = extensionNumber(m_doc, p, *ext, "transmissionFactor", 0.0, 0.0, 1.0);
        if (ext->Has("transmissionTexture"))
            m_notes.add("transmission textures", where);
    }
    double ior = 1.5;
    if (const tinygltf::Value* ext = extension(m, "KHR_materials_ior"))
        ior = extensionNumber(m_doc, pointer + "/extensions/KHR_materials_ior", *ext, "ior", 1.5, kMinIor, kMaxIor);
    const std::vector<double> base =
        factor(m_doc, pointer + "/pbrMetallicRoughness/baseColorFactor", pbr.baseColorFactor, 4, 0.0, 1.0,
               {1.0, 1.0, 1.0, 1.0});
    const vec3 color(static_cast<float>(base[0]), static_cast<float>(base[1]), static_cast<float>(base[2]));
    const auto metallic = static_cast<float>(
        number(m_doc, pointer + "/pbrMetallicRoughness/metallicFactor", pbr.metallicFactor, 0.0, 1.0));
    const auto roughness = static_cast<float>(
        number(m_doc, pointer + "/pbrMetallicRoughness/roughnessFactor", pbr.roughnessFactor, 0.0, 1.0));
    // KHR_materials_transmission mixes the transmission into the dielectric BRDF alone: a metal does not transmit.
    const double transmitted = transmission * (1.0 - metallic);
    if (transmitted > 0.0 && transmitted < 1.0)
        m_notes.add(fmt::format("partial transmission ({:.2g} of the light: {})", transmitted,
                                transmitted > 0.5 ? "clear glass" : "opaque"),
                    where);
    if (transmitted > 0.5)
    {
        if (color != vec3(1.0f) || pbr.baseColorTexture.index >= 0)
            m_notes.add("tinted transmission (clear glass)", where);
        if (pbr.metallicRoughnessTexture.index >= 0)
            m_notes.add("metallic-roughness textures of transmissive materials (the roughness factor alone)", where);
        return m_builder.roughDielectric(roughness * roughness, static_cast<float>(ior)); // alpha = roughness^2
    }

    std::optional<GltfWrapModes> wrap;
    const std::uint32_t baseColorTexture =
        baseColor(m, pointer + "/pbrMetallicRoughness/baseColorTexture", where, color, wrap);
    const std::uint32_t metallicRoughnessTexture =
        metallicRoughness(m, pointer + "/pbrMetallicRoughness/metallicRoughnessTexture", where, wrap);
    const std::uint32_t made =
        m_builder.gltfPbr(baseColorTexture, metallic, roughness, metallicRoughnessTexture, static_cast<float>(ior));
    if (wrap)
        m_texturedMaterials.emplace(made, *wrap);
    return made;
}

std::optional<GltfMaterials::Source> GltfMaterials::source(const tinygltf::TextureInfo& info,
                                                           const std::string& pointer, const std::string& where,
                                                           const char* what, const char* fallback)
{
    const tinygltf::Model& model = m_doc.model;
    if (static_cast<std::size_t>(info.index) >= model.textures.size())
        m_doc.fail(pointer + "/index",
                   fmt::format("texture {} does not exist (the file has {})", info.index, model.textures.size()));
    for (const auto& [name, value] : info.extensions)
        m_notes.add(name == "KHR_texture_transform" ? "KHR_texture_transform (textures placed untransformed)" : name,
                    where);
    if (info.texCoord != 0)
    {
        m_notes.add(fmt::format("{} textures on TEXCOORD_{} ({})", what, info.texCoord, fallback), where);
        return std::nullopt;
    }
    const tinygltf::Texture& texture = model.textures[static_cast<std::size_t>(info.index)];
    if (texture.source < 0)
    {
        for (const auto& [name, value] : texture.extensions)
            m_notes.add(name, where);
        m_notes.add(fmt::format("textures without a PNG or JPEG source ({})", fallback), where);
        return std::nullopt;
    }
    Source out{texture.source, GltfWrapModes{}}; // no sampler: repeat in both directions (§3.8.4)
    if (texture.sampler >= 0)
    {
        if (static_cast<std::size_t>(texture.sampler) >= model.samplers.size())
            m_doc.fail(fmt::format("/textures/{}/sampler", info.index),
                       fmt::format("sampler {} does not exist (the file has {})", texture.sampler,
                                   model.samplers.size()));
        const tinygltf::Sampler& sampler = model.samplers[static_cast<std::size_t>(texture.sampler)];
        out.wrap = GltfWrapModes{gltfWrap(sampler.wrapS), gltfWrap(sampler.wrapT)};
    }
    return out;
}

std::uint32_t GltfMaterials::baseColor(const tinygltf::Material& m, const std::string& pointer,
                                       const std::string& where, const vec3& factor,
                                       std::optional<GltfWrapModes>& wrap)
{
    const tinygltf::TextureInfo& info = m.pbrMetallicRoughness.baseColorTexture;
    if (info.index < 0)
        return m_builder.solid(factor);
    const std::optional<Source> found = source(info, pointer, where, "base colour", "the factor alone");
    if (!found)
        return m_builder.solid(factor);
    wrap = found->wrap;
    const std::array<float, 3> key{factor.r, factor.g, factor.b};
    if (const auto it = m_imageTextures.find({found->image, key}); it != m_imageTextures.end())
        return it->second;
    ImageData image = readGltfImage(m_doc, found->image);
    if (factor != vec3(1.0f))
    {
        image = tintedImage(std::move(image), factor);
        // No longer the file's texels: a name that is no file (--export-scene writes such images out).
        image.path = fmt::format("{} x baseColorFactor ({}, {}, {})", image.path, factor.r, factor.g, factor.b);
    }
    const std::uint32_t made = imageTexture(std::move(image), false);
    m_imageTextures.emplace(std::make_pair(found->image, key), made);
    return made;
}

std::uint32_t GltfMaterials::metallicRoughness(const tinygltf::Material& m, const std::string& pointer,
                                               const std::string& where, std::optional<GltfWrapModes>& wrap)
{
    const tinygltf::TextureInfo& info = m.pbrMetallicRoughness.metallicRoughnessTexture;
    if (info.index < 0)
        return kNoIndex;
    const std::optional<Source> found = source(info, pointer, where, "metallic-roughness", "the factors alone");
    if (!found)
        return kNoIndex;
    // One set of texture coordinates serves both textures (the engines clamp; GltfTexcoords moves triangles by
    // whole periods of one sampler's wrapping): the base colour's wrapping wins where the two differ.
    if (!wrap)
        wrap = found->wrap;
    else if (wrap->s != found->wrap.s || wrap->t != found->wrap.t)
        m_notes.add("metallic-roughness textures wrapping unlike their base colour (wrapped as the base colour)",
                    where);
    if (const auto it = m_linearTextures.find(found->image); it != m_linearTextures.end())
        return it->second;
    // Linear data, not colour (§3.9.2): the texels are read as they are, never decoded from sRGB, nor tinted.
    const std::uint32_t made = imageTexture(readGltfImage(m_doc, found->image), true);
    m_linearTextures.emplace(found->image, made);
    return made;
}

std::uint32_t GltfMaterials::imageTexture(ImageData image, bool linear)
{
    Scene& scene = m_builder.scene();
    TextureData t{};
    t.type = TextureType::Image;
    t.image = static_cast<std::uint32_t>(scene.images.size());
    t.linear = linear ? 1u : 0u;
    scene.images.push_back(std::move(image));
    scene.textures.push_back(t);
    return static_cast<std::uint32_t>(scene.textures.size() - 1);
}
} // namespace rt
