// The headless comparison (thesis Table 5.4 redone honestly): one scene, the same settings and seed family on
// every engine (single core, multi core, GPU), a list of sample counts; for each, the render time of every
// engine, the CPU/GPU time ratio, and the error of every image against an independent high-spp reference.
#pragma once

#include <string>
#include <vector>

#include <functional>
#include <memory>

#include "Render/RenderEngine.h"
#include "Render/RenderRequest.h"

namespace rt::app
{
struct CompareOptions
{
    std::vector<int> spps; // sample counts, one table row each
    std::vector<EngineKind> engines; // columns, in order
    int referenceSpp = 0; // spp of the reference image (rendered by the last engine, seed + 1000)
    std::string referencePath; // a linear PFM to use as the reference instead of rendering one
    std::string json; // write every figure here when not empty
};

/// Parses "10,50,100" (positive integers). Throws UsageError.
std::vector<int> parseSppList(const std::string& text);
/// Parses "single,multi,gpu". Throws UsageError.
std::vector<EngineKind> parseEngineList(const std::string& text);

/// Renders and prints the table on stdout; returns the process status. Engines that cannot start (no Vulkan
/// ray-tracing device) are reported and left out rather than failing the comparison.
/// `base` is the request of `scene` (the scene it names, built); each row renders it at another spp.
int runComparison(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
                  const std::function<std::unique_ptr<RenderEngine>(EngineKind)>& makeEngine);
} // namespace rt::app
