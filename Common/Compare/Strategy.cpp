#include "Compare/Strategy.h"

#include <algorithm>
#include <optional>

#include <spdlog/fmt/fmt.h>

#include "Cli/ValueParsing.h"
#include "Error.h"
#include "Shared/Estimator.h"

namespace rt::compare
{
namespace
{
/// The values of a comma-separated list, or {fallback} when it is empty.
template <typename T, typename Parse>
std::vector<T> parseList(const std::string& text, const char* flag, const char* names, T fallback, Parse parse)
{
    if (text.empty())
        return {fallback};
    std::vector<T> values;
    for (const std::string& part : splitCommas(text))
    {
        const std::optional<T> value = parse(part);
        if (!value)
            throw UsageError(fmt::format("{} takes {} separated by commas (got '{}')", flag, names, part));
        if (std::find(values.begin(), values.end(), *value) == values.end())
            values.push_back(*value);
    }
    if (values.empty() || text.back() == ',')
        throw UsageError(fmt::format("{} has an empty entry (got '{}')", flag, text));
    return values;
}
} // namespace

Strategy Strategy::of(const RenderSettings& s)
{
    return {s.estimator, s.lightSampler, s.lightSelection, s.sampling, s.russianRoulette};
}

RenderSettings Strategy::applyTo(RenderSettings base) const
{
    base.estimator = estimator;
    base.lightSampler = lightSampler;
    base.lightSelection = lightSelection;
    base.sampling = sampling;
    base.russianRoulette = russianRoulette;
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
    return fmt::format("{} {} {} {} rr-{}", toString(estimator), toString(lightSampler), toString(lightSelection),
                       toString(sampling), russianRoulette ? "on" : "off");
}

std::vector<Strategy> strategyGrid(const StrategyLists& lists, const RenderSettings& base)
{
    const auto estimators = parseList(lists.estimators, "--estimators", "bsdf, mixture, nee and nee-mis",
                                      base.estimator, parseEstimator);
    const auto samplers = parseList(lists.lightSamplers, "--light-samplers", "area, solid-angle and projected",
                                    base.lightSampler, parseLightSampler);
    const auto selections = parseList(lists.lightSelections, "--light-selections", "uniform, power and bvh",
                                      base.lightSelection, parseLightSelection);
    const auto samplings = parseList(lists.samplings, "--samplings", "random, stratified, accumulate and sobol",
                                     base.sampling, parsePixelSampling);
    const auto roulettes = parseList(lists.roulettes, "--roulettes", "on and off", base.russianRoulette,
                                     [](const std::string& t) { return parseOnOff(t); });
    std::vector<Strategy> grid;
    for (const Estimator e : estimators)
        for (const LightSampler ls : samplers)
            for (const LightSelection sel : selections)
                for (const PixelSampling sm : samplings)
                    for (const bool rr : roulettes)
                    {
                        // Only NEE samples and selects lights: keep the first of the others' duplicates.
                        const Strategy s{e, shader::usesNee(e) ? ls : samplers.front(),
                                         shader::usesNee(e) ? sel : selections.front(), sm, rr};
                        if (std::find(grid.begin(), grid.end(), s) == grid.end())
                            grid.push_back(s);
                    }
    return grid;
}

std::vector<std::string> distinctLabels(const std::vector<Strategy>& strategies)
{
    const auto varies = [&](auto field) {
        return std::any_of(strategies.begin(), strategies.end(),
                           [&](const Strategy& s) { return field(s) != field(strategies.front()); });
    };
    const bool estimator = varies([](const Strategy& s) { return s.estimator; });
    const bool sampler = varies([](const Strategy& s) { return s.lightSampler; });
    const bool selection = varies([](const Strategy& s) { return s.lightSelection; });
    const bool sampling = varies([](const Strategy& s) { return s.sampling; });
    const bool roulette = varies([](const Strategy& s) { return s.russianRoulette; });
    std::vector<std::string> labels;
    for (const Strategy& s : strategies)
    {
        std::vector<std::string> parts;
        if (estimator || !(sampler || selection || sampling || roulette))
            parts.emplace_back(toString(s.estimator));
        if (sampler && shader::usesNee(s.estimator))
            parts.emplace_back(toString(s.lightSampler));
        if (selection && shader::usesNee(s.estimator))
            parts.emplace_back(toString(s.lightSelection));
        if (sampling)
            parts.emplace_back(toString(s.sampling));
        if (roulette)
            parts.push_back(s.russianRoulette ? "rr-on" : "rr-off");
        labels.push_back(fmt::format("{}", fmt::join(parts, " ")));
    }
    return labels;
}
} // namespace rt::compare
