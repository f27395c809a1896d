// One GPU engine per test process, with validation on: creating a device and compiling the ray-tracing
// pipeline costs seconds on lavapipe, so every device test shares it (one device per process anyway:
// Vulkan/Device.h). Tests call RT_REQUIRE_GPU() first: it skips, with the reason, when no device fits (fails
// under CI=true: Support/SkipOrFail.h).
#pragma once

#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "Engine/GpuEngine.h"
#include "Image/Image.h"
#include "Support/PixelStatistics.h"
#include "Support/RenderWithSettings.h"
#include "Support/SkipOrFail.h"

namespace rt::gpu::test
{
/// The integrator the suite's shared engine runs: RT_GPU_INTEGRATOR (auto, megakernel or wavefront), the
/// app's default (auto) when unset, so that one suite checks either integrator on any device.
GpuIntegrator suiteIntegrator();

/// The shared engine, or nullptr when none could be created (see engineError()).
GpuEngine* sharedEngine();
const std::string& engineError();

/// Renders `scene` with `settings` on the shared engine (setScene first).
RenderResult renderOnGpu(const Scene& scene, const RenderSettings& settings);

/// Renders the furnace (a closed sphere of albedo `albedo` emitting `radiance` inside) at 32 px, `spp`, depth
/// 50 with `estimator` on the shared engine and expects every channel's pixel mean at Le / (1 - a) (minus the
/// a^depth tail) within 3 standard errors (1e-5 relative where the estimator has no variance).
void expectFurnaceOnGpu(float albedo, float radiance, Estimator estimator, int spp);

/// Renders `sceneId` at `width` px, depth 8, with `estimator` (the scene's when empty), in bands of two rows per
/// submission on the shared engine, cancels a few bands into the second batch and expects the batch put back: the
/// image a clean render of the true spp gives, bit for bit, and its NaN/Inf counters (GpuEngine's snapshot).
void expectCancelInsideABandedBatchPutsTheBatchBack(const std::string& sceneId, int width,
                                                    std::optional<Estimator> estimator = std::nullopt);

/// Renders `sceneId` at `width` px (an odd number of rows), 3 spp, depth 8, once in bands of three rows per
/// submission (the interleaved row order of Shared/BandOrder.h) and once in one submission per batch, and
/// expects the same image bit for bit: every pixel traced once per sample, whatever the bands.
void expectBandsGiveTheImageOfOneSubmission(const std::string& sceneId, int width);

/// Traces one launch of one pass of the interleaved order (Shared/BandOrder.h: the first rows of a capped first
/// band) with `integrator` (Megakernel or Wavefront: the shared engine must allow it) on a sky of radiance 1,
/// 24x37 px at one sample, and expects exactly the rows r = 0 mod 16 traced: the shaders' side of the order.
void expectOnePassTracesEverySixteenthRow(GpuIntegrator integrator);

using ::rt::test::MeanAndError;
using ::rt::test::pixelStatistics;
using ::rt::test::renderWithSettings;
} // namespace rt::gpu::test

#define RT_REQUIRE_GPU()                                                                                       \
    do                                                                                                         \
    {                                                                                                          \
        if (!::rt::gpu::test::sharedEngine())                                                                  \
        {                                                                                                      \
            RT_SKIP_OR_FAIL("no usable Vulkan ray-tracing device: " << ::rt::gpu::test::engineError());       \
        }                                                                                                      \
    } while (false)
