// restir-di on the CPU engine (Bitterli et al. 2020; the per-sample math in Shared/Shading/Restir.h, shared with
// the GPU): one iteration is one sample per pixel in two passes over the image, each parallel over rows.
//  1. Candidates and temporal reuse (Alg. 3 and 5): the camera path to its first vertex where NEE would run
//     (stored as the pixel's RestirSurface), M candidates resampled into a reservoir, its point's visibility
//     (visibility reuse, §4.1: W = 0 if occluded), then the combination with the pixel's final reservoir of the
//     last iteration (its M capped at --restir-temporal-cap times M, by default 20, §4.2).
//  2. Spatial reuse and shading: the combination with k neighbours' reservoirs of pass 1 (within --restir-radius, with
//     normals within 25 degrees and camera-path lengths within 10 %, §4.2), then the camera path again (the
//     same random numbers find the same vertex) with f(y) W as its direct light there, nee-mis beyond.
// Combinations are unbiased: GRIS with pairwise MIS over targets that include visibility (Shared/Restir.h,
// docs/RESTIR.md), at most two shadow rays per reused input; --restir-biased runs Alg. 4 instead.
#pragma once

#include <cstdint>
#include <vector>

#include "Engine/CpuScene.h"
#include "Integrator/TraceCounts.h"
#include "Shared/HostDevice.h"
#include "Shared/Restir.h"

namespace rt::cpu
{
/// restir-di's buffers for one frame: a surface and two reservoirs per pixel, kept across iterations.
struct RestirBuffers
{
    std::vector<shader::RestirSurface> surfaces; // this iteration's (pass 1 reads the last one's at its pixel first)
    std::vector<shader::Reservoir> temporal; // after pass 1
    std::vector<shader::Reservoir> final; // after pass 2: shaded, and the next iteration's temporal input
    int width = 0;
    int height = 0;
    /// Whether `final` and `surfaces` hold a complete iteration (false at the start and after a cancelled one).
    bool history = false;

    RestirBuffers(int w, int h);
    /// Bytes per pixel of the reservoirs (the two of them) and of the surface.
    static constexpr std::size_t kReservoirBytesPerPixel = 2 * sizeof(shader::Reservoir);
    static constexpr std::size_t kSurfaceBytesPerPixel = sizeof(shader::RestirSurface);
};

/// What a row of a pass traced, for the engine's tally.
struct RestirRowTally
{
    TraceCounts counts;
};

/// Pass 1 for row y of sample `sampleIndex`.
void restirCandidatesRow(const CpuScene& scene, const shader::RenderUniforms& uniforms, RestirBuffers& buffers, int y,
                         std::uint32_t sampleIndex, RestirRowTally& tally);

/// Pass 2 for row y of sample `sampleIndex`: radiance[x] is pixel x's sample (linear RGB).
void restirShadeRow(const CpuScene& scene, const shader::RenderUniforms& uniforms, RestirBuffers& buffers, int y,
                    std::uint32_t sampleIndex, vec3* radiance, RestirRowTally& tally);
} // namespace rt::cpu
