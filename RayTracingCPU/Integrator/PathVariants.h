// Which compiled instance of the path loop a render runs (issue 11: "chosen once per render, not tested per
// ray"). The scene's features (Scene/SceneFeatures.h) and the render's estimator pick one of the 16
// specialised instances of tracePath: one per estimator, with or without media, with or without non-solid
// textures. In a scene of at most a few thousand quads and spheres they run kLanes paths at a time, their
// rays tested together (Integrator/PathStream.h). --specialize off keeps the general instance, one path at a time,
// the baseline of tests/Bench/cpu_specialization.sh.
#pragma once

#include <string>

#include "Integrator/PathIntegrator.h"
#include "Integrator/PathStream.h"
#include "Scene/SceneFeatures.h"

namespace rt::cpu
{
using TracePathsFn = void (*)(const CpuScene&, const shader::RenderUniforms&, std::span<const PathJob>, vec3*,
                              TraceCounts&);

struct PathVariant
{
    TracePathsFn trace = nullptr; // one path after the other (traceJobs)
    PathCode code; // what `trace` was compiled for
    /// The same instance tracing kLanes paths at a time, their rays tested together (Integrator/PathStream.h),
    /// where the scene allows it; else nullptr.
    TracePathsFn traceLanes = nullptr;
    /// "general", or e.g. "nee-mis, no media, solid colours only, 8 rays at a time", for logs.
    std::string describe() const;
};

/// The instance for `features` and `estimator`: the general one, one path at a time, when `specialize` is
/// false. `rayLanes`: the scene's rays can be tested kLanes at a time (CpuScene::tracesRayLanes).
PathVariant choosePathVariant(const SceneFeatures& features, Estimator estimator, bool specialize,
                              bool rayLanes = false);
} // namespace rt::cpu
