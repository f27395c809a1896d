#include "Compare/Strategy.h"

#include <algorithm>

#include <spdlog/fmt/fmt.h>
#include <spdlog/fmt/ranges.h>

#include "Cli/ValueParsing.h"
#include "Error.h"
#include "Render/SettingsTable.h"

namespace rt::compare
{
std::vector<std::string> listedWords(const StrategyLists& lists, const Setting& setting, const RenderSettings& base)
{
    const auto it = lists.find(setting.compareFlag);
    if (it == lists.end() || it->second.empty())
        return {setting.text(base)};
    const std::string& text = it->second;
    std::vector<std::string> words;
    for (const std::string& word : splitCommas(text))
    {
        if (!setting.accepts(word))
            throw UsageError(fmt::format("{} takes {} separated by commas (got '{}')", setting.compareFlag,
                                         setting.expected(), word));
        if (std::find(words.begin(), words.end(), word) == words.end())
            words.push_back(word);
    }
    if (words.empty() || text.back() == ',')
        throw UsageError(fmt::format("{} has an empty entry (got '{}')", setting.compareFlag, text));
    return words;
}

namespace
{
/// The word a label shows for `setting`: the value's, or TAG-on / TAG-off.
std::string labelWord(const Setting& setting, const RenderSettings& s)
{
    if (setting.name == "estimator")
        return estimatorLabel(s);
    const std::string word = setting.text(s);
    return setting.compareTag.empty() ? word : fmt::format("{}-{}", setting.compareTag, word);
}
} // namespace

bool Strategy::operator==(const Strategy& other) const
{
    const auto settingsList = strategySettings();
    return std::all_of(settingsList.begin(), settingsList.end(), [&](const Setting* s) {
        return s->text(settings) == s->text(other.settings);
    });
}

Strategy Strategy::of(const RenderSettings& s)
{
    Strategy x;
    for (const Setting* setting : strategySettings())
        setting->copy(x.settings, s);
    return x;
}

RenderSettings Strategy::applyTo(RenderSettings base) const
{
    for (const Setting* s : strategySettings())
        s->copy(base, settings);
    return base;
}

RenderRequest Strategy::request(RenderRequest base, int spp) const
{
    base.settings = applyTo(base.settings);
    base.settings.spp = spp;
    return base;
}

std::string Strategy::name() const
{
    std::vector<std::string> words;
    for (const Setting* s : strategySettings())
        words.push_back(labelWord(*s, settings));
    return fmt::format("{}", fmt::join(words, " "));
}

std::vector<Strategy> strategyGrid(const StrategyLists& lists, const RenderSettings& base)
{
    const std::vector<const Setting*> varied = strategySettings();
    for (const auto& [flag, text] : lists)
        if (std::none_of(varied.begin(), varied.end(), [&](const Setting* s) { return s->compareFlag == flag; }))
            throw UsageError(fmt::format("--compare varies no setting by '{}'", flag));
    // Every combination, later settings varying fastest.
    std::vector<RenderSettings> combinations{base};
    std::vector<std::vector<std::string>> words;
    for (const Setting* s : varied)
    {
        words.push_back(listedWords(lists, *s, base));
        std::vector<RenderSettings> next;
        for (const RenderSettings& c : combinations)
            for (const std::string& word : words.back())
            {
                RenderSettings v = c;
                s->assign(*s, v, word);
                next.push_back(v);
            }
        combinations = std::move(next);
    }
    std::vector<Strategy> grid;
    for (RenderSettings c : combinations)
    {
        // What the strategy does not use takes its list's first word: the others' duplicates go.
        for (std::size_t i = 0; i < varied.size(); ++i)
            if (!varied[i]->used(c))
                varied[i]->assign(*varied[i], c, words[i].front());
        const Strategy s = Strategy::of(c);
        if (std::find(grid.begin(), grid.end(), s) == grid.end())
            grid.push_back(s);
    }
    return grid;
}

std::vector<std::string> distinctLabels(const std::vector<Strategy>& strategies)
{
    const std::vector<const Setting*> varied = strategySettings();
    std::vector<const Setting*> shown;
    for (const Setting* s : varied)
        if (std::any_of(strategies.begin(), strategies.end(), [&](const Strategy& x) {
                return s->text(x.settings) != s->text(strategies.front().settings);
            }))
            shown.push_back(s);
    if (shown.empty())
        shown.push_back(&setting("estimator"));
    std::vector<std::string> labels;
    for (const Strategy& x : strategies)
    {
        std::vector<std::string> parts;
        for (const Setting* s : shown)
            if (s->used(x.settings))
                parts.push_back(labelWord(*s, x.settings));
        labels.push_back(fmt::format("{}", fmt::join(parts, " ")));
    }
    return labels;
}
} // namespace rt::compare
