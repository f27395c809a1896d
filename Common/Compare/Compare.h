// The headless comparison (thesis Table 5.4 redone honestly, and the light-sampling studies): one scene, the
// same settings and seed family on every engine (single core, multi core, GPU) and every strategy (estimator,
// light sampler, light selection, pixel sampling, roulette), then either
//  - a ladder of sample counts: for each, the render time, the CPU/GPU time ratio and the error against an
//    independent high-spp reference (a table on stdout, rows in CSV and JSON, plots of error against time), or
//  - an equal-time comparison: each strategy rendered for the same time, the images and their error images in
//    one figure.
// The reference is a file, or rendered once and cached on disk (ReferenceCache.h).
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "Compare/AutoStrategy.h"
#include "Compare/Strategy.h"
#include "Image/Metrics.h"
#include "Render/RenderEngine.h"
#include "Render/RenderRequest.h"

namespace rt::compare
{
struct CompareOptions
{
    std::vector<int> spps; // sample counts of the ladder, one row each
    std::vector<EngineKind> engines; // in order; the reference is rendered by the last
    std::vector<Strategy> strategies; // at least one
    int referenceSpp = 0; // spp of the reference image (seed + 1000)
    std::string referencePath; // a linear PFM to use as the reference instead of rendering one
    std::filesystem::path referenceCache; // folder of cached references; empty: render every time
    std::string json; // every figure as JSON, when not empty
    std::string csv; // one CSV row per engine x strategy x spp, written as each render ends
    std::string plot; // a PNG of the CSV's rows drawn by scripts/plot_convergence.py (needs csv)
    double equalTimeMs = 0.0; // > 0: the equal-time comparison instead of the ladder
    std::string grid; // --output's figure (PNG): the equal-time tiles, or the ladder's images at every spp
    std::filesystem::path images; // every render's PFM and an index (ImageFolder.h), when not empty
    int seeds = 1; // each row rendered with seeds seed, seed + 1, ...: means with 95 % intervals (Confidence.h)
    int rounds = 3; // every row timed again in this many interleaved rounds: the median time and its spread
    ErrorMetric metric = ErrorMetric::RelMse; // the error the tables show and the efficiencies use
    /// --strategy auto: a row "auto" after the strategies, on every engine, whose strategy a pilot over these
    /// candidates chooses (Compare/AutoStrategy.h) for each of its renders (each spp and seed; its later rounds
    /// reuse the choice), and whose time includes the pilot's. Empty: no such row.
    StrategyLists autoCandidates;
    PilotBudget pilotBudget;
};

/// Parses "10,50,100" (positive integers). Throws UsageError.
std::vector<int> parseSppList(const std::string& text);
/// Parses "single,multi,gpu". Throws UsageError.
std::vector<EngineKind> parseEngineList(const std::string& text);

/// Checks what can be checked before any engine starts: output paths, the plotting scripts and matplotlib.
/// Throws UsageError, OutputError or AssetError.
void checkComparison(const CompareOptions& options);

/// The end of a cancelled comparison's warning, what it leaves: the CSV's finished rows and the --images folder's
/// images (indexed by its images.json) where they were asked for, else ": nothing written".
std::string keptOnCancel(const CompareOptions& options, bool csvOpen, bool imagesFolder);

/// Runs the comparison and prints its table on stdout, progress on stderr; returns the process status (0, or
/// 130 when Ctrl-C stopped it: the CSV keeps every row finished before). Engines that cannot start (no Vulkan
/// ray-tracing device) are reported and left out rather than failing the comparison. `base` is the request
/// of `scene` (the scene it names, built); rows vary its spp and strategy.
int runComparison(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
                  const std::function<std::unique_ptr<RenderEngine>(EngineKind)>& makeEngine);
} // namespace rt::compare
