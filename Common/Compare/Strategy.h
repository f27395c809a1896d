// A light-sampling strategy of a comparison: the settings --compare varies beside the spp (estimator, light
// sampler, light selection, pixel sampling, Russian roulette), the rest of a render held fixed.
#pragma once

#include <string>
#include <vector>

#include "Render/RenderRequest.h"
#include "Render/RenderSettings.h"

namespace rt::compare
{
struct Strategy
{
    Estimator estimator = Estimator::NeeMis;
    LightSampler lightSampler = LightSampler::Projected;
    LightSelection lightSelection = LightSelection::Bvh;
    PixelSampling sampling = PixelSampling::Random;
    bool russianRoulette = true;

    bool operator==(const Strategy&) const = default;

    static Strategy of(const RenderSettings& settings);
    /// `base` with this strategy's fields.
    RenderSettings applyTo(RenderSettings base) const;
    /// `base` with this strategy's fields and `spp` samples per pixel: one render of a comparison.
    RenderRequest request(RenderRequest base, int spp) const;
    /// "nee-mis projected bvh random rr-on": every field, space separated (the CSV's strategy column).
    std::string name() const;
};

/// The lists of --estimators, --light-samplers, --light-selections, --samplings, --roulettes: comma separated
/// names, each empty for "the base request's value".
struct StrategyLists
{
    std::string estimators;
    std::string lightSamplers;
    std::string lightSelections;
    std::string samplings;
    std::string roulettes;
};

/// Every combination of the lists (in list order, estimators outermost), the base's value where a list is
/// empty. Combinations that differ only in what their estimator does not use (the light sampler and selection
/// of bsdf, the selection of the mixture, which picks lights uniformly) are kept once. Throws UsageError naming
/// the flag and the bad name.
std::vector<Strategy> strategyGrid(const StrategyLists& lists, const RenderSettings& base);

/// The shortest labels that tell the strategies apart: only the fields that vary among them ("mixture",
/// "nee-mis projected"), or the estimator's name when there is one strategy.
std::vector<std::string> distinctLabels(const std::vector<Strategy>& strategies);
} // namespace rt::compare
