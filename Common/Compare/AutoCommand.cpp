#include "Compare/AutoCommand.h"

#include <spdlog/spdlog.h>

#include "Compare/StrategyCache.h"

namespace rt::compare
{
std::vector<std::string> fixedSettings(const CommonOptions& options)
{
    std::vector<std::string> fixed;
    for (const auto& [name, value] : options.settings)
        fixed.push_back(name);
    if (options.pdf)
        fixed.push_back("estimator");
    return fixed;
}

StrategyLists commandLineCandidates(const Scene& scene, const CommonOptions& options, const StrategyLists& lists)
{
    return autoCandidates(scene, lists, fixedSettings(options));
}

PilotBudget pilotBudget(const CommonOptions& options)
{
    return {.fraction = options.pilotBudget, .maxSeconds = options.pilotMaxSeconds};
}

RequestChooser strategyChooser(const Scene& scene, const CommonOptions& options)
{
    if (options.strategy != "auto")
        return {};
    const std::filesystem::path cacheDir = options.strategyCache.empty()   ? defaultStrategyCacheDir()
                                           : options.strategyCache == "off" ? std::filesystem::path()
                                                                            : std::filesystem::path(options.strategyCache);
    PilotBudget budget = pilotBudget(options);
    // The default bounds the candidates' preparation (a GPU's pipelines): a render asked for no pilot must not wait
    // on compiles longer than a fifth of itself; a given auto prepares every candidate.
    if (!options.strategyGiven)
        budget.prepareFraction = kDefaultPrepareFraction;
    return [lists = commandLineCandidates(scene, options), budget,
            cache = StrategyCache(cacheDir)](RenderEngine& engine, const RenderRequest& request) {
        const std::optional<StrategyLists> candidates = pilotCandidates(lists, request.settings);
        if (!candidates)
        {
            spdlog::info("--strategy auto: {}", kNoPilotForRestirDi);
            return ChosenRequest{request, nullptr, false};
        }
        const std::string key = StrategyCache::key(*engine.scene(), request, engine, *candidates, budget);
        if (const std::optional<CachedChoice> cached = cache.find(key))
        {
            nlohmann::json record = cached->record;
            record["cached"] = cached->file.string();
            ChosenRequest chosen{request, std::move(record), false};
            chosen.request.settings = cached->chosen.applyTo(request.settings);
            spdlog::info("--strategy auto: {}, as a pilot on this device chose it before ({}; --strategy-cache off "
                         "measures again)",
                         cached->chosen.name(), cached->file.string());
            return chosen;
        }
        const AutoChoice choice = chooseStrategy(engine, request, *candidates, budget);
        cache.store(key, choice);
        ChosenRequest chosen{request, choice.toJson(), choice.cancelled};
        chosen.request.settings = choice.chosen.applyTo(request.settings);
        if (choice.cancelled)
            return chosen; // runHeadless says so
        if (choice.rows.empty() && choice.unprepared > 0)
            spdlog::info("--strategy auto: preparing the candidates passed the default's bound, {:.2f} s (a fifth of "
                         "the render's estimated {:.1f} s, at most --pilot-max-seconds; a given --strategy auto has "
                         "none), after {:.2f} s, before any but the scene's own: it stays, {}",
                         choice.prepareBoundSeconds, choice.estimatedRenderSeconds, choice.prepareSeconds,
                         choice.chosen.name());
        else if (choice.tooShort)
            spdlog::info("--strategy auto: the render is too short to choose for (its pilot's budget, {:.3f} s, gives "
                         "each candidate fewer than {:.0f} paths a half): the scene's own, {}",
                         choice.budgetSeconds, kMinimumPilotPaths, choice.chosen.name());
        else if (choice.rows.empty())
            spdlog::info("--strategy auto: the flags leave one candidate, {}", choice.chosen.name());
        else
            spdlog::info("--strategy auto: {} (pilot {:.2f} s, {:.2f} s of it preparing the candidates{}, of a {:.2f} "
                         "s budget{}, {}x{} at {} spp per candidate; render estimated at {:.1f} s):\n{}",
                         choice.chosen.name(), choice.pilotWallSeconds, choice.prepareSeconds,
                         choice.unprepared > 0 ? fmt::format(" ({} more left out: the default's bound on it, {:.2f} s)",
                                                             choice.unprepared, choice.prepareBoundSeconds)
                                               : std::string(),
                         choice.budgetSeconds, choice.budgetSpent ? ", stopped there before every candidate" : "",
                         choice.width, choice.height, choice.spp, choice.estimatedRenderSeconds, choice.table());
        return chosen;
    };
}
} // namespace rt::compare
