#include "Compare/StrategyCache.h"

#include <system_error>

#include <spdlog/spdlog.h>

#include "Compare/CacheEntry.h"
#include "Compare/Fnv1a.h"
#include "Compare/ReferenceCache.h"
#include "IO/AtomicFile.h"
#include "Render/SettingsTable.h"

namespace rt::compare
{
namespace
{
/// The running program's file, by size and modification time ("" where the platform does not tell): a rebuild is
/// another program, whose speeds the pilot has not measured.
std::string programIdentity()
{
    std::error_code error;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
    if (error)
        return {};
    const auto size = std::filesystem::file_size(exe, error);
    if (error)
        return {};
    const auto time = std::filesystem::last_write_time(exe, error);
    if (error)
        return {};
    return fmt::format("{} {} {}", exe.string(), size, time.time_since_epoch().count());
}
} // namespace

std::filesystem::path defaultStrategyCacheDir() { return cacheFolder("RT_STRATEGY_CACHE", "strategies"); }

std::string StrategyCache::key(const Scene& scene, const RenderRequest& request, const RenderEngine& engine,
                               const StrategyLists& candidates, const PilotBudget& budget)
{
    RenderRequest unseeded = request;
    unseeded.settings.seed = 0; // a choice holds for every seed
    nlohmann::json k = nlohmann::json::parse(ReferenceCache::key(scene, unseeded, engine.kind()));
    k["version"] = 1;
    k["device"] = engine.deviceName();
    k["program"] = programIdentity();
    k["candidates"] = nlohmann::json::object();
    for (const auto& [flag, list] : candidates)
        k["candidates"][flag] = list;
    k["budget"] = {budget.fraction, budget.maxSeconds, budget.renderSeconds, budget.prepareFraction};
    return k.dump();
}

std::optional<CachedChoice> StrategyCache::find(const std::string& key) const
{
    if (m_dir.empty())
        return std::nullopt;
    const std::filesystem::path file = m_dir / (fnv1aHex(key) + ".json");
    const std::optional<nlohmann::json> entry = readCacheEntry(file, key);
    if (!entry || !entry->contains("chosen_settings") || !(*entry)["chosen_settings"].is_object() ||
        !entry->contains("record") || !(*entry)["record"].is_object())
        return std::nullopt; // none, a hash collision or a damaged entry: the pilot runs again
    const nlohmann::json& stored = *entry;
    CachedChoice found{Strategy{}, stored["record"], file};
    try
    {
        for (const Setting* s : strategySettings())
            if (const auto it = stored["chosen_settings"].find(std::string(s->name)); it != stored["chosen_settings"].end())
                s->set(found.chosen.settings, it->get<std::string>(), s->name);
            else
                return std::nullopt;
    }
    catch (const std::exception& e)
    {
        spdlog::warn("strategy cache: {}: {}: the pilot runs again", file.string(), e.what());
        return std::nullopt;
    }
    return found;
}

void StrategyCache::store(const std::string& key, const AutoChoice& choice) const
{
    if (m_dir.empty() || choice.cancelled || choice.budgetSpent || choice.unprepared > 0)
        return;
    nlohmann::json chosen = nlohmann::json::object();
    for (const Setting* s : strategySettings())
        chosen[std::string(s->name)] = s->text(choice.chosen.settings);
    try
    {
        std::filesystem::create_directories(m_dir);
        writeFileAtomically(m_dir / (fnv1aHex(key) + ".json"),
                            nlohmann::json{{"key", nlohmann::json::parse(key)},
                                           {"chosen_settings", chosen},
                                           {"record", choice.toJson()}}
                                    .dump(2) +
                                "\n");
    }
    catch (const std::exception& e)
    {
        spdlog::warn("strategy cache: could not store the choice in {}: {}", m_dir.string(), e.what());
    }
}
} // namespace rt::compare
