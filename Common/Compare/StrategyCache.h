// --strategy auto's choices, kept on disk between runs (as FFTW keeps its planner's measurements, "wisdom"): a
// pilot measures which strategy is the most efficient for a scene on an engine, and a render of the same scene at
// the same settings on the same device by the same program needs no second pilot. It also renders the same image
// for the same seed, where two pilots may choose differently between close candidates (a choice depends on
// timings). An entry is the pilot's record (AutoChoice::toJson) under a key of everything the choice depends on:
// the scene's fingerprint, every render setting but the seed, the engine and its device, the candidates, the
// budget, and the program's file (its size and time: a rebuild changes the speeds the pilot measured). Not the
// engine's options (the GPU app's --integrator, --specialize): after changing them, --strategy-cache off.
// --compare's auto row never reads it: the row measures what a pilot costs.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "Compare/AutoStrategy.h"
#include "Compare/Strategy.h"
#include "Render/RenderEngine.h"
#include "Render/RenderRequest.h"
#include "Scene/Scene.h"

namespace rt::compare
{
/// $RT_STRATEGY_CACHE ('off': none, an empty path), else $XDG_CACHE_HOME/ray-tracing/strategies, else
/// ~/.cache/ray-tracing/strategies.
std::filesystem::path defaultStrategyCacheDir();

/// A choice found in the cache: the strategy and the record of the pilot that chose it.
struct CachedChoice
{
    Strategy chosen;
    nlohmann::json record; // AutoChoice::toJson of that pilot
    std::filesystem::path file;
};

class StrategyCache
{
public:
    /// An empty `dir` disables the cache (every lookup misses, store does nothing).
    explicit StrategyCache(std::filesystem::path dir) : m_dir(std::move(dir)) {}

    /// The choice stored under `key`, or nullopt (none, or an entry that does not parse: the pilot runs again).
    std::optional<CachedChoice> find(const std::string& key) const;
    /// Stores `choice` under `key` (atomically; a failure is logged, not thrown: the render does not depend on
    /// the cache). A cancelled pilot is not stored, nor one whose budget ran out before it measured every round (a
    /// GPU's first pilot, compiling its pipelines), nor one that left candidates unprepared (the default's bound on
    /// a cold driver cache): the next render pilots again, its driver's cache warmer.
    void store(const std::string& key, const AutoChoice& choice) const;

    /// The JSON text of the key of a pilot for `request` (its seed aside) on `engine`, whose scene is `scene`.
    static std::string key(const Scene& scene, const RenderRequest& request, const RenderEngine& engine,
                           const StrategyLists& candidates, const PilotBudget& budget);

private:
    std::filesystem::path m_dir;
};
} // namespace rt::compare
