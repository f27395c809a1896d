#include "SceneFile/JsonSceneWriter.h"

#include <charconv>
#include <cstdlib>

#include <spdlog/fmt/fmt.h>

#include "Assets/AssetPaths.h"
#include "Error.h"
#include "IO/AtomicFile.h"
#include "IO/OutputSet.h"
#include "Image/ImageIO.h"
#include "Render/RenderSettings.h"
#include "SceneFile/JsonSceneReader.h"

namespace rt
{
using ojson = nlohmann::ordered_json;

double exactFloat(float f)
{
    char text[32];
    const auto [end, ec] = std::to_chars(text, text + sizeof text - 1, f); // shortest form that reads back as f
    *end = '\0';
    const double d = std::strtod(text, nullptr);
    // Reading the text as double, then rounding to float, can in rare cases round differently from reading
    // it as float; the float's own exact value always reads back.
    return ec == std::errc() && static_cast<float>(d) == f ? d : static_cast<double>(f);
}

namespace
{
ojson number(float f) { return exactFloat(f); }

ojson vector(const vec3& v) { return ojson::array({number(v.x), number(v.y), number(v.z)}); }

/// `paths[i]` is where image i is to be found: its own file, or one exportScene wrote beside the scene file.
ojson textureByType(const TextureData& t, const Scene& scene, const std::vector<std::string>& paths)
{
    switch (t.type)
    {
    case TextureType::Solid: return {{"type", "solid"}, {"color", vector(t.color0)}};
    case TextureType::Checker:
        return {{"type", "checker"}, {"scale", number(t.scale)}, {"even", vector(t.color0)}, {"odd", vector(t.color1)}};
    case TextureType::Image:
    {
        std::filesystem::path path(t.image < paths.size() ? paths[t.image] : scene.images.at(t.image).path);
        const std::filesystem::path relative = path.lexically_proximate(assetRoot());
        if (!relative.empty() && *relative.begin() != "..")
            path = relative; // found through the asset folder wherever the scene file and the checkout are
        ojson j = {{"type", "image"}, {"path", path.generic_string()}};
        if (t.linear != 0)
            j["linear"] = true;
        return j;
    }
    case TextureType::Noise: return {{"type", "noise"}, {"scale", number(t.scale)}};
    case TextureType::Turbulence: return {{"type", "turbulence"}, {"scale", number(t.scale)}};
    case TextureType::Marble: return {{"type", "marble"}, {"scale", number(t.scale)}};
    }
    throw SceneError(fmt::format("texture type {} cannot be written", static_cast<unsigned>(t.type)));
}

ojson texture(const TextureData& t, const Scene& scene, const std::vector<std::string>& paths)
{
    ojson j = textureByType(t, scene, paths);
    if (t.origin != vec3(0.0f))
        j["offset"] = vector(t.origin); // a solid texture's pattern at p + offset
    return j;
}

ojson material(const MaterialData& m)
{
    switch (m.type)
    {
    case MaterialType::Lambertian:
    {
        ojson j = {{"type", "lambertian"}, {"albedo_texture", m.albedoTexture}};
        if (m.emissionTexture != kNoIndex)
            j["radiance_texture"] = m.emissionTexture;
        return j;
    }
    case MaterialType::Metal:
        return {{"type", "metal"}, {"albedo_texture", m.albedoTexture}, {"fuzz", number(m.fuzz)}};
    case MaterialType::Dielectric:
        return {{"type", "dielectric"},
                {"ior", number(m.ior)},
                {"fresnel", m.fresnel == shader::FresnelModel::Exact ? "exact" : "schlick"}};
    case MaterialType::DiffuseLight: return {{"type", "diffuse_light"}, {"radiance_texture", m.emissionTexture}};
    case MaterialType::Isotropic: return {{"type", "isotropic"}, {"albedo_texture", m.albedoTexture}};
    case MaterialType::Conductor:
    {
        ojson j = {{"type", "conductor"}, {"alpha", ojson::array({number(m.alphaX), number(m.alphaY)})}};
        if (m.fresnel == shader::FresnelModel::Schlick)
            j["f0_texture"] = m.albedoTexture;
        else
        {
            j["eta"] = ojson::array({number(m.eta.x), number(m.eta.y), number(m.eta.z)});
            j["k"] = ojson::array({number(m.k.x), number(m.k.y), number(m.k.z)});
        }
        return j;
    }
    case MaterialType::RoughDielectric:
        return {{"type", "rough_dielectric"}, {"alpha", number(m.alphaX)}, {"ior", number(m.ior)}};
    case MaterialType::GltfPbr:
    {
        ojson j = {{"type", "gltf_pbr"},
                   {"base_color_texture", m.albedoTexture},
                   {"metallic", number(m.metallic)},
                   {"alpha", number(m.alphaX)},
                   {"ior", number(m.ior)}};
        if (m.metallicRoughnessTexture != kNoIndex)
            j["metallic_roughness_texture"] = m.metallicRoughnessTexture;
        return j;
    }
    }
    throw SceneError(fmt::format("material type {} cannot be written", static_cast<unsigned>(m.type)));
}

template <typename V>
ojson flat(const std::vector<V>& list)
{
    constexpr int arity = sizeof(V) / sizeof(float);
    ojson out = ojson::array();
    for (const V& v : list)
        for (int k = 0; k < arity; ++k)
            out.push_back(number(v[k]));
    return out;
}

ojson mesh(const MeshData& m)
{
    ojson j = {{"name", m.name}, {"positions", flat(m.positions)}, {"indices", m.indices}};
    if (!m.normals.empty())
        j["normals"] = flat(m.normals);
    if (!m.uvs.empty())
        j["uvs"] = flat(m.uvs);
    if (!m.triangleMaterials.empty())
        j["triangle_materials"] = m.triangleMaterials;
    return j;
}

ojson group(const GroupDesc& g)
{
    ojson shapes = ojson::array();
    for (const SphereDesc& s : g.spheres)
    {
        if (s.moving())
            shapes.push_back({{"type", "moving_sphere"}, {"center0", vector(s.center0)}, {"center1", vector(s.center1)},
                              {"radius", number(s.radius)}, {"material", s.material}});
        else
            shapes.push_back(
                {{"type", "sphere"}, {"center", vector(s.center0)}, {"radius", number(s.radius)}, {"material", s.material}});
    }
    for (const QuadDesc& q : g.quads)
        shapes.push_back({{"type", "quad"}, {"q", vector(q.q)}, {"u", vector(q.u)}, {"v", vector(q.v)}, {"material", q.material}});
    for (const MeshRef& r : g.meshes)
        shapes.push_back({{"type", "mesh"}, {"mesh", r.mesh}, {"material", r.material}});
    for (const MediumDesc& m : g.media)
    {
        ojson j = {{"type", "constant_medium"}};
        if (m.boundary == MediumDesc::Boundary::Sphere)
        {
            j["boundary"] = "sphere";
            j["center"] = vector(m.center);
            j["radius"] = number(m.radius);
        }
        else
        {
            j["boundary"] = "box";
            j["min"] = vector(m.boxMin);
            j["max"] = vector(m.boxMax);
        }
        j["density"] = number(m.density);
        j["material"] = m.phaseMaterial;
        shapes.push_back(std::move(j));
    }
    return {{"name", g.name}, {"shapes", std::move(shapes)}};
}

ojson instance(const InstanceDesc& i)
{
    ojson j = {{"group", i.group}};
    if (!i.worldFromObject.isIdentity())
    {
        ojson rows = ojson::array();
        for (int r = 0; r < 3; ++r)
        {
            ojson row = ojson::array();
            for (int c = 0; c < 4; ++c)
                row.push_back(number(i.worldFromObject.m[c][r]));
            rows.push_back(std::move(row));
        }
        j["transform"] = ojson::array({{{"matrix", std::move(rows)}}});
    }
    return j;
}

ojson camera(const CameraDesc& c)
{
    return {{"look_from", vector(c.lookFrom)},
            {"look_at", vector(c.lookAt)},
            {"up", vector(c.vup)},
            {"vfov", number(c.vfovDegrees)},
            {"defocus_angle", number(c.defocusAngleDegrees)},
            {"focus_distance", number(c.focusDistance)},
            {"shutter", ojson::array({number(c.shutterOpen), number(c.shutterClose)})}};
}

ojson render(const SceneDefaults& d)
{
    return {{"spp", d.spp},
            {"depth", d.depth},
            {"width", d.width},
            {"aspect", number(d.aspect)},
            {"unidirectional_light", d.unidirectionalLight},
            {"estimator", toString(d.estimator)},
            {"sampling", toString(d.sampling)}};
}

ojson background(const Background& b)
{
    if (b.type == BackgroundType::Constant && b.color0 == b.color1)
        return {{"type", "constant"}, {"color", vector(b.color0)}};
    if (b.type == BackgroundType::Constant)
        throw SceneError("a constant background with two colours cannot be written");
    return {{"type", "gradient"}, {"bottom", vector(b.color0)}, {"top", vector(b.color1)}};
}

/// One line per entry a reader looks for: the document and its lists spread over lines, each texture,
/// material, mesh, instance and shape on one line of its own (a mesh's arrays would be a line per number).
void layOut(const ojson& v, int depth, bool expandChildren, std::string& out)
{
    const bool expand = depth <= 1 || expandChildren;
    if (!expand || !v.is_structured() || v.empty())
    {
        out += v.dump();
        return;
    }
    const std::string indent(static_cast<std::size_t>(depth + 1), ' ');
    out += v.is_object() ? "{\n" : "[\n";
    std::size_t i = 0;
    for (auto it = v.begin(); it != v.end(); ++it, ++i)
    {
        out += indent;
        if (v.is_object())
            out += ojson(it.key()).dump() + ": ";
        // A group (depth 2 under "groups") spreads its shapes one per line.
        const bool group = depth == 1 && it->is_object() && it->contains("shapes");
        layOut(*it, depth + 1, group || (expandChildren && v.is_object() && it.key() == "shapes"), out);
        out += i + 1 < v.size() ? ",\n" : "\n";
    }
    out += std::string(static_cast<std::size_t>(depth), ' ') + (v.is_object() ? "}" : "]");
}
} // namespace

ojson sceneToJson(const Scene& scene, const std::vector<std::string>& imagePaths)
{
    ojson doc = {{"format", "ray-tracing-scene"}, {"version", kSceneFormatVersion}};
    doc["description"] = fmt::format("scene '{}', written by --export-scene", scene.id);
    if (scene.origin != dvec3(0.0))
        doc["origin"] = ojson::array({scene.origin.x, scene.origin.y, scene.origin.z});
    doc["camera"] = camera(scene.camera);
    doc["render"] = render(scene.defaults);
    doc["background"] = background(scene.background);
    doc["textures"] = ojson::array();
    for (const TextureData& t : scene.textures)
        doc["textures"].push_back(texture(t, scene, imagePaths));
    doc["materials"] = ojson::array();
    for (const MaterialData& m : scene.materials)
        doc["materials"].push_back(material(m));
    doc["meshes"] = ojson::array();
    for (const MeshData& m : scene.meshes)
        doc["meshes"].push_back(mesh(m));
    doc["groups"] = ojson::array();
    for (const GroupDesc& g : scene.groups)
        doc["groups"].push_back(group(g));
    doc["instances"] = ojson::array();
    for (const InstanceDesc& i : scene.instances)
        doc["instances"].push_back(instance(i));
    ojson targets = ojson::array();
    for (std::size_t i = 0; i < scene.lights.size(); ++i)
    {
        if (scene.lightSources.at(i).kind != LightSource::Kind::Target)
            continue; // the reader derives the emitters again from the primitives
        const LightData& l = scene.lights[i];
        if (l.shape != shader::LightShape::Sphere)
            throw SceneError(fmt::format("light {} is a sampling target that is not a sphere: cannot be written", i));
        targets.push_back({{"type", "sphere"}, {"center", vector(l.p0)}, {"radius", number(l.radius)}});
    }
    if (!targets.empty())
        doc["light_targets"] = std::move(targets);
    return doc;
}

void exportScene(const Scene& scene, const std::filesystem::path& file)
{
    // An image that is no file of its own (a glTF file's embedded image, or one its base colour factor tinted),
    // or a file the exported scene may not read (outside its folder and the asset folder: AssetPaths.h), is
    // written beside the scene file as a PNG of the texels as held (8-bit sRGB RGBA), which reads back texel for
    // texel; the document names it relative to itself, where the reader looks first.
    // The document and its images are one set, written all or none (a full disk after the first image left it).
    std::vector<std::string> paths;
    OutputSet outputs;
    for (std::size_t i = 0; i < scene.images.size(); ++i)
    {
        const ImageData& image = scene.images[i];
        if (std::filesystem::is_regular_file(image.path) && outsideSceneFolders(image.path, file.parent_path()).empty())
        {
            paths.push_back(image.path);
            continue;
        }
        paths.push_back(fmt::format("{}.image{}.png", file.stem().string(), i));
        outputs.add(file.parent_path() / paths.back(), [&image](const std::filesystem::path& tmp) {
            writePng8(tmp, image.width, image.height, image.rgba);
        });
    }
    std::string text;
    layOut(sceneToJson(scene, paths), 0, false, text);
    text += "\n";
    outputs.add(file, [&text](const std::filesystem::path& tmp) { writeFileAtomically(tmp, text); });
    outputs.commit();
}
} // namespace rt
