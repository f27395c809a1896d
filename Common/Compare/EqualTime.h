// The equal-time comparison: each strategy rendered on one engine for the same time budget (its spp found by
// a short calibration render, corrected up to three times while a render misses the budget by more than
// 15 %), then one figure of the reference, every image and every error image (scripts/equal_time_grid.py).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "Compare/Measurement.h"
#include "Compare/Strategy.h"

namespace rt::compare
{
struct EqualTimeTile
{
    EngineKind engine = EngineKind::Gpu;
    std::string label;
    Strategy strategy;
    Measurement result;
};

/// The spp that should take `budgetMs` at `msPerSample` per spp: at least 1, at most INT_MAX.
int sppForBudget(double budgetMs, double msPerSample);

/// Renders `strategy` of `base` with `engine` for about `budgetMs` (GPU time where the engine has it).
/// Returns a cancelled measurement when Ctrl-C stopped it.
Measurement renderForBudget(RenderEngine& engine, const RenderRequest& base, const Strategy& strategy,
                            double budgetMs, const Image& reference);

struct GridCaption
{
    std::string scene;
    std::string device;
    double budgetMs = 0.0;
    int referenceSpp = 0;
};

/// Writes the figure to `png` (atomically): the tiles' images go to a temporary folder as PFMs, the script
/// draws them. Throws OutputError when the script fails.
void writeEqualTimeGrid(const std::filesystem::path& png, const GridCaption& caption, const Image& reference,
                        const std::vector<EqualTimeTile>& tiles);
} // namespace rt::compare
