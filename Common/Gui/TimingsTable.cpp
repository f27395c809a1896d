#include "Gui/TimingsTable.h"

#include <algorithm>

#include "Compare/ReferenceRequest.h"
#include "Image/Metrics.h"

namespace rt::gui
{
TimingKey TimingKey::of(const RenderRequest& request)
{
    TimingKey key{.scene = request.scene, .settings = request.settings, .camera = request.camera};
    key.settings.spp = request.settings.trueSpp();
    key.settings.seed = 0;
    return key;
}

nlohmann::json cameraJson(const std::optional<CameraDesc>& camera)
{
    if (!camera)
        return nullptr;
    const auto xyz = [](const vec3& v) { return nlohmann::json{v.x, v.y, v.z}; };
    return {{"look_from", xyz(camera->lookFrom)},
            {"look_at", xyz(camera->lookAt)},
            {"vup", xyz(camera->vup)},
            {"vfov", camera->vfovDegrees}};
}

std::vector<const Setting*> timingColumns()
{
    std::vector<const Setting*> out;
    for (const Setting& s : settingsTable())
        if (s.name != "width" && s.name != "aspect" && s.name != "seed")
            out.push_back(&s);
    return out;
}

namespace
{
/// relMSE against the ready reference; the image waits in `cell` while it is not.
void measure(EngineTiming& cell, const std::optional<RowReference>& reference)
{
    if (reference && reference->state == RowReference::State::Failed)
        cell.unmeasured.reset(); // nothing will measure it
    if (!cell.unmeasured || !reference || reference->state != RowReference::State::Ready)
        return;
    cell.relMse = compareImages(*cell.unmeasured, *reference->image).relMse;
    cell.unmeasured.reset();
}

const char* stateName(RowReference::State state)
{
    switch (state)
    {
    case RowReference::State::Waiting: return "waiting";
    case RowReference::State::Ready: return "ready";
    case RowReference::State::Failed: return "failed";
    }
    return "?";
}

nlohmann::json orNull(const std::optional<double>& value)
{
    return value ? nlohmann::json(*value) : nlohmann::json();
}
} // namespace

void TimingsTable::record(const RenderStats& stats, const WindowRedraws& redraws, std::shared_ptr<const Image> image)
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
    cell->relMse.reset();
    cell->unmeasured = std::move(image);
    measure(*cell, row->reference);
    m_latest = std::size_t(row - m_rows.begin());
    m_latestRequest = stats.request;
    ++m_revision;
}

std::optional<ReferenceTask> TimingsTable::referenceWanted(std::optional<EngineKind> engine)
{
    if (m_latest >= m_rows.size() || m_rows[m_latest].reference)
        return std::nullopt;
    TimingRow& row = m_rows[m_latest];
    std::size_t fastest = std::size_t(EngineKind::Multi);
    double best = 0.0;
    for (std::size_t e = 0; e < row.engines.size(); ++e)
        if (row.engines[e] && row.engines[e]->mpathsPerSecond > best)
        {
            best = row.engines[e]->mpathsPerSecond;
            fastest = e == std::size_t(EngineKind::Single) ? std::size_t(EngineKind::Multi) : e;
        }
    const long long spp = static_cast<long long>(compare::kDefaultReferenceFactor) * row.key.settings.spp;
    ReferenceTask task{.base = m_latestRequest, .engine = engine.value_or(EngineKind(fastest)), .spp = int(std::min<long long>(spp, kMaxSpp))};
    row.reference = RowReference{.task = task};
    if (spp > 2LL * kMaxSpp) // two halves of at most kMaxSpp each, as --compare refuses it
    {
        row.reference->state = RowReference::State::Failed;
        row.reference->error = "its reference would pass two renders of the largest spp";
        return std::nullopt;
    }
    return task;
}

void TimingsTable::attach(const FinishedReference& reference)
{
    for (TimingRow& row : m_rows)
    {
        if (!row.reference || row.reference->state != RowReference::State::Waiting || row.reference->task != reference.task)
            continue;
        RowReference& r = *row.reference;
        r.state = reference.image ? RowReference::State::Ready : RowReference::State::Failed;
        r.image = reference.image;
        r.ownRelMse = reference.ownRelMse;
        r.fromCache = reference.fromCache;
        r.seconds = reference.seconds;
        r.error = reference.error;
        for (auto& cell : row.engines)
            if (cell)
                measure(*cell, row.reference);
    }
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
                                            {"camera", cameraJson(row.key.camera)},
                                            {"build_seconds", cell->buildSeconds},
                                            {"compiled", cell->compileSeconds.has_value()},
                                            {"compile_seconds", orNull(cell->compileSeconds)},
                                            {"rel_mse", orNull(cell->relMse)},
                                            {"efficiency", cell->relMse ? nlohmann::json(cell->efficiency())
                                                                        : nlohmann::json()}});
                if (const auto& r = row.reference)
                    entry["reference"] = {{"state", stateName(r->state)},
                                          {"spp", r->task.spp},
                                          {"engine", rt::toString(r->task.engine)},
                                          {"own_rel_mse", r->state == RowReference::State::Ready
                                                              ? nlohmann::json(r->ownRelMse)
                                                              : nlohmann::json()},
                                          {"from_cache", r->fromCache},
                                          {"seconds", r->seconds},
                                          {"error", r->error}};
                else
                    entry["reference"] = nullptr;
                out.push_back(std::move(entry));
            }
    return out;
}
} // namespace rt::gui
