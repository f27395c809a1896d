#include "SceneFile/JsonSceneReader.h"

#include <chrono>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "Assets/AssetPaths.h"
#include "Assets/ImageLoader.h"
#include "Assets/ObjLoader.h"
#include "Render/RenderSettings.h"
#include "Error.h"
#include "Scene/SceneBuilder.h"
#include "SceneFile/JsonMeshes.h"
#include "SceneFile/JsonTransform.h"

namespace rt
{
namespace
{
constexpr float kMaxRadiance = 1e30f; // finite with room for the engines' sums
constexpr float kMinIor = 1e-3f;
constexpr float kMaxIor = 100.0f;
constexpr float kMinConductorEta = 1e-3f; // silver's eta is 0.05-0.16 in the visible range

/// Runs a loader; an AssetError it throws gets the pointer of the value that named the file.
template <typename F>
auto located(const JsonNode& n, F&& load)
{
    try
    {
        return load();
    }
    catch (const AssetError& e)
    {
        throw AssetError(fmt::format("{}: {}: {}", n.file(), n.pointer(), e.what()));
    }
}

/// Names to indices for one kind of entry (textures, materials, meshes, groups); a reference is a name or
/// an index, which counts from 0 in the file's list (docs/SCENES.md), whatever index the scene gave the entry
/// (a group's is shifted by the "world" group that top-level shapes make). A name given twice is refused only
/// where it is used (an exported catalogue scene has several groups named after one mesh, and refers to them by
/// index).
class NameTable
{
public:
    explicit NameTable(const char* what) : m_what(what) {}

    /// Records the file's next entry, `index` in the scene.
    void add(const JsonNode& entry, std::uint32_t index)
    {
        m_order.push_back(index);
        if (!entry.has("name"))
            return;
        const auto [it, added] = m_indices.emplace(entry["name"].string(), index);
        if (!added)
            it->second = kAmbiguous;
    }

    /// The scene's index of the entry `ref` names, among those added so far.
    std::uint32_t resolve(const JsonNode& ref) const
    {
        if (ref.value().is_string())
        {
            const auto it = m_indices.find(ref.string());
            if (it == m_indices.end())
                ref.fail(fmt::format("no {} is named '{}'", m_what, ref.string()));
            if (it->second == kAmbiguous)
                ref.fail(fmt::format("more than one {} is named '{}': refer to it by its index", m_what, ref.string()));
            return it->second;
        }
        if (m_order.empty())
            ref.fail(fmt::format("the scene defines no {} to refer to", m_what));
        return m_order[static_cast<std::size_t>(ref.integer(0, static_cast<std::int64_t>(m_order.size()) - 1))];
    }

private:
    static constexpr std::uint32_t kAmbiguous = kNoIndex;
    const char* m_what;
    std::vector<std::uint32_t> m_order; // the scene's index of each entry, in the file's order
    std::unordered_map<std::string, std::uint32_t> m_indices;
};

class Reader
{
public:
    Reader(const JsonNode& root, const std::filesystem::path& file)
        : m_root(root), m_folder(file.parent_path()), m_builder(file.string())
    {
    }

    Scene read()
    {
        m_root.allowOnly({"format", "version", "description", "origin", "camera", "render", "background",
                          "textures", "materials", "meshes", "shapes", "groups", "instances", "light_targets"});
        if (m_root.has("format") && m_root["format"].string() != "ray-tracing-scene")
            m_root["format"].fail("expected \"ray-tracing-scene\"");
        if (m_root.has("version"))
            m_root["version"].integer(1, kSceneFormatVersion);
        if (m_root.has("description"))
            m_root["description"].string();
        if (m_root.has("camera"))
            readCamera(m_root["camera"]);
        if (m_root.has("render"))
            readRender(m_root["render"]);
        if (m_root.has("background"))
            readBackground(m_root["background"]);
        forEach("textures", [this](const JsonNode& t) { readTexture(t); });
        forEach("materials", [this](const JsonNode& m) { readMaterial(m); });
        forEach("meshes", [this](const JsonNode& m) { readMesh(m); });
        if (m_root.has("shapes"))
            readShapes(m_root["shapes"], m_builder.world());
        forEach("groups", [this](const JsonNode& g) { readGroup(g); });
        forEach("instances", [this](const JsonNode& i) { readInstance(i); });
        forEach("light_targets", [this](const JsonNode& t) { readLightTarget(t); });
        if (m_root.has("origin"))
            scene().origin = m_root["origin"].dvector3();
        if (m_builder.scene().primitiveCount() == 0)
            m_root.fail("the scene has nothing to render: give \"shapes\", or \"groups\" and \"instances\"");
        try
        {
            return m_builder.finish();
        }
        catch (const SceneError& e)
        {
            m_root.fail(e.what());
        }
    }

private:
    Scene& scene() { return m_builder.scene(); }

    template <typename F>
    void forEach(const char* key, F&& f)
    {
        if (!m_root.has(key))
            return;
        const JsonNode list = m_root[key];
        for (std::size_t i = 0; i < list.size(); ++i)
            f(list[i]);
    }

    std::filesystem::path resolvePath(const JsonNode& node, const char* what) const
    {
        const std::filesystem::path path(node.string());
        std::vector<std::filesystem::path> tried;
        if (path.is_absolute())
            tried.push_back(path);
        else
        {
            tried.push_back(m_folder / path);
            tried.push_back(assetRoot() / path);
        }
        for (const auto& p : tried)
            if (std::filesystem::is_regular_file(p))
            {
                if (const std::string outside = outsideSceneFolders(p, m_folder); !outside.empty())
                    node.fail(fmt::format("{} '{}': {}", what, path.string(), outside));
                return p;
            }
        std::string places;
        for (const auto& p : tried)
        {
            std::error_code ec;
            if (std::filesystem::exists(p, ec))
                node.fail(fmt::format("{} '{}': '{}' is {}", what, path.string(), p.string(),
                                      std::filesystem::is_directory(p, ec) ? "a folder, not a file"
                                                                           : "not a regular file"));
            places += fmt::format("{}{}", places.empty() ? "" : ", ", p.string());
        }
        node.fail(fmt::format("{} '{}' not found (looked in: {})", what, path.string(), places));
    }

    void readCamera(const JsonNode& c)
    {
        c.allowOnly({"look_from", "look_at", "up", "vfov", "defocus_angle", "aperture", "focus_distance", "shutter"});
        CameraDesc& cam = scene().camera;
        cam.lookFrom = c["look_from"].vector3();
        cam.lookAt = c["look_at"].vector3();
        if (c.has("up"))
            cam.vup = c["up"].vector3();
        const vec3 forward = cam.lookAt - cam.lookFrom;
        if (glm::length(forward) == 0.0f)
            c["look_at"].fail("the camera looks at its own position");
        if (glm::length(glm::cross(forward, cam.vup)) == 0.0f)
            c.fail("'up' is zero or parallel to the viewing direction");
        if (c.has("vfov"))
            cam.vfovDegrees = c["vfov"].number(1e-3f, 179.0f);
        if (c.has("focus_distance"))
        {
            cam.focusDistance = c["focus_distance"].number(0.0f);
            if (cam.focusDistance == 0.0f)
                c["focus_distance"].fail("expected a distance > 0");
        }
        if (c.has("defocus_angle") && c.has("aperture"))
            c.fail("give 'defocus_angle' or 'aperture', not both");
        if (c.has("defocus_angle"))
            cam.defocusAngleDegrees = c["defocus_angle"].number(0.0f, 179.0f);
        if (c.has("aperture"))
            cam.defocusAngleDegrees =
                CameraDesc::defocusAngleFromAperture(c["aperture"].number(0.0f), cam.focusDistance);
        if (c.has("shutter"))
        {
            const JsonNode s = c["shutter"];
            if (s.size() != 2)
                s.fail("expected [open, close]");
            cam.shutterOpen = s[std::size_t{0}].number();
            cam.shutterClose = s[1].number();
            if (cam.shutterClose < cam.shutterOpen)
                s.fail("the shutter closes before it opens");
        }
    }

    void readRender(const JsonNode& r)
    {
        r.allowOnly({"spp", "depth", "width", "aspect", "unidirectional_light", "estimator", "sampling"});
        SceneDefaults& d = scene().defaults;
        if (r.has("spp"))
            d.spp = static_cast<int>(r["spp"].integer(1, kMaxSpp));
        if (r.has("depth"))
            d.depth = static_cast<int>(r["depth"].integer(1, 100000));
        if (r.has("width"))
            d.width = static_cast<int>(r["width"].integer(1, 1 << 16));
        if (r.has("aspect"))
        {
            d.aspect = r["aspect"].number(1e-4f, 1e4f);
        }
        if (r.has("unidirectional_light"))
            d.unidirectionalLight = r["unidirectional_light"].boolean();
        if (r.has("estimator"))
            d.estimator = static_cast<Estimator>(r["estimator"].choice({"bsdf", "mixture", "nee", "nee-mis"}));
        if (r.has("sampling"))
            d.sampling = static_cast<PixelSampling>(r["sampling"].choice({"random", "stratified", "accumulate", "sobol"}));
    }

    void readBackground(const JsonNode& b)
    {
        Background& bg = scene().background;
        if (b["type"].choice({"constant", "gradient"}) == 0)
        {
            b.allowOnly({"type", "color"});
            bg = {BackgroundType::Constant, b["color"].vector3(0.0f, kMaxRadiance), vec3(0.0f)};
            bg.color1 = bg.color0;
        }
        else
        {
            b.allowOnly({"type", "bottom", "top"});
            bg = {BackgroundType::Gradient, b["bottom"].vector3(0.0f, kMaxRadiance), b["top"].vector3(0.0f, kMaxRadiance)};
        }
    }

    void readTexture(const JsonNode& t)
    {
        TextureData tex{};
        switch (t["type"].choice({"solid", "checker", "image", "noise", "turbulence", "marble"}))
        {
        case 0:
            t.allowOnly({"name", "type", "color"});
            tex.type = TextureType::Solid;
            tex.color0 = t["color"].vector3(0.0f, kMaxRadiance);
            break;
        case 1:
            t.allowOnly({"name", "type", "scale", "even", "odd", "offset"});
            tex.type = TextureType::Checker;
            tex.scale = positive(t["scale"]);
            tex.color0 = t["even"].vector3(0.0f, kMaxRadiance);
            tex.color1 = t["odd"].vector3(0.0f, kMaxRadiance);
            break;
        case 2:
        {
            t.allowOnly({"name", "type", "path", "linear"});
            tex.type = TextureType::Image;
            tex.linear = t.has("linear") && t["linear"].boolean() ? 1u : 0u;
            const std::filesystem::path file = resolvePath(t["path"], "texture");
            tex.image = static_cast<std::uint32_t>(scene().images.size());
            scene().images.push_back(located(t["path"], [&] { return loadImage(file.string()); }));
            break;
        }
        default:
        {
            t.allowOnly({"name", "type", "scale", "offset"});
            static constexpr TextureType kNoise[] = {TextureType::Noise, TextureType::Turbulence, TextureType::Marble};
            tex.type = kNoise[t["type"].choice({"noise", "turbulence", "marble"})];
            tex.scale = positive(t["scale"]);
        }
        }
        if (t.has("offset"))
            tex.origin = t["offset"].vector3(); // the pattern at p + offset
        m_textureNames.add(t, static_cast<std::uint32_t>(scene().textures.size()));
        scene().textures.push_back(tex);
    }

    static float positive(const JsonNode& n)
    {
        const float v = n.number(0.0f);
        if (v == 0.0f)
            n.fail("expected a number > 0");
        return v;
    }

    /// A colour given inline (a new solid texture; albedo in [0, 1]) or a texture reference under `key`_texture.
    std::uint32_t colorOrTexture(const JsonNode& m, const std::string& key, float maxValue)
    {
        const std::string textureKey = key + "_texture";
        if (m.has(key) && m.has(textureKey))
            m.fail(fmt::format("give '{}' or '{}', not both", key, textureKey));
        if (m.has(textureKey))
            return m_textureNames.resolve(m[textureKey]);
        return m_builder.solid(m[key].vector3(0.0f, maxValue));
    }

    /// A microfacet material's GGX roughness: "alpha" as is (a number, or [alpha_x, alpha_y] where `anisotropic`),
    /// or "roughness" as glTF maps it, alpha = roughness^2 (pbrt-v4 would take its square root instead).
    static void readRoughness(const JsonNode& m, MaterialData& mat, bool anisotropic)
    {
        if (m.has("alpha") == m.has("roughness"))
            m.fail("give the roughness as 'alpha' (GGX alpha) or as 'roughness' (alpha = roughness^2), one of them");
        if (m.has("roughness"))
        {
            const float r = m["roughness"].number(0.0f, 1.0f);
            mat.alphaX = mat.alphaY = r * r;
            return;
        }
        const JsonNode a = m["alpha"];
        if (anisotropic && a.value().is_array())
        {
            if (a.size() != 2)
                a.fail("expected [alpha_x, alpha_y]");
            mat.alphaX = a[0].number(0.0f, 1.0f);
            mat.alphaY = a[1].number(0.0f, 1.0f);
        }
        else
            mat.alphaX = mat.alphaY = a.number(0.0f, 1.0f);
    }

    void readMaterial(const JsonNode& m)
    {
        MaterialData mat{.type = MaterialType::Lambertian,
                         .albedoTexture = kNoIndex,
                         .emissionTexture = kNoIndex,
                         .metallicRoughnessTexture = kNoIndex};
        switch (m["type"].choice(
            {"lambertian", "metal", "dielectric", "diffuse_light", "isotropic", "conductor", "rough_dielectric", "gltf_pbr"}))
        {
        case 0:
            m.allowOnly({"name", "type", "albedo", "albedo_texture", "radiance", "radiance_texture"});
            mat.albedoTexture = colorOrTexture(m, "albedo", 1.0f);
            if (m.has("radiance") || m.has("radiance_texture"))
                mat.emissionTexture = colorOrTexture(m, "radiance", kMaxRadiance);
            break;
        case 1:
            m.allowOnly({"name", "type", "albedo", "albedo_texture", "fuzz"});
            mat.type = MaterialType::Metal;
            mat.albedoTexture = colorOrTexture(m, "albedo", 1.0f);
            mat.fuzz = m.has("fuzz") ? m["fuzz"].number(0.0f, 1.0f) : 0.0f;
            break;
        case 2:
            m.allowOnly({"name", "type", "ior", "fresnel"});
            mat.type = MaterialType::Dielectric;
            mat.ior = m["ior"].number(kMinIor, kMaxIor);
            if (m.has("fresnel"))
                mat.fresnel = static_cast<shader::FresnelModel>(m["fresnel"].choice({"schlick", "exact"}));
            break;
        case 3:
            m.allowOnly({"name", "type", "radiance", "radiance_texture"});
            mat.type = MaterialType::DiffuseLight;
            mat.emissionTexture = colorOrTexture(m, "radiance", kMaxRadiance);
            break;
        case 4:
            m.allowOnly({"name", "type", "albedo", "albedo_texture"});
            mat.type = MaterialType::Isotropic;
            mat.albedoTexture = colorOrTexture(m, "albedo", 1.0f);
            break;
        case 5:
            m.allowOnly({"name", "type", "alpha", "roughness", "eta", "k", "f0", "f0_texture"});
            mat.type = MaterialType::Conductor;
            readRoughness(m, mat, true);
            if (m.has("f0") || m.has("f0_texture"))
            {
                if (m.has("eta") || m.has("k"))
                    m.fail("give 'f0' (Schlick) or 'eta' and 'k' (exact), not both");
                mat.fresnel = shader::FresnelModel::Schlick;
                mat.albedoTexture = colorOrTexture(m, "f0", 1.0f);
            }
            else
            {
                mat.fresnel = shader::FresnelModel::Exact;
                mat.eta = m["eta"].vector3(kMinConductorEta, kMaxIor);
                mat.k = m["k"].vector3(0.0f, kMaxIor);
            }
            break;
        case 6:
            m.allowOnly({"name", "type", "alpha", "roughness", "ior"});
            mat.type = MaterialType::RoughDielectric;
            mat.fresnel = shader::FresnelModel::Exact;
            readRoughness(m, mat, false);
            mat.ior = m["ior"].number(kMinIor, kMaxIor);
            break;
        default:
            m.allowOnly({"name", "type", "base_color", "base_color_texture", "metallic", "roughness", "alpha",
                         "metallic_roughness_texture", "ior"});
            mat.type = MaterialType::GltfPbr;
            mat.albedoTexture = m.has("base_color") || m.has("base_color_texture") ? colorOrTexture(m, "base_color", 1.0f)
                                                                                   : m_builder.solid(vec3(1.0f));
            mat.metallic = m.has("metallic") ? m["metallic"].number(0.0f, 1.0f) : 1.0f;
            if (m.has("alpha") || m.has("roughness"))
                readRoughness(m, mat, false);
            else
                mat.alphaX = mat.alphaY = 1.0f; // glTF's default roughnessFactor 1
            mat.metallicRoughnessTexture = m.has("metallic_roughness_texture")
                                               ? m_textureNames.resolve(m["metallic_roughness_texture"])
                                               : kNoIndex;
            mat.ior = m.has("ior") ? m["ior"].number(1.0f, kMaxIor) : 1.5f;
        }
        m_materialNames.add(m, static_cast<std::uint32_t>(scene().materials.size()));
        scene().materials.push_back(mat);
    }

    std::uint32_t materialRef(const JsonNode& n) { return m_materialNames.resolve(n); }

    void readMesh(const JsonNode& m)
    {
        MeshData mesh;
        if (m.has("obj"))
        {
            m.allowOnly({"name", "obj", "fit"});
            const std::filesystem::path file = resolvePath(m["obj"], "mesh");
            const ObjPlacement placement =
                !m.has("fit") || m["fit"].boolean() ? ObjPlacement::Fit : ObjPlacement::AsWritten;
            // A mesh of a million triangles takes a second or two: say what the wait is for.
            const auto start = std::chrono::steady_clock::now();
            mesh = located(m["obj"], [&] { return loadObj(file.string(), placement); });
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (seconds > 0.5)
                spdlog::info("mesh {}: {} triangles read in {:.1f} s", file.string(), mesh.triangleCount(), seconds);
        }
        else
        {
            m.allowOnly({"name", "positions", "indices", "normals", "uvs", "triangle_materials"});
            mesh = readInlineMesh(m, [this](const JsonNode& ref) { return materialRef(ref); });
        }
        if (m.has("name"))
            mesh.name = m["name"].string();
        m_meshNames.add(m, static_cast<std::uint32_t>(scene().meshes.size()));
        scene().meshes.push_back(std::move(mesh));
    }

    void readGroup(const JsonNode& g)
    {
        g.allowOnly({"name", "shapes"});
        const std::string name = g.has("name") ? g["name"].string() : fmt::format("group {}", scene().groups.size());
        const std::uint32_t group = m_builder.group(name);
        m_groupNames.add(g, group);
        readShapes(g["shapes"], group);
    }

    void readInstance(const JsonNode& i)
    {
        i.allowOnly({"group", "transform"});
        const std::uint32_t group = m_groupNames.resolve(i["group"]);
        const Transform t = i.has("transform") ? readTransform(i["transform"]) : Transform::identity();
        const GroupDesc& g = scene().groups[group];
        if (!g.spheres.empty() && !t.uniformScale())
            i["transform"].fail("the group has spheres, which only a rotation, uniform scale and translation keep "
                                "spheres");
        if ((!g.quads.empty() || !g.meshes.empty()) && glm::determinant(mat3(t.m)) < 0.0f)
            i["transform"].fail("the transform mirrors (negative determinant), which would turn the group's quads' and "
                                "triangles' faces inward: mirror the geometry itself instead");
        m_builder.instance(group, t);
    }

    void readLightTarget(const JsonNode& t)
    {
        t.allowOnly({"type", "center", "radius"});
        t["type"].choice({"sphere"});
        m_builder.samplingTargetSphere(t["center"].vector3(), positive(t["radius"]));
    }

    void readShapes(const JsonNode& shapes, std::uint32_t group);
    void readMedium(const JsonNode& s, std::uint32_t group);

    const JsonNode& m_root;
    std::filesystem::path m_folder;
    SceneBuilder m_builder;
    NameTable m_textureNames{"texture"};
    NameTable m_materialNames{"material"};
    NameTable m_meshNames{"mesh"};
    NameTable m_groupNames{"group"};
};

void Reader::readShapes(const JsonNode& shapes, std::uint32_t group)
{
    MeshData triangles; // the group's "triangle" shapes, gathered into one mesh (one BLAS on the GPU)
    for (std::size_t i = 0; i < shapes.size(); ++i)
    {
        const JsonNode s = shapes[i];
        switch (s["type"].choice({"sphere", "moving_sphere", "quad", "box", "triangle", "mesh", "constant_medium"}))
        {
        case 0:
            s.allowOnly({"type", "center", "radius", "material"});
            m_builder.sphere(group, s["center"].vector3(), positive(s["radius"]), materialRef(s["material"]));
            break;
        case 1:
            s.allowOnly({"type", "center0", "center1", "radius", "material"});
            m_builder.movingSphere(group, s["center0"].vector3(), s["center1"].vector3(), positive(s["radius"]),
                                   materialRef(s["material"]));
            break;
        case 2:
        {
            s.allowOnly({"type", "q", "u", "v", "material"});
            const vec3 u = s["u"].vector3();
            const vec3 v = s["v"].vector3();
            if (!(glm::length(glm::cross(u, v)) > 0.0f))
                s.fail("the quad has zero area (u and v are zero or parallel)");
            m_builder.quad(group, s["q"].vector3(), u, v, materialRef(s["material"]));
            break;
        }
        case 3:
        {
            s.allowOnly({"type", "min", "max", "material"});
            const vec3 lo = s["min"].vector3();
            const vec3 hi = s["max"].vector3();
            if (!glm::all(glm::lessThan(lo, hi)))
                s["max"].fail("every coordinate of 'max' must exceed that of 'min' (a box of zero thickness has "
                              "faces of zero area)");
            m_builder.box(group, lo, hi, materialRef(s["material"]));
            break;
        }
        case 4:
        {
            s.allowOnly({"type", "p0", "p1", "p2", "material"});
            const vec3 p[3] = {s["p0"].vector3(), s["p1"].vector3(), s["p2"].vector3()};
            if (!(glm::length(glm::cross(p[1] - p[0], p[2] - p[0])) > 0.0f))
                s.fail("the triangle has zero area");
            const auto first = static_cast<std::uint32_t>(triangles.positions.size());
            for (int k = 0; k < 3; ++k)
            {
                triangles.positions.push_back(p[k]);
                triangles.indices.push_back(first + static_cast<std::uint32_t>(k));
            }
            triangles.triangleMaterials.push_back(materialRef(s["material"]));
            break;
        }
        case 5:
            s.allowOnly({"type", "mesh", "material"});
            m_builder.mesh(group, m_meshNames.resolve(s["mesh"]), materialRef(s["material"]));
            break;
        default:
            readMedium(s, group);
        }
    }
    if (!triangles.indices.empty())
    {
        triangles.name = fmt::format("{} triangles", scene().groups[group].name);
        const std::uint32_t material = triangles.triangleMaterials.front();
        m_builder.mesh(group, m_builder.addMesh(std::move(triangles)), material);
    }
}

void Reader::readMedium(const JsonNode& s, std::uint32_t group)
{
    const bool sphere = s["boundary"].choice({"sphere", "box"}) == 0;
    if (sphere)
        s.allowOnly({"type", "boundary", "center", "radius", "density", "albedo", "material"});
    else
        s.allowOnly({"type", "boundary", "min", "max", "density", "albedo", "material"});
    MediumDesc m;
    m.boundary = sphere ? MediumDesc::Boundary::Sphere : MediumDesc::Boundary::Box;
    if (sphere)
    {
        m.center = s["center"].vector3();
        m.radius = positive(s["radius"]);
    }
    else
    {
        m.boxMin = s["min"].vector3();
        m.boxMax = s["max"].vector3();
        if (!glm::all(glm::lessThan(m.boxMin, m.boxMax)))
            s["max"].fail("every coordinate of 'max' must exceed that of 'min'");
    }
    m.density = positive(s["density"]);
    if (s.has("albedo") == s.has("material"))
        s.fail("give the phase function's 'albedo' or an isotropic 'material', one of the two");
    if (s.has("material"))
    {
        m.phaseMaterial = materialRef(s["material"]);
        if (scene().materials[m.phaseMaterial].type != MaterialType::Isotropic)
            s["material"].fail("a medium's material must be of type 'isotropic'");
    }
    else
        m.phaseMaterial = m_builder.isotropic(s["albedo"].vector3(0.0f, 1.0f));
    scene().groups[group].media.push_back(m);
}
} // namespace

Scene readJsonSceneText(const std::string& text, const std::filesystem::path& file)
{
    const nlohmann::json doc = parseJsonText(text, file.string());
    return Reader(JsonNode(doc, file.string()), file).read();
}

Scene readJsonScene(const std::filesystem::path& file)
{
    std::error_code ec;
    if (const auto bytes = std::filesystem::file_size(file, ec); !ec && bytes > (std::uintmax_t{16} << 20))
        spdlog::info("reading {} ({} MB)", file.string(), bytes >> 20);
    std::ifstream in(file, std::ios::binary);
    if (!in)
        throw SceneError(fmt::format("{}: cannot be opened", file.string()));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad())
        throw SceneError(fmt::format("{}: cannot be read", file.string()));
    return readJsonSceneText(text.str(), file);
}
} // namespace rt
