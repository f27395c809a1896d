#include "App/Gui/TimingsTable.h"

#include <algorithm>

namespace rt::gui
{
void TimingsTable::record(const RenderStats& stats, const WindowRedraws& redraws)
{
    const RenderSettings& s = stats.request.settings;
    const TimingKey key{.scene = stats.request.scene,
                        .width = stats.width,
                        .height = stats.height,
                        .spp = stats.trueSpp,
                        .depth = s.depth,
                        .sampling = s.sampling,
                        .estimator = s.estimator,
                        .lightSampler = s.lightSampler,
                        .lightSelection = s.lightSelection,
                        .russianRoulette = s.russianRoulette,
                        .unidirectionalLight = s.unidirectionalLight};
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
    m_latest = std::size_t(row - m_rows.begin());
    ++m_revision;
}

nlohmann::json TimingsTable::toJson() const
{
    nlohmann::json out = nlohmann::json::array();
    for (const TimingRow& row : m_rows)
        for (std::size_t e = 0; e < row.engines.size(); ++e)
            if (const auto& cell = row.engines[e])
                out.push_back({{"scene", row.key.scene.id},
                               {"count", row.key.scene.options.count},
                               {"mesh", row.key.scene.options.meshPath},
                               {"width", row.key.width},
                               {"height", row.key.height},
                               {"spp", row.key.spp},
                               {"depth", row.key.depth},
                               {"sampling", toString(row.key.sampling)},
                               {"estimator", toString(row.key.estimator)},
                               {"light_sampler", toString(row.key.lightSampler)},
                               {"light_selection", toString(row.key.lightSelection)},
                               {"russian_roulette", row.key.russianRoulette},
                               {"unidirectional_light", row.key.unidirectionalLight},
                               {"engine", toString(EngineKind(e))},
                               {"seconds", cell->lastSeconds},
                               {"best_seconds", cell->bestSeconds},
                               {"mpaths_per_second", cell->mpathsPerSecond},
                               {"renders", cell->renders},
                               {"device", cell->device},
                               {"window_redraws", cell->redraws.total},
                               {"window_redraws_on_input", cell->redraws.onInput}});
    return out;
}
} // namespace rt::gui
