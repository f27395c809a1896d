#include "Scenes/Catalogue.h"

#include <algorithm>
#include <filesystem>
#include <vector>

#include <spdlog/fmt/fmt.h>

#include "Error.h"
#include "Scene/RenderSpace.h"
#include "Scene/SceneTransform.h"
#include "SceneFile/SceneFile.h"
#include "Scenes/SceneFactories.h"

namespace rt
{
const std::vector<SceneInfo>& sceneCatalogue()
{
    using namespace scenes;
    static const std::vector<SceneInfo> catalogue = {
        {"rtow-default", "Book 1 default: three spheres on a ground", "RTIOW §14", rtowDefault},
        {"rtow-camera-test", "Book 1 camera test: red and blue spheres", "RTIOW §12", rtowCameraTest},
        {"rtow-final", "Book 1 cover: random spheres", "RTIOW §14", rtowFinal},
        {"rtnw-motion-blur", "Book 2 bouncing spheres (motion blur)", "RTTNW §2", rtnwMotionBlur},
        {"rtnw-checker-spheres", "Book 2 checker spheres", "RTTNW §4", rtnwCheckerSpheres},
        {"rtnw-earth", "Book 2 earth texture", "RTTNW §4", rtnwEarth},
        {"rtnw-perlin-spheres", "Book 2 Perlin marble spheres", "RTTNW §5", rtnwPerlinSpheres},
        {"rtnw-quads", "Book 2 quads", "RTTNW §6", rtnwQuads},
        {"rtnw-simple-light", "Book 2 simple light", "RTTNW §7", rtnwSimpleLight},
        {"rtnw-cornell-box", "Book 2 Cornell box", "RTTNW §7-8", rtnwCornellBox},
        {"rtnw-cornell-smoke", "Book 2 Cornell box with smoke", "RTTNW §9", rtnwCornellSmoke},
        {"rtnw-final", "Book 2 final scene", "RTTNW §10", rtnwFinal},
        {"rtrol-cornell-box", "Book 3 Cornell box", "RTTROYL §12", rtrolCornellBox},
        {"rtrol-cornell-mirror", "Book 3 Cornell box, aluminium box", "RTTROYL §12", rtrolCornellMirror},
        {"rtrol-cornell-glass", "Book 3 final: Cornell box with glass sphere", "RTTROYL §12.5", rtrolCornellGlass},
        {"white-spheres", "Thesis: white spheres for BVH scaling", "thesis §4.3", whiteSpheres, kTakesCount},
        {"cornell-box-lights", "Thesis benchmark: Cornell box with 12 lights", "thesis §5.2", cornellBoxLights},
        {"cube-and-spheres", "Thesis GPU app: cube and spheres", "thesis B.2", cubeAndSpheres},
        {"planets-in-one-weekend", "Thesis GPU app: planets in one weekend", "thesis B.2", planetsInOneWeekend},
        {"mesh-in-one-weekend", "Thesis GPU app: meshes in one weekend", "thesis B.2", meshInOneWeekend, kTakesMesh},
        {"cornell-box-and-mesh", "Thesis GPU app: Cornell box and mesh", "thesis B.2", cornellBoxAndMesh, kTakesMesh},
        {"furnace", "White furnace: Le / (1 - a) everywhere", "research notes §4.5", furnace},
        {"rect-light-closeup", "Rectangular light upright on a floor, seen near its foot", "scenes.md", rectLightCloseup},
        {"many-lights", "cornell-box-lights' room with N small lights (--count, default 1000)", "scenes.md", manyLights, kTakesCount},
        {"lamp-room", "N lamps in shades open on one side (--count, default 4096): visibility decides", "scenes.md", lampRoom,
         kTakesCount},
        {"sphere-light-closeup", "Sphere light just above a floor", "scenes.md", sphereLightCloseup},
        {"triangle-lights", "Cornell box lit by triangles: ceiling halves, a sliver, an emitting mesh",
         "scenes.md", triangleLights, kTakesMesh},
        {"veach-mis", "Veach's MIS scene: four glossy plates, four sphere lights of equal power", "Veach 1997 fig. 9.2",
         veachMis},
        {"glossy-cornell", "cornell-box-lights with a rough conductor, a glTF floor and rough glass", "scenes.md",
         glossyCornell},
    };
    return catalogue;
}

const SceneInfo* findScene(const std::string& id)
{
    for (const SceneInfo& info : sceneCatalogue())
        if (info.id == id)
            return &info;
    return nullptr;
}

const char* fresnelOptionName(const std::optional<shader::FresnelModel>& fresnel)
{
    if (!fresnel)
        return "scene";
    return *fresnel == shader::FresnelModel::Exact ? "exact" : "schlick";
}

bool parseFresnelOption(std::string_view text, std::optional<shader::FresnelModel>& fresnel)
{
    if (text == "scene")
        fresnel.reset();
    else if (text == "schlick")
        fresnel = shader::FresnelModel::Schlick;
    else if (text == "exact")
        fresnel = shader::FresnelModel::Exact;
    else
        return false;
    return true;
}

namespace
{
/// Levenshtein distance: the edits (insert, delete, replace one character) from a to b.
std::size_t editDistance(const std::string& a, const std::string& b)
{
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
    {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
        {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

Scene withOptions(Scene scene, const SceneOptions& options)
{
    placeScene(scene, options.transform);
    if (options.fresnel)
        for (MaterialData& m : scene.materials)
            if (m.type == MaterialType::Dielectric)
                m.fresnel = *options.fresnel;
    if (options.roughnessScale != 1.0f)
        for (MaterialData& m : scene.materials)
            if (isMicrofacetMaterial(m.type))
            {
                m.alphaX = std::min(m.alphaX * options.roughnessScale, 1.0f);
                m.alphaY = std::min(m.alphaY * options.roughnessScale, 1.0f);
            }
    return scene;
}
} // namespace

Scene placedScene(const std::string& id, const SceneOptions& options)
{
    if (isSceneFilePath(id))
        return withOptions(loadSceneFile(id), options);
    const SceneInfo* info = findScene(id);
    if (!info)
    {
        std::string known;
        for (const SceneInfo& s : sceneCatalogue())
            known += (known.empty() ? "" : ", ") + s.id;
        // A typo of a catalogue id (at most a third of its characters edited) is named first.
        const SceneInfo* nearest = nullptr;
        std::size_t best = 0;
        for (const SceneInfo& s : sceneCatalogue())
            if (const std::size_t d = editDistance(id, s.id); !nearest || d < best)
            {
                nearest = &s;
                best = d;
            }
        std::string suggestion = nearest && 3 * best <= nearest->id.size()
                                     ? fmt::format(": did you mean '{}'?", nearest->id)
                                     : std::string();
        // A path that names something else than a scene file says what it names.
        std::error_code ec;
        if (std::filesystem::is_directory(id, ec))
            suggestion = ": it is a folder, not a scene file";
        else if (std::filesystem::exists(id, ec))
            suggestion = std::filesystem::is_regular_file(id, ec) ? ": it is a file without a scene file's extension"
                                                                  : ": it is not a regular file";
        throw SceneError(fmt::format("unknown scene '{}'{} (known: {}; or a scene file: .json, .gltf, .glb)", id,
                                     suggestion, known));
    }
    return withOptions(info->build(options), options);
}

Scene makeScene(const std::string& id, const SceneOptions& options)
{
    Scene scene = placedScene(id, options);
    toRenderSpace(scene);
    // float32's reach as rendered: in render space, after --scale-scene, which may bring a file's scene back into it.
    checkFloatReach(scene, id);
    return scene;
}
} // namespace rt
