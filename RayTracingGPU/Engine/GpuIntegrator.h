// How the GPU engine runs the path-tracing estimator: one ray-tracing invocation per camera sample looping
// over its segments (the megakernel, RayGen.rgen), or kernels per segment over a wave of paths
// (WavefrontPipeline.h). Both compute the same estimator with the same shading code (Shared/Shading/); which
// is faster depends on the render (docs/notebook/PERFORMANCE.md §8), and `auto` picks by a rule measured on the H100.
#pragma once

#include <cstdint>

#include "Render/EngineOptions.h"
#include "Shared/HostDevice.h"

namespace rt::gpu
{
using rt::GpuIntegrator; // --integrator (Render/EngineOptions.h, with its names)

/// Scenes with at least this many traced primitives run the wavefront under `auto`: their traversal calls
/// many intersection shaders, each dearer in the megakernel, whose raygen keeps the path's state across it
/// (rtow-final's 485 spheres: 1.29x on the H100).
inline constexpr std::uint64_t kWavefrontPrimitives = 256;

/// Under auto, a render of fewer camera paths than these runs the megakernel: each of the wavefront's
/// segments costs a few launches whatever their size, which a small render does not repay (H100,
/// docs/notebook/PERFORMANCE.md §8.5). NEE with several emitters gains the most from the wavefront (cornell-box-lights:
/// 0.71x the megakernel at 0.36 M paths, 1.11x at 1.4 M); the mixture and large scenes need more paths
/// (cornell-box-lights' mixture 0.92x at 7.2 M, 1.02x at 10.8 M; rtrol-cornell-glass 0.88x at 11.5 M, 1.03x at
/// 23 M; rtow-final 0.80x at 6.5 M, 1.29x at 52 M).
inline constexpr std::uint64_t kWavefrontMinPathsNee = std::uint64_t(1) << 20;
inline constexpr std::uint64_t kWavefrontMinPaths = std::uint64_t(1) << 24;

/// What `setting` runs for a render of `paths` camera paths (the headless render's width x height x spp; a
/// window frame's) with `uniforms`, of a scene of `primitives` traced primitives (TLAS instances'
/// triangles, spheres and media, counted per instance), `media` where it has participating media. Auto: the
/// megakernel on a CPU device (lavapipe, where the wavefront's extra launches only cost); else the wavefront
/// where a vertex evaluates several lights (NEE over at least two emitters, from kWavefrontMinPathsNee paths),
/// and from kWavefrontMinPaths paths where its shading or traversal is dear: book 3's mixture over at least two
/// lights, NEE at one emitter in a scene of more than that emitter, media, or kWavefrontPrimitives primitives or
/// more; else the megakernel, which is faster for light scenes and small renders (the wavefront moves a path's
/// state through memory at every segment). Pure.
GpuIntegrator resolveIntegrator(GpuIntegrator setting, bool cpuDevice, const shader::RenderUniforms& uniforms,
                                std::uint64_t primitives, std::uint64_t paths, bool media = false);
} // namespace rt::gpu
