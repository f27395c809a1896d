// The world-space light record of one emitting primitive, as its instance places it: what
// SceneBuilder::finish adds to the light list and transformScene re-derives after moving the instances, so
// the two cannot disagree on how a light is made.
#pragma once

#include <optional>

#include "Scene/Scene.h"

namespace rt
{
/// The light of `source` (kind Quad, Sphere or Triangle; the indices must be valid: finish() checks them
/// before calling), or nullopt when the primitive has zero area in world space (no light to sample, and
/// neither engine reports a hit on it). Throws SceneError for an emitting sphere that moves or whose
/// instance is not a similarity: the light samplers need a static sphere.
std::optional<LightData> emitterLight(const Scene& scene, const LightSource& source);
} // namespace rt
