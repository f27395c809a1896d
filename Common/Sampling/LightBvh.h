// The light BVH that NEE's `bvh` selection descends (Shared/LightBvh.h), built on the host once per scene.
// Host only: both engines build it from the scene (the GPU uploads the two arrays unchanged).
#pragma once

#include <cstdint>
#include <vector>

#include "Scene/Scene.h"

namespace rt
{
using shader::LightBvhNode;

/// The tree and, per emitter (Scene::lights[0, emitterCount())), the index of its leaf, or kNoIndex for an
/// emitter of zero power (never selected, pmf 0).
struct LightBvh
{
    std::vector<LightBvhNode> nodes; // depth first, root at 0; never empty
    std::vector<std::uint32_t> leaves;
};

/// Builds the light BVH over the emitters of positive power (Sampling/LightPower.h), one emitter per leaf:
/// top-down, each node split at the bucket boundary (12 per axis, on the emitters' box centres) of least
/// cost, pbrt-v4's surface area orientation heuristic (Estevez Conty & Kulla 2018, §4.4: power x box area x
/// the measure of the orientation cones, with the box's aspect in the split axis). Spheres emit in every
/// direction; quads and triangles along their normal within pi/2. No leaf lies deeper than
/// shader::kLightBvhMaxDepth (median splits take over below depth 32). A scene without such emitters gets one
/// leaf of zero power, which selects nothing.
LightBvh buildLightBvh(const Scene& scene);
} // namespace rt
