// A light-sampling strategy of a comparison: the settings --compare varies beside the spp (the settings table's
// entries with a compareFlag: estimator, light sampler, light selection, pixel sampling, Russian roulette), the
// rest of a render held fixed.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "Render/RenderRequest.h"
#include "Render/RenderSettings.h"

namespace rt
{
struct Setting; // Render/SettingsTable.h
}

namespace rt::compare
{
struct Strategy
{
    RenderSettings settings; // only the strategy settings (strategySettings()) take part

    /// The strategy settings equal.
    bool operator==(const Strategy& other) const;

    static Strategy of(const RenderSettings& settings);
    /// `base` with this strategy's settings.
    RenderSettings applyTo(RenderSettings base) const;
    /// `base` with this strategy's settings and `spp` samples per pixel: one render of a comparison.
    RenderRequest request(RenderRequest base, int spp) const;
    /// "nee-mis projected bvh random rr-on": every strategy setting, space separated (the CSV's strategy column).
    std::string name() const;
};

/// --compare's lists by flag ("--estimators" -> "bsdf,nee-mis"): comma separated words; a flag absent or empty
/// stands for the base request's value.
using StrategyLists = std::map<std::string, std::string, std::less<>>;

/// The words of `setting`'s list, checked and without repeats, or the base's word when the list is absent or empty.
/// Throws UsageError naming the flag and the bad word, or an empty entry.
std::vector<std::string> listedWords(const StrategyLists& lists, const Setting& setting, const RenderSettings& base);

/// Every combination of the lists (in the settings table's order, estimators outermost), the base's value where a
/// list is empty. Combinations that differ only in what their estimator does not use (the light sampler and
/// selection of bsdf and of the mixture, which keeps book 3's) are kept once. Throws UsageError naming the flag and
/// the bad word.
std::vector<Strategy> strategyGrid(const StrategyLists& lists, const RenderSettings& base);

/// The shortest labels that tell the strategies apart: only the settings that vary among them and that the
/// strategy uses ("mixture", "nee-mis projected"), or the estimator's name when nothing varies.
std::vector<std::string> distinctLabels(const std::vector<Strategy>& strategies);
} // namespace rt::compare
