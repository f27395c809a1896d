#include "App/Gui/TimingsTable.h"

#include <algorithm>

namespace rt::gui
{
TimingKey TimingKey::of(const RenderRequest& request)
{
    TimingKey key{.scene = request.scene, .settings = request.settings};
    key.settings.spp = request.settings.trueSpp();
    key.settings.seed = 0;
    return key;
}

std::vector<const Setting*> timingColumns()
{
    std::vector<const Setting*> out;
    for (const Setting& s : settingsTable())
        if (s.name != "width" && s.name != "aspect" && s.name != "seed")
            out.push_back(&s);
    return out;
}

void TimingsTable::record(const RenderStats& stats, const WindowRedraws& redraws)
{
    const TimingKey key = TimingKey::of(stats.request);
    auto row = std::find_if(m_rows.begin(), m_rows.end(), [&](const TimingRow& r) { return r.key == key; });
    if (row == m_rows.end())
        row = m_rows.insert(m_rows.end(), TimingRow{.key = key});
    auto& cell = row->engines[std::size_t(stats.engine)];
    const double seconds = stats.renderSeconds;
    if (!cell)
        cell = EngineTiming{.bestSeconds = seconds};
    cell->lastSeconds = seconds;
    cell->bestSeconds = std::min(cell->bestSeconds, seconds);
    cell->mpathsPerSecond = stats.mpathsPerSecond();
    cell->renders += 1;
    cell->device = stats.device;
    cell->redraws = redraws;
    cell->buildSeconds = stats.buildSeconds;
    cell->compileSeconds.reset();
    if (const auto compile = stats.stageSeconds.find("pipeline_host"); compile != stats.stageSeconds.end())
        cell->compileSeconds = compile->second;
    m_latest = std::size_t(row - m_rows.begin());
    ++m_revision;
}

nlohmann::json TimingsTable::toJson() const
{
    nlohmann::json out = nlohmann::json::array();
    for (const TimingRow& row : m_rows)
        for (std::size_t e = 0; e < row.engines.size(); ++e)
            if (const auto& cell = row.engines[e])
            {
                nlohmann::json entry = rt::toJson(row.key.settings);
                entry.erase("seed");
                entry.update(nlohmann::json{{"scene", row.key.scene.id},
                                            {"count", row.key.scene.options.count},
                                            {"mesh", row.key.scene.options.meshPath},
                                            {"height", row.key.settings.height()},
                                            {"engine", toString(EngineKind(e))},
                                            {"seconds", cell->lastSeconds},
                                            {"best_seconds", cell->bestSeconds},
                                            {"mpaths_per_second", cell->mpathsPerSecond},
                                            {"renders", cell->renders},
                                            {"device", cell->device},
                                            {"window_redraws", cell->redraws.total},
                                            {"window_redraws_on_input", cell->redraws.onInput},
                                            {"build_seconds", cell->buildSeconds},
                                            {"compiled", cell->compileSeconds.has_value()},
                                            {"compile_seconds", cell->compileSeconds ? nlohmann::json(*cell->compileSeconds)
                                                                                     : nlohmann::json()}});
                out.push_back(std::move(entry));
            }
    return out;
}
} // namespace rt::gui
