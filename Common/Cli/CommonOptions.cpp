#include "Cli/CommonOptions.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "Cli/ValueParsing.h"
#include "Error.h"
#include "Render/MemoryBudget.h"
#include "SceneFile/JsonSceneWriter.h"
#include "SceneFile/SceneFile.h"
#include "SceneFile/SceneFileWatch.h"

namespace rt
{
namespace
{
bool onOffFlag(const std::string& flag, const std::string& value)
{
    if (const auto on = parseOnOff(value))
        return *on;
    throw UsageError(fmt::format("{} must be 'on' or 'off' (got '{}')", flag, value));
}

SceneTransform sceneTransform(const std::string& translate, const std::string& scale)
{
    SceneTransform t;
    if (!translate.empty())
    {
        const auto xyz = parseRealTriple(translate);
        if (!xyz || !std::isfinite((*xyz)[0]) || !std::isfinite((*xyz)[1]) || !std::isfinite((*xyz)[2]))
            throw UsageError(fmt::format("--translate-scene must be three finite numbers X,Y,Z (got '{}')", translate));
        t.translation = vec3((*xyz)[0], (*xyz)[1], (*xyz)[2]);
    }
    if (!scale.empty())
    {
        const auto s = parseReal(scale);
        if (!s || !std::isfinite(*s) || !(*s > 0.0f))
            throw UsageError(fmt::format("--scale-scene must be a finite number > 0 (got '{}')", scale));
        t.scale = *s;
    }
    return t;
}
} // namespace

SceneRef CommonOptions::sceneRef() const
{
    SceneRef ref{.id = scene, .fileVersion = sceneFileVersion(scene)};
    ref.options.count = count.value_or(-1);
    if (!mesh.empty())
        ref.options.meshPath = mesh;
    ref.options.transform = sceneTransform(translateScene, scaleScene);
    if (fresnel)
        parseFresnelOption(*fresnel, ref.options.fresnel); // CLI11 has checked the name
    return ref;
}

void addCommonOptions(CLI::App& app, CommonOptions& o)
{
    app.add_flag("--headless", o.headless, "Render without a window, write the files asked for and exit");
    app.add_flag("--list-scenes", o.listScenes, "Print the scene ids with their titles and exit");
    app.add_option("--scene", o.scene,
                   "Scene id (see --list-scenes), or a scene file: .json (docs/SCENES.md) or glTF 2.0 (.gltf, .glb)")
        ->capture_default_str();
    app.add_option("--export-scene", o.exportScene,
                   "Write the scene (with --count, --mesh, --translate-scene, --scale-scene applied) to this .json "
                   "file and exit: reading it back with --scene renders the same image bit for bit on the CPU")
        ->check([](const std::string& path) {
            return isSceneFilePath(path) && path.ends_with(".json") ? std::string()
                                                                     : std::string("must name a .json file");
        });
    app.add_option("--spp", o.spp, "Samples per pixel, 1 to 16777216 (default: the scene's)");
    app.add_option("--depth", o.depth, "Ray segments per path at most, the camera ray included: 1 sees only the emitters (default: the scene's, usually 50)");
    app.add_option("--width", o.width, "Image width in pixels, 1 to 65536 (default: the scene's)");
    app.add_option("--aspect", o.aspect, "Aspect ratio width/height, e.g. 1 or 1.7778 (default: the scene's)")
        ->check([](const std::string& text) -> std::string {
            // Checked as written, in double: a float reads 1e308 as inf, and the message would quote that.
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            if (text.empty() || end != text.c_str() + text.size())
                return fmt::format("must be a number (got '{}')", text);
            if (!(value > 0.0) || !(value <= double(std::numeric_limits<float>::max())))
                return fmt::format("must be a positive number a float can hold (got {})", text);
            return {};
        });
    app.add_option("--sampling", o.sampling,
                   "Pixel sampling: random (independent jitter), stratified (floor(sqrt(spp))^2 jittered strata), "
                   "accumulate (progressive 1-spp passes) or sobol (every 2D draw of a sample - pixel, lens, light "
                   "point, BSDF direction - an Owen-scrambled Sobol point over the pixel's samples, Burley 2020: "
                   "stratified at every power-of-two spp). Default: the scene's: sobol, or random for the books' "
                   "scenes");
    app.add_option("--estimator", o.estimator,
                   "How a path gathers light (default: the scene's: nee-mis, or mixture for the books' scenes). "
                   "bsdf: follow sampled BSDF directions only (books 1-2); mixture: book 3's one-sample mix of "
                   "BSDF and light directions, no shadow rays; nee: a shadow ray to one sampled light at every "
                   "diffuse vertex, BSDF rays ignore the lights; nee-mis: NEE and BSDF rays both count, weighted "
                   "by the power heuristic");
    app.add_option("--light-sampler", o.lightSampler,
                   "How nee and nee-mis pick a point on a light: area (uniform over its surface), solid-angle "
                   "(uniform over the directions it covers: cones for spheres, spherical rectangles for "
                   "rectangular quads, spherical triangles (Arvo) for triangles of 3e-4 to 6.22 sr, area "
                   "where no solid-angle sampler applies) or projected (by the cosine over a sphere's cap "
                   "when it lies above the receiver's horizon, and over rectangles and triangles by a "
                   "bilinear warp of their spherical samplers; else as solid-angle). The mixture keeps "
                   "book 3's.")
        ->capture_default_str();
    app.add_option("--light-selection", o.lightSelection,
                   "Which light nee and nee-mis sample at a vertex: uniform (each of the N emitters 1/N), power "
                   "(in proportion to area x emitted luminance, by an alias table) or bvh (by a light BVH: in "
                   "proportion to a bound of what each group of emitters can contribute at the vertex, from its "
                   "power, distance, orientation and the receiver's horizon)")
        ->capture_default_str();
    app.add_option("--fresnel", o.fresnel,
                   "The reflectance of every dielectric (glass): schlick (Schlick's approximation, as the books) "
                   "or exact (the unpolarised Fresnel equations, as pbrt-v4 and Mitsuba); default: each "
                   "material's own, schlick in the catalogue's scenes")
        ->check(CLI::IsMember({"schlick", "exact"}));
    app.add_option("--pdf", o.pdf, "The books' name for two estimators: on = --estimator mixture, off = bsdf");
    app.add_option("--russian-roulette", o.russianRoulette,
                   "on: from the third segment, a path whose throughput fell below 1 ends with probability "
                   "1 - throughput and the survivors are scaled up (unbiased, pbrt-v4's rule; with bsdf and "
                   "mixture a path ends after the light its last direction finds); off: paths run to --depth")
        ->capture_default_str();
    app.add_option("--unidirectional-light", o.unidirectionalLight,
                   "on: emitters emit from their front face only; off: from both faces (default: the scene's)");
    app.add_option("--seed", o.seed, "Seed of the per-pixel, per-sample random streams (0..4294967295)")
        ->capture_default_str();
    app.add_option("--output", o.output, "Write the tone-mapped sRGB image here (.png)");
    app.add_option("--hdr", o.hdr, "Write the linear radiance image here (.pfm)");
    app.add_option("--stats", o.stats, "Write render statistics as JSON here");
    app.add_option("--count", o.count,
                   "Object count for scenes that scale (white-spheres: spheres, default 20000; many-lights: lights, "
                   "default 1000), at least 1; refused up front when the scene would not fit in the memory "
                   "available (about 1 KB per object)")
        ->check(CLI::Range(1, std::numeric_limits<int>::max()));
    app.add_option("--mesh", o.mesh, "OBJ file for the mesh scenes (default: the Stanford bunny in Assets)");
    app.add_option("--translate-scene", o.translateScene,
                   "X,Y,Z: move the whole scene and its camera by this vector (world units). The image stays "
                   "the same in exact arithmetic, so what changes is float32 precision far from the origin: a "
                   "stress test. Refused past the distance float32 renders right (docs/ROBUSTNESS.md)");
    app.add_option("--scale-scene", o.scaleScene,
                   "S > 0: scale the whole scene and its camera by S about the origin (before --translate-scene); "
                   "media densities scale by 1/S, so the image stays the same: a float32 precision stress test");
    app.add_flag("--quiet", o.quiet, "No progress line");
}

RenderRequest resolveRequest(const CommonOptions& o, const Scene& scene)
{
    RenderRequest request = defaultRequest(o.sceneRef(), scene);
    RenderSettings& s = request.settings;
    s.spp = o.spp.value_or(s.spp);
    s.depth = o.depth.value_or(s.depth);
    s.width = o.width.value_or(s.width);
    s.aspect = o.aspect.value_or(s.aspect);
    if (o.sampling)
    {
        const auto sampling = parsePixelSampling(*o.sampling);
        if (!sampling)
            throw UsageError(
                fmt::format("--sampling must be random, stratified, accumulate or sobol (got '{}')", *o.sampling));
        s.sampling = *sampling;
    }
    if (o.estimator)
    {
        const auto estimator = parseEstimator(*o.estimator);
        if (!estimator)
            throw UsageError(
                fmt::format("--estimator must be bsdf, mixture, nee or nee-mis (got '{}')", *o.estimator));
        s.estimator = *estimator;
    }
    if (o.pdf)
    {
        const Estimator named = onOffFlag("--pdf", *o.pdf) ? Estimator::Mixture : Estimator::BsdfOnly;
        if (o.estimator && s.estimator != named)
            throw UsageError(fmt::format("--pdf {} means --estimator {}, which contradicts --estimator {}", *o.pdf,
                                         toString(named), *o.estimator));
        s.estimator = named;
    }
    s.russianRoulette = onOffFlag("--russian-roulette", o.russianRoulette);
    const auto lightSampler = parseLightSampler(o.lightSampler);
    if (!lightSampler)
        throw UsageError(
            fmt::format("--light-sampler must be area, solid-angle or projected (got '{}')", o.lightSampler));
    s.lightSampler = *lightSampler;
    const auto lightSelection = parseLightSelection(o.lightSelection);
    if (!lightSelection)
        throw UsageError(fmt::format("--light-selection must be uniform, power or bvh (got '{}')", o.lightSelection));
    s.lightSelection = *lightSelection;
    if (o.unidirectionalLight)
        s.unidirectionalLight = onOffFlag("--unidirectional-light", *o.unidirectionalLight);
    s.seed = o.seed;
    s.validate();
    return request;
}

CommandLineRender resolveCommandLine(const CommonOptions& options)
{
    const std::uint64_t available = availableMemoryBytes();
    const SceneInfo* info = findScene(options.scene);
    const unsigned takes = info ? info->takes : kTakesNothing; // an unknown id fails in buildScene
    if (options.count && (takes & kTakesCount) == 0u)
        spdlog::warn("--count is ignored: scene {} has no object count (white-spheres and many-lights have one)",
                     options.scene);
    else if (options.count)
        checkMemory(renderBytes(0, std::uint64_t(*options.count)), fmt::format("--count {}", *options.count),
                    available);
    if (!options.mesh.empty() && (takes & kTakesMesh) == 0u)
        spdlog::warn("--mesh is ignored: scene {} loads no mesh (mesh-in-one-weekend, cornell-box-and-mesh and "
                     "triangle-lights do)",
                     options.scene);
    CommandLineRender r{.scene = buildScene(options.sceneRef())};
    if (options.fresnel && std::none_of(r.scene.materials.begin(), r.scene.materials.end(), [](const MaterialData& m) {
            return m.type == MaterialType::Dielectric;
        }))
        spdlog::warn("--fresnel is ignored: scene {} has no dielectric", r.scene.id);
    r.request = resolveRequest(options, r.scene);
    const RenderSettings& s = r.request.settings;
    const std::uint64_t pixels = std::uint64_t(s.width) * std::uint64_t(s.height());
    checkMemory(renderBytes(pixels, r.scene.primitiveCount() + r.scene.lights.size()),
                fmt::format("a {}x{} render of {}", s.width, s.height(), r.scene.id), available);
    return r;
}

std::string sceneListing()
{
    std::string out;
    for (const SceneInfo& s : sceneCatalogue())
        out += fmt::format("{:<24} {:<52} {}\n", s.id, s.title, s.source);
    return out;
}

bool runCommonCommands(const CommonOptions& options)
{
    spdlog::set_pattern("%^%l%$: %v");
    spdlog::set_level(options.quiet ? spdlog::level::warn : spdlog::level::info);
    if (options.listScenes)
    {
        std::fputs(sceneListing().c_str(), stdout);
        return true;
    }
    if (options.exportScene.empty())
        return false;
    exportScene(buildScene(options.sceneRef()), options.exportScene);
    spdlog::info("wrote {}", options.exportScene);
    return true;
}
} // namespace rt
