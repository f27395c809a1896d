#include "Cli/CommonOptions.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string_view>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "Cli/ValueParsing.h"
#include "Cluster/Job.h"
#include "Error.h"
#include "Render/MemoryBudget.h"
#include "Render/SettingsTable.h"
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
    ref.options.roughnessScale = roughnessScale;
    return ref;
}

CLI::Validator finiteNumber()
{
    return CLI::Validator(
        [](std::string& text) {
            // strtod reads what CLI11's conversion reads ("+0.5", "0x1p-2", leading spaces), NaN and inf included.
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            const bool number =
                end != text.c_str() && std::string_view(end).find_first_not_of(" \t") == std::string_view::npos;
            return number && std::isfinite(value) ? std::string() : fmt::format("'{}' is not a finite number", text);
        },
        "");
}

CLI::Validator namesAFile()
{
    return CLI::Validator([](std::string& path) { return path.empty() ? std::string("names no file") : std::string(); },
                          "FILE");
}

void addCommonOptions(CLI::App& app, CommonOptions& o)
{
    // The program's name is known once CLI11 has read argv[0].
    app.set_version_flag(
        "--version",
        [&app] {
            return fmt::format("{} (light-sampling lab) {}", std::filesystem::path(app.get_name()).filename().string(),
                               RT_VERSION);
        },
        "Print the program's name and version and exit");
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
    for (const Setting& setting : settingsTable())
    {
        // Each flag writes its text into `settings` (CLI11 keeps the callback); resolveRequest parses it.
        const std::string name(setting.name);
        std::string help(setting.help);
        if (!setting.fromScene)
            help += fmt::format(" (default: {})", setting.text(RenderSettings{}));
        app.add_option_function<std::string>(
               "--" + name, [&o, name](const std::string& value) { o.settings[name] = value; }, help)
            ->check([&setting, name](const std::string& value) -> std::string {
                return setting.accepts(value) ? std::string() : setting.refusal(value);
            })
            ->type_name(setting.placeholder());
    }
    app.add_option("--fresnel", o.fresnel,
                   "The reflectance of every dielectric (glass): schlick (Schlick's approximation, as the books) "
                   "or exact (the unpolarised Fresnel equations, as pbrt-v4 and Mitsuba); default: each "
                   "material's own, schlick in the catalogue's scenes")
        ->check(CLI::IsMember({"schlick", "exact"}));
    app.add_option("--roughness-scale", o.roughnessScale,
                   fmt::format("Multiply the GGX roughness alpha of every microfacet material (conductor, rough "
                               "dielectric, glTF metallic-roughness) by this factor, {:g} to {:g}, alpha kept at "
                               "most 1: veach-mis's plates from mirror to matte (default: 1, the scene's own)",
                               kMinRoughnessScale, kMaxRoughnessScale))
        ->check(finiteNumber())
        ->check(CLI::Range(kMinRoughnessScale, kMaxRoughnessScale))
        ->type_name("X");
    app.add_option("--strategy", o.strategy,
                   "auto (the default of a headless render) first runs a short pilot on the render's engine that "
                   "measures the efficiency 1/(relMSE x time) of every combination of the candidates (nee-mis and "
                   "mixture; area, solid-angle, projected and, for quad and triangle lights, projected-exact; every "
                   "light selection with two lights or more; random and sobol pixel sampling where the scene's is "
                   "random, else the request's), renders with the best where its lead over the scene's own is beyond "
                   "the pilot's noise and 5 % (a render too short for a pilot keeps the scene's own), logs the pilot's "
                   "table and records it in --stats (strategy_choice); a choice is kept for the next render "
                   "(--strategy-cache). A setting given as a flag is not varied, nor an estimator the pilot does not "
                   "choose among (bsdf, nee: kept as asked; restir-di: no pilot). By default the candidates' "
                   "preparation (a GPU compiles a pipeline each) stops at a fifth of the render's estimated time (at "
                   "most --pilot-max-seconds) and the candidates left are not measured; a given auto prepares every "
                   "one, outside its budget. scene renders with the scene's estimator, light sampler, light selection "
                   "and pixel sampling (and the flags given), the same image for the same seed on every machine. The "
                   "windows open on scene (their first frame at once) and offer the pilot as a button; a given auto "
                   "opens them on its choice. Over mpirun's ranks the default is scene (one process chooses; a given "
                   "auto is refused there). With --compare: a given auto adds a row 'auto', its pilot over the "
                   "comparison's lists (auto's own candidates for a setting without one), its time including the "
                   "pilot's")
        ->capture_default_str()
        ->check(CLI::IsMember({"scene", "auto"}))
        ->each([&o](const std::string&) { o.strategyGiven = true; });
    app.add_option("--pilot-budget", o.pilotBudget,
                   "With --strategy auto: the pilot's time as a fraction of the render's estimated time (from a "
                   "probe render), 0.001 to 1; on the engine's clock (a GPU's own), its search held to twice it on the "
                   "host's, the probe and the candidates' preparation beside it")
        ->capture_default_str()
        ->check(finiteNumber())
        ->check(CLI::Range(0.001, 1.0));
    app.add_option("--pilot-max-seconds", o.pilotMaxSeconds,
                   "With --strategy auto: the pilot's time at most, in seconds (0.01 to 600)")
        ->capture_default_str()
        ->check(finiteNumber())
        ->check(CLI::Range(0.01, 600.0));
    app.add_option("--strategy-cache", o.strategyCache,
                   "With --strategy auto, headless: the folder of pilots' choices kept between runs (a render of the "
                   "same scene, settings but the seed, engine, device and program takes the choice made before, with "
                   "no pilot, and renders the same image for the same seed), or off (a pilot every time; --compare's "
                   "auto row always runs one). Default: $RT_STRATEGY_CACHE, else ~/.cache/ray-tracing/strategies")
        ->type_name("DIR|off");
    app.add_option("--pdf", o.pdf, "The books' name for two estimators: on = --estimator mixture, off = bsdf");
    app.add_option("--output", o.output, "Write the tone-mapped sRGB image here (.png)")->check(namesAFile());
    app.add_option("--hdr", o.hdr, "Write the linear radiance image here: .pfm (float) or .exr (OpenEXR, ZIP)")
        ->check(namesAFile());
    app.add_option("--hdr-type", o.hdrType,
                   "The channel type of an .exr --hdr: half (16-bit, 11 significant bits, values beyond 65504 clamped "
                   "to it) or float (32-bit, the image bit for bit); a .pfm is always float")
        ->capture_default_str()
        ->check(CLI::IsMember({"half", "float"}));
    app.add_option("--stats", o.stats, "Write render statistics as JSON here")->check(namesAFile());
    app.add_option("--heatmap", o.heatmap,
                   "Headless: time each pixel's samples and write the cost here: .png (painted blue to red, with a "
                   "colour bar and its unit), .pfm or .exr (the values: microseconds per sample on the CPU engines, "
                   "shader-clock ticks per sample on the GPU, which needs VK_KHR_shader_clock). Timing costs the "
                   "render time; the GPU engine traces it with its megakernel. In the windows: on or off, their cost "
                   "view (the same painted map)");
    app.add_option("--count", o.count,
                   "Object count for scenes that scale (white-spheres: spheres, default 20000; many-lights: lights, "
                   "default 1000), at least 1; refused up front when the scene would not fit in the memory "
                   "available (about 1 KB per object)")
        ->check(CLI::Range(1, std::numeric_limits<int>::max()));
    app.add_option("--mesh", o.mesh, "OBJ file for the mesh scenes (default: the Stanford bunny in Assets)");
    app.add_option("--translate-scene", o.translateScene,
                   "X,Y,Z: move the whole scene and its camera by this vector (world units), kept in double as "
                   "the scene's origin. Both engines render relative to the camera (render space), so the image "
                   "is the same however far the scene goes: a stress test of that (docs/ROBUSTNESS.md)");
    app.add_option("--scale-scene", o.scaleScene,
                   "S > 0: scale the whole scene and its camera by S about the origin (before --translate-scene); "
                   "media densities scale by 1/S, so the image stays the same: a float32 precision stress test");
    app.add_flag("--quiet", o.quiet, "No progress line");
}

std::optional<std::string> CommonOptions::given(std::string_view name) const
{
    const auto it = settings.find(name);
    return it == settings.end() ? std::nullopt : std::optional(it->second);
}

RenderRequest resolveRequest(const CommonOptions& o, const Scene& scene)
{
    RenderRequest request = defaultRequest(o.sceneRef(), scene);
    RenderSettings& s = request.settings;
    for (const auto& [name, value] : o.settings)
    {
        const Setting* setting = findSetting(name);
        if (setting == nullptr)
            throw UsageError(fmt::format("no setting '{}'", name));
        setting->set(s, value, "--" + name);
    }
    if (o.pdf)
    {
        const Estimator named = onOffFlag("--pdf", *o.pdf) ? Estimator::Mixture : Estimator::BsdfOnly;
        if (const auto estimator = o.given("estimator"); estimator && s.estimator != named)
            throw UsageError(fmt::format("--pdf {} means --estimator {}, which contradicts --estimator {}", *o.pdf,
                                         toString(named), *estimator));
        s.estimator = named;
    }
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
    if (options.roughnessScale != 1.0f && !r.scene.hasMicrofacetMaterial())
        spdlog::warn("--roughness-scale is ignored: scene {} has no microfacet material", r.scene.id);
    r.request = resolveRequest(options, r.scene);
    const RenderSettings& s = r.request.settings;
    // The BSDF-only estimator picks no light: a light sampler or selection given for it changes nothing.
    if (s.estimator == Estimator::BsdfOnly)
        for (const char* setting : {"light-sampler", "light-selection"})
            if (options.given(setting))
                spdlog::warn("--{} is ignored: estimator bsdf samples no light (nee, nee-mis, mixture and restir-di do)",
                             setting);
    checkMemory(renderBytes(s, r.scene.primitiveCount() + r.scene.lights.size()),
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

void configureLogging(bool quiet)
{
    const cluster::Job& job = cluster::job();
    spdlog::set_pattern(job.root() ? std::string("%^%l%$: %v") : fmt::format("%^%l%$: {}: %v", job.name(job.rank())));
    spdlog::set_level(quiet || !job.root() ? spdlog::level::warn : spdlog::level::info);
}

bool runCommonCommands(const CommonOptions& options)
{
    configureLogging(options.quiet);
    if (options.listScenes)
    {
        std::fputs(sceneListing().c_str(), stdout);
        return true;
    }
    if (options.exportScene.empty())
        return false;
    if (!cluster::job().root())
        return true; // one file, written once
    exportScene(placedScene(options.sceneRef().id, options.sceneRef().options), options.exportScene);
    spdlog::info("wrote {}", options.exportScene);
    return true;
}
} // namespace rt
