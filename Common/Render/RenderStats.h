#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "Render/LightSampleCounts.h"
#include "Render/RayCounts.h"
#include "Render/RenderRequest.h"

namespace rt
{
/// What a finished (or cancelled) render reports (filled by the render driver, Render/RenderDriver.h);
/// written as stats.json by the apps.
struct RenderStats
{
    RenderRequest request; // the scene and the settings asked for
    EngineKind engine = EngineKind::Single;
    std::string device; // CPU model or Vulkan device name
    int width = 0;
    int height = 0;
    int trueSpp = 0; // samples each pixel really received
    double wallSeconds = 0.0; // whole render call: setup + build + render + readback
    double buildSeconds = 0.0; // acceleration structures (BVH, BLAS/TLAS)
    double renderSeconds = 0.0; // tracing only, host clock
    double gpuSeconds = -1.0; // tracing only, the device's own clock (GPU timestamp queries); < 0: none
    std::uint64_t paths = 0; // camera paths traced (pixels x true spp)
    RayCounts rays; // rays traced by kind (the camera ray and the extension rays are a path's segments)
    LightSampleCounts lightSamples; // NEE's light samples by outcome (fallback, declined), counted with the rays
    bool raysCounted = false; // false: the engine did not count them (the GPU engine without --count-rays)
    std::uint64_t nanSamples = 0; // camera samples whose radiance had a NaN (dropped from the image)
    std::uint64_t infSamples = 0; // ... or an infinity
    int threadsUsed = 1;
    bool cancelled = false;
    std::map<std::string, double> stageSeconds; // RenderEngine::stageSeconds (the GPU engine's: docs/GPU.md)
    std::string frameConfiguration; // RenderEngine::frameConfiguration
    nlohmann::json strategyChoice; // --strategy auto's pilot (Compare/AutoStrategy.h); null otherwise
    std::map<std::string, std::uint64_t> frameBytesPerPixel; // RenderEngine::frameBytesPerPixel
    nlohmann::json heatmap; // --heatmap's figures (Image/Heatmap.h's toJson): unit, mean, median, p99, max; null otherwise
    nlohmann::json ranks; // a render split over MPI ranks: each rank's share, host, device, times; null otherwise

    double mpathsPerSecond() const { return renderSeconds > 0.0 ? double(paths) / renderSeconds * 1e-6 : 0.0; }
    /// Millions of rays of `n` per second of tracing (renderSeconds, the host's clock, as mpathsPerSecond).
    double mraysPerSecond(std::uint64_t n) const { return renderSeconds > 0.0 ? double(n) / renderSeconds * 1e-6 : 0.0; }
    nlohmann::json toJson() const;
};

/// Writes stats.toJson() to `path` atomically. Throws OutputError.
void writeStatsJson(const std::filesystem::path& path, const RenderStats& stats);
} // namespace rt
