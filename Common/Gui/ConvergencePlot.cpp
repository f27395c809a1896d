#include "Gui/ConvergencePlot.h"

#include <algorithm>

#include "Compare/ReferenceRequest.h"
#include "Gui/EngineLabel.h"
#include "Image/Metrics.h"
#include "Render/SettingsTable.h"

namespace rt::gui
{
TimingKey plotWork(const RenderRequest& request)
{
    TimingKey work = TimingKey::of(request);
    work.settings.spp = 0;
    return work;
}

namespace
{
std::vector<std::string> strategyWords(const RenderSettings& settings)
{
    std::vector<std::string> words;
    for (const Setting* s : strategySettings())
        words.push_back(s->text(settings));
    return words;
}

/// "nee-mis projected bvh sobol sqrt": the strategy words, as the command line spells them.
std::string strategyText(const RenderSettings& settings)
{
    std::string text;
    for (const std::string& word : strategyWords(settings))
        text += (text.empty() ? "" : " ") + word;
    return text;
}

/// The strategy words in which `lines` differ, per line.
std::vector<std::string> distinctWords(const std::vector<const PlotLine*>& lines)
{
    std::vector<std::vector<std::string>> words;
    for (const PlotLine* line : lines)
        words.push_back(strategyWords(line->work.settings));
    std::vector<std::string> out(lines.size());
    for (std::size_t w = 0; !words.empty() && w < words[0].size(); ++w)
    {
        const bool differ = std::any_of(words.begin(), words.end(), [&](const auto& l) { return l[w] != words[0][w]; });
        for (std::size_t i = 0; differ && i < lines.size(); ++i)
            out[i] += (out[i].empty() ? "" : " ") + words[i][w];
    }
    return out;
}
} // namespace

std::vector<std::string> shortLabels(const std::vector<const PlotLine*>& lines)
{
    std::vector<std::string> out = distinctWords(lines);
    for (std::size_t i = 0; i < lines.size(); ++i)
        out[i] = std::string(rt::toString(lines[i]->engine)) + (out[i].empty() ? "" : " " + out[i]);
    return out;
}

std::string PlotLine::label() const
{
    return std::string(engineLabel(engine)) + ": " + strategyText(work.settings);
}

std::optional<ReferenceTask> ConvergencePlot::add(const RenderRequest& request, EngineKind engine,
                                                  const std::string& device, double seconds, int spp,
                                                  std::shared_ptr<const Image> image, EngineKind referenceEngine,
                                                  bool loopMean)
{
    const long long referenceSpp = static_cast<long long>(compare::kDefaultReferenceFactor) * spp;
    if (referenceSpp > 2LL * kMaxSpp)
        return std::nullopt;
    const TimingKey work = plotWork(request);
    auto line = std::find_if(m_lines.begin(), m_lines.end(),
                             [&](const PlotLine& l) { return l.work == work && l.engine == engine; });
    if (line == m_lines.end())
        line = m_lines.insert(m_lines.end(), PlotLine{.work = work, .engine = engine});
    line->device = device;
    PlotPoint point{.seconds = seconds,
                    .spp = spp,
                    .loopMean = loopMean,
                    .reference = {.base = request, .engine = referenceEngine, .spp = int(referenceSpp)},
                    .unmeasured = std::move(image)};
    line->points.push_back(std::move(point));
    return line->points.back().reference;
}

void ConvergencePlot::attach(const FinishedReference& reference)
{
    for (PlotLine& line : m_lines)
        for (PlotPoint& point : line.points)
            if (point.unmeasured && point.reference == reference.task)
            {
                if (!reference.image) // failed: the point stays off the plot, and waits no more
                {
                    point.unmeasured.reset();
                    continue;
                }
                point.error = compareImages(*point.unmeasured, *reference.image);
                point.referenceRelMse = reference.ownRelMse;
                point.unmeasured.reset();
            }
}

std::vector<const PlotLine*> ConvergencePlot::linesOf(const RenderRequest& work) const
{
    const TimingKey key = plotWork(work);
    std::vector<const PlotLine*> out;
    for (const PlotLine& line : m_lines)
        if (line.work.scene == key.scene && line.work.camera == key.camera && line.work.settings.width == key.settings.width &&
            line.work.settings.height() == key.settings.height() && line.work.settings.depth == key.settings.depth)
            out.push_back(&line);
    return out;
}

nlohmann::json ConvergencePlot::toJson() const
{
    nlohmann::json out = nlohmann::json::array();
    for (const PlotLine& line : m_lines)
    {
        nlohmann::json points = nlohmann::json::array();
        for (const PlotPoint& p : line.points)
            points.push_back({{"seconds", p.seconds},
                              {"spp", p.spp},
                              {"rel_mse", p.error ? nlohmann::json(p.error->relMse) : nlohmann::json()},
                              {"reference_rel_mse", p.error ? nlohmann::json(p.referenceRelMse) : nlohmann::json()},
                              {"loop_mean", p.loopMean}});
        nlohmann::json entry = rt::toJson(line.work.settings);
        entry.erase("seed");
        entry.erase("spp");
        entry.update({{"label", line.label()},
                      {"scene", line.work.scene.id},
                      {"height", line.work.settings.height()},
                      {"engine", rt::toString(line.engine)},
                      {"device", line.device},
                      {"points", std::move(points)}});
        out.push_back(std::move(entry));
    }
    return out;
}

std::vector<compare::ConvergenceRow> ConvergencePlot::csvRows(const std::vector<const PlotLine*>& lines)
{
    std::vector<compare::ConvergenceRow> rows;
    const std::vector<std::string> labels = distinctWords(lines);
    for (std::size_t l = 0; l < lines.size(); ++l)
    {
        const PlotLine* line = lines[l];
        const std::string strategy = strategyText(line->work.settings);
        for (const PlotPoint& p : line->points)
            if (p.error)
                rows.push_back({.scene = line->work.scene.id,
                                .engine = rt::toString(line->engine),
                                .device = line->device,
                                .strategy = strategy,
                                .label = labels[l].empty() ? strategy : labels[l],
                                .spp = p.spp,
                                .wallMs = p.seconds * 1e3,
                                .mpathsPerSecond = p.seconds > 0.0 ? double(line->work.settings.width) *
                                                                         line->work.settings.height() * p.spp /
                                                                         p.seconds * 1e-6
                                                                   : 0.0,
                                .mse = p.error->mse,
                                .relMse = p.error->relMse,
                                .rmse = p.error->rmse,
                                .referenceRelMse = p.referenceRelMse,
                                .seed = p.reference.base.settings.seed,
                                .trimmedRelMse = p.error->trimmedRelMse,
                                .mape = p.error->mape});
    }
    return rows;
}
} // namespace rt::gui
