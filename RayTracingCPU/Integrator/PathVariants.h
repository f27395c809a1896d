// Which compiled instance of the path loop a render runs (issue 11: "chosen once per render, not tested per
// ray"). The scene's features (Scene/SceneFeatures.h) and the render's estimator pick one of the 16
// specialised instances of tracePath: one per estimator, with or without media, with or without non-solid
// textures. --specialize off keeps the general instance, the baseline of tests/Bench/cpu_specialization.sh.
#pragma once

#include <string>

#include "Integrator/PathIntegrator.h"
#include "Scene/SceneFeatures.h"

namespace rt::cpu
{
using TracePathFn = vec3 (*)(const CpuScene&, const PathOptions&, Ray, Rng&, std::uint64_t&);

struct PathVariant
{
    TracePathFn trace = nullptr;
    PathCode code; // what `trace` was compiled for
    /// "general", or e.g. "nee-mis, no media, solid colours only", for logs.
    std::string describe() const;
};

/// The instance for `features` and `estimator`: the general one when `specialize` is false.
PathVariant choosePathVariant(const SceneFeatures& features, Estimator estimator, bool specialize);
} // namespace rt::cpu
