// --strategy auto on the command line of either app: the candidates its flags leave open, and the chooser the
// headless run calls once the engine has the scene (Cli/HeadlessRun.h), which runs the pilot (AutoStrategy.h),
// logs its table and records it for --stats.
#pragma once

#include "Cli/CommonOptions.h"
#include "Cli/HeadlessRun.h"
#include "Compare/AutoStrategy.h"

namespace rt::compare
{
/// The candidates of `options` for `scene`: autoCandidates with every strategy setting given as a flag (--pdf
/// included) fixed, and `lists` (--compare's) where given.
StrategyLists commandLineCandidates(const Scene& scene, const CommonOptions& options, const StrategyLists& lists = {});

/// The strategy settings given as flags (--pdf as the estimator): names of the settings table, which no pilot of the
/// process varies (the windows' included).
std::vector<std::string> fixedSettings(const CommonOptions& options);

/// The pilot budget of --pilot-budget and --pilot-max-seconds.
PilotBudget pilotBudget(const CommonOptions& options);

/// The default --strategy auto's PilotBudget::prepareFraction: a GPU's candidates compiled in at most a fifth of the
/// render's estimated time (or --pilot-max-seconds).
inline constexpr double kDefaultPrepareFraction = 0.2;

/// For runHeadless: the pilot's choice with --strategy auto (the default's preparation bounded by
/// kDefaultPrepareFraction), nothing (render as asked) with --strategy scene.
RequestChooser strategyChooser(const Scene& scene, const CommonOptions& options);
} // namespace rt::compare
