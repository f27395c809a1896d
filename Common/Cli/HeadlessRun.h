// The headless flow both apps share: render a scene with an engine, show progress and ETA on stderr, stop
// cleanly on Ctrl-C, write the image, HDR and stats files asked for, print a one-line summary.
#pragma once

#include <functional>
#include <initializer_list>
#include <string>

#include <nlohmann/json.hpp>

#include "Cli/CommonOptions.h"
#include "Render/RenderEngine.h"
#include "Render/RenderRequest.h"

namespace rt
{
/// Checks, before any work, that `path` (if not empty) ends in one of `extensions` and can be written
/// (IO/OutputSet.h's checkWritable: the folder exists and takes a new file, the path is no folder).
/// Throws UsageError (extension) or OutputError (folder), naming `flag`.
void checkOutputPath(const std::string& path, const char* flag, std::initializer_list<const char*> extensions);

/// Checks, before any work, that every output path can be written (folder exists, known extension) and that no
/// two name one file (checkDistinctOutputs). Throws UsageError or OutputError.
void checkOutputPaths(const CommonOptions& options);

/// Throws UsageError naming both flags where two of `outputs` (flag, path; empty paths skipped) name one file: the
/// same path, or a symbolic link to the other's (the second would replace the first's file).
void checkDistinctOutputs(std::initializer_list<std::pair<const char*, const std::string*>> outputs);

/// What a headless run renders once its scene is set: the request, and what chose it (--stats' "strategy_choice").
struct ChosenRequest
{
    RenderRequest request;
    nlohmann::json record; // null: nothing to record
    bool cancelled = false; // Ctrl-C stopped the choice
};
/// Chooses the request to render on `engine` (whose scene is set) from the command line's (--strategy auto:
/// Compare/AutoStrategy.h); runs inside the render's Ctrl-C scope.
using RequestChooser = std::function<ChosenRequest(RenderEngine& engine, const RenderRequest& request)>;

/// Renders `request` of `scene` (the scene it names, built), or what `chooser` makes of it when given, and writes
/// the outputs, all or none (IO/OutputSet.h). Over mpirun's ranks no chooser runs: the default --strategy renders
/// the request as it is, a given --strategy auto is refused (UsageError). Returns the process exit status: 0, or 130
/// when cancelled by SIGINT (nothing is written then). Throws rt::Error for failures (OutputError, with no output
/// left behind, when one cannot be written).
int runHeadless(RenderEngine& engine, const Scene& scene, const RenderRequest& request, const CommonOptions& options,
                const RequestChooser& chooser = {});

/// Parses the command line, then runs `body`, turning every rt::Error and CLI11 parse error into one
/// "error: ..." line on stderr and the error's exit status. `--help` prints the help and returns 0.
int guardedMain(CLI::App& app, int argc, char** argv, const std::function<int()>& body);
} // namespace rt
