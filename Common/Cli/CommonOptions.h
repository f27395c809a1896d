// The headless flags both apps share (ray-tracing-cpu and ray-tracing-gpu take the same ones), parsed by
// CLI11, and their resolution against a scene's defaults.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

#include "Render/RenderRequest.h"
#include "Scene/Scene.h"

namespace rt
{
struct CommonOptions
{
    bool headless = false;
    bool listScenes = false;
    std::string scene = "cornell-box-lights";
    /// The render settings' flags as given, by the settings table's names (Render/SettingsTable.h): "spp" -> "16";
    /// a setting not given is absent and keeps the scene's request's value.
    std::map<std::string, std::string, std::less<>> settings;
    std::optional<std::string> pdf; // the books' name for two estimators
    std::string output;
    std::string hdr;
    std::string hdrType = "half"; // --hdr-type: an .exr's channels
    std::string stats;
    /// --heatmap: headless, the file of the per-pixel cost (.png painted, .pfm or .exr values); in the windows,
    /// on or off (their cost view).
    std::string heatmap;
    std::optional<int> count; // >= 1 (CLI11 checks); empty: the scene's default
    std::string mesh;
    std::string translateScene; // "X,Y,Z", empty = none
    std::string scaleScene; // a real > 0, empty = none
    std::string exportScene; // a .json path, empty = none
    std::optional<std::string> fresnel; // schlick | exact; empty: each dielectric's own
    float roughnessScale = 1.0f; // in [kMinRoughnessScale, kMaxRoughnessScale] (CLI11 checks)
    bool quiet = false;
    /// --strategy: auto (a pilot chooses; the default) | scene (the scene's defaults and the flags).
    std::string strategy = "auto";
    /// --strategy was given: the default auto gives way to the scene's own where a pilot cannot run (over mpirun's
    /// ranks) and adds no row to --compare; a given auto refuses the first and adds the row.
    bool strategyGiven = false;
    double pilotBudget = 0.05; // --pilot-budget: the pilot's share of the render's estimated time
    double pilotMaxSeconds = 2.0; // --pilot-max-seconds
    std::string strategyCache; // --strategy-cache: a folder, or off; empty: the default (Compare/StrategyCache.h)

    /// The value given for the setting `name`, or nothing.
    std::optional<std::string> given(std::string_view name) const;
    /// The scene the flags name; throws UsageError for a malformed --translate-scene or --scale-scene.
    SceneRef sceneRef() const;
};

/// CLI11's check of a flag that names a file to write: an empty value (`--output ""`) is refused, not read as
/// "not given".
CLI::Validator namesAFile();

/// CLI11's check of a number flag: NaN and the infinities are refused (CLI::Range lets NaN through).
CLI::Validator finiteNumber();

/// Registers the shared flags on `app` with help text for each: the render settings' from the settings table.
void addCommonOptions(CLI::App& app, CommonOptions& options);

/// The request of a command line for `scene` (built from options.sceneRef()): the scene's defaults,
/// overridden by every flag the user gave. Throws UsageError.
RenderRequest resolveRequest(const CommonOptions& options, const Scene& scene);

/// A command line's scene, built, and its request.
struct CommandLineRender
{
    Scene scene;
    RenderRequest request;
};

/// Builds the scene the flags name and resolves the request. Refuses, before building anything, a request
/// whose estimated memory (Render/MemoryBudget.h: --count's objects, then the built scene and the image)
/// exceeds what the machine has available. Throws UsageError, SceneError, AssetError.
CommandLineRender resolveCommandLine(const CommonOptions& options);

/// One line per catalogue scene: id, title, source.
std::string sceneListing();

/// The log lines on stderr: warnings and errors, and the info lines unless `quiet`. Of an MPI job's ranks, root's
/// alone say what every rank would say alike; the others log warnings and errors only, each naming its rank.
void configureLogging(bool quiet);

/// What every command of both apps does first: log level from --quiet, --list-scenes printed to stdout, and
/// --export-scene's file written. Returns true when the command is done (it was one of the two).
/// Throws what buildScene and exportScene throw.
bool runCommonCommands(const CommonOptions& options);
} // namespace rt
