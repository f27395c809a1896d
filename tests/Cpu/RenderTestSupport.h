// Helpers the CPU render tests share: render a scene with given settings, compare images bit for bit.
#pragma once

#include "Engine/CpuEngine.h"
#include "Render/RenderDriver.h"
#include "Render/RenderSettings.h"
#include "Support/PixelStatistics.h" // the render tests' image statistics

namespace rt::test
{
RenderSettings smallSettings(int width, int spp, int depth, Estimator estimator, float aspect = 1.0f);

RenderResult renderCpu(const Scene& scene, const RenderSettings& settings, EngineKind engine = EngineKind::Multi);

bool bitIdentical(const Image& a, const Image& b);
} // namespace rt::test
