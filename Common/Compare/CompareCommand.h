// `--compare` on the command line of either app (Compare.h): its flags, and the run that renders on the engines
// the program links (Render/EngineRegistry.h) with the app's engine options. So ray-tracing-cpu offers it with
// single and multi (and gpu where it links the GPU engine), ray-tracing-gpu with all three, from one code.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "Cli/CommonOptions.h"
#include "Compare/Strategy.h"
#include "Render/EngineOptions.h"

namespace rt::compare
{
/// --compare's seeds per row where a strategy is restir-di and --seeds is not given.
inline constexpr int kRestirSeeds = 4;

/// What the --compare flags set.
struct CompareFlags
{
    bool compare = false;
    std::string sppList = "10,50,100";
    std::string engines; // empty: every engine the program links
    long long referenceSpp = 0; // wider than an spp: a count past two renders' is refused by name, not by CLI11
    std::string referencePath;
    std::string table;
    StrategyLists strategies;
    std::string csv;
    std::string plot;
    double equalTimeMs = 0.0;
    std::string referenceCache;
    std::string images;
    int seeds = 0; // 0: 1, or kRestirSeeds where a strategy is restir-di
    int rounds = 3;
    std::string metric = "relmse";
};

/// Adds --compare and the flags that go with it to `app`.
void addCompareOptions(CLI::App& app, CompareFlags& flags);

/// Runs the comparison the flags and the common options ask for (the scene, the base settings, --output for the
/// equal-time figure) on engines made with `engineOptions`. Returns the process status (Compare.h's
/// runComparison). Throws rt::Error subclasses for bad input.
int runCompare(const CompareFlags& flags, const CommonOptions& options, const EngineOptions& engineOptions);
} // namespace rt::compare
