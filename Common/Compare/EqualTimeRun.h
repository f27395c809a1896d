// The equal-time comparison of Compare.h: every engine x strategy rendered for the same time, on one process.
#pragma once

#include <vector>

#include "Compare/ComparisonRun.h"
#include "Compare/ConvergenceCsv.h"
#include "Compare/ImageFolder.h"
#include "Scene/Scene.h"

namespace rt::compare
{
/// Every engine x strategy for options.equalTimeMs, one figure (tiles in the engines' order). Returns false when
/// Ctrl-C stopped it.
bool runEqualTime(const Scene& scene, const RenderRequest& base, const CompareOptions& options,
                  std::vector<EngineUnderTest>& engines, const Reference& reference, ConvergenceCsv* csv,
                  ImageFolder& images);
} // namespace rt::compare
