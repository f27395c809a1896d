// Helpers the CPU render tests share: render a scene with given settings, and summary statistics of images.
#pragma once

#include "Engine/CpuEngine.h"
#include "Render/RenderSettings.h"

namespace rt::test
{
RenderSettings smallSettings(int width, int spp, int depth, Estimator estimator, float aspect = 1.0f);

RenderResult renderCpu(const Scene& scene, const RenderSettings& settings, EngineKind engine = EngineKind::Multi);

/// Mean and standard error of the mean of the per-pixel luminance-free channel average (R+G+B)/3, treating
/// pixels as independent estimates.
struct MeanAndError
{
    double mean = 0.0;
    double standardError = 0.0;
    double pixelStdDev = 0.0; // spread of single pixels
};
MeanAndError pixelStatistics(const Image& image);

bool bitIdentical(const Image& a, const Image& b);
} // namespace rt::test
