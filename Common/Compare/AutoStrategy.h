// --strategy auto: the light-sampling strategy (estimator x light sampler x light selection; pixel sampling where asked)
// chosen for a scene by measurement on the engine that will render it, since which one wins depends on the
// scene, the engine and the build (issue 37: the project's own tables changed their verdict as the code got
// faster).
//
// The pilot: a probe render of the scene's strategy times a path and so estimates the render; the budget is a
// fraction of that estimate (5 % by default), at most a few seconds. Then a coordinate search: one setting at a
// time (in the settings table's order), every candidate value rendered with the others at the best found so far,
// each as two independent halves of the same small render (the pilot's size and spp are the same for every
// candidate, so that their images combine: about 1024 pixels, the rest of the budget as spp).
//
// A candidate's error is the variance of its estimate from its halves (Image/Metrics.h's two-half estimate), as
// relMSE; where its relMSE against the other candidates' combined estimate (weighted by their inverse errors), less
// that combination's own noise, is higher by more than twice its standard error, that instead: a bias the halves
// cannot see. relMSE's denominator is the others' estimate blurred over 5 x 5 pixels, never the candidate's own
// image (a firefly over itself is about 1). Its efficiency is 1 / (relMSE x seconds), twice the faster half's time
// on the engine's clock (Compare/Measurement.h). The most efficient candidate measured wins, where its lead over
// the best before it is more than twice the standard error of their ratio: otherwise the scene's own strategy
// (where the search starts) stays.
//
// The choice depends on timings, so two runs may choose differently where candidates are close: the record names
// the strategy chosen, and giving its flags renders it again, bit for bit.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "Compare/Strategy.h"
#include "Image/Image.h"
#include "Render/RenderEngine.h"
#include "Render/RenderRequest.h"
#include "Scene/Scene.h"

namespace rt::compare
{
struct PilotBudget
{
    double fraction = 0.05; // of the render's estimated time
    double maxSeconds = 2.0; // at most, whatever the render
    double renderSeconds = 0.0; // > 0: the render's time, known (--compare --equal-time), instead of the estimate
};

/// One candidate the pilot rendered.
struct PilotRow
{
    Strategy strategy;
    std::string varied; // the setting its stage varied ("estimator"); empty for a pilot of one candidate
    double ms = 0.0; // both halves: twice the faster half's, on the engine's clock (Measurement::ms)
    /// Its relMSE at the pilot's size and spp (both halves together), against the other candidates' combined
    /// estimate, that estimate's own noise removed (see above).
    double relMse = 0.0;
    double relMseError = 0.0; // relMse's standard error (over the pixels' terms)
    double efficiency = 0.0; // 1 / (relMse x seconds)
    bool tooSlow = false; // a half ran past 4x its share of the budget and was stopped: efficiency 0
};

/// What the pilot measured and chose: --stats' "strategy_choice", the log's table, --compare's auto row.
struct AutoChoice
{
    Strategy chosen;
    int width = 0; // the pilot's image
    int height = 0;
    int spp = 0; // per candidate, both halves together
    double estimatedRenderSeconds = 0.0; // from the probe
    double budgetSeconds = 0.0;
    double pilotMs = 0.0; // the probe's and every candidate's render time, on the engine's clock
    double pilotWallSeconds = 0.0; // the whole pilot on the host's clock (GPU pipelines compiled included)
    std::vector<PilotRow> rows; // in the order measured
    bool cancelled = false; // Ctrl-C stopped the pilot

    nlohmann::json toJson() const;
    /// The table of rows, one per line, the chosen one marked: what the headless run logs.
    std::string table() const;
};

/// The values auto may choose among, by --compare's list flag ("--estimators" -> "nee-mis,nee"): `given` where it
/// names a list, else the defaults for the scene, of which a setting given on the command line (`fixed`, by
/// setting name: "estimator") keeps only its value. The defaults: every estimator; area, solid-angle and projected
/// light sampling, and projected-exact where the scene has quad or triangle lights (on spheres it is projected),
/// none but the request's when it has no emitter; every light selection where the scene has two emitters or more.
/// The pixel sampling and Russian roulette stay the request's: Sobol's gain over random grows with the spp, and a
/// pilot of a few samples per pixel cannot measure what the render's many will gain (a list given varies them).
StrategyLists autoCandidates(const Scene& scene, const StrategyLists& given, const std::vector<std::string>& fixed);

/// Runs the pilot for `request` (whose strategy settings start the search) on `engine`, whose scene is set to
/// `scene`, over `candidates` (autoCandidates' form; a setting without a list keeps the request's value).
/// Cancellable by Ctrl-C while an InterruptScope lives (Cli/Interrupt.h): then `cancelled` is set and `chosen` is
/// the request's. Throws UsageError for a bad candidate word, what the engine throws.
AutoChoice chooseStrategy(RenderEngine& engine, const RenderRequest& request, const StrategyLists& candidates,
                          const PilotBudget& budget = {});

/// A pilot candidate's two independent halves (the same size).
struct PilotHalves
{
    Image a;
    Image b;
};

struct PilotError
{
    double relMse = 0.0;
    double standardError = 0.0; // of relMse, from the spread of its pixels' terms
};

/// The pilot's error of each candidate (see above: its halves' variance, or its relMSE against the others' combined
/// estimate less that estimate's noise where that is significantly higher). One candidate: its own variance. Every image the same
/// size; throws UsageError otherwise.
std::vector<PilotError> pilotRelMse(const std::vector<PilotHalves>& candidates);
} // namespace rt::compare
