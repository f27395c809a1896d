// The stress knobs --translate-scene and --scale-scene: the whole scene, camera included, moved and scaled
// by one similarity, so that the image stays the same in exact arithmetic and every difference a render shows
// is float32 precision (research notes §3.4). Applied by the catalogue (makeScene) to the scene a SceneRef
// names, so the headless runs and both windows render the same moved scene.
#pragma once

#include <string>

#include "Math/Math.h"
#include "Math/Transform.h"

namespace rt
{
struct Scene;

/// world' = scale * world + translation (world units). The identity by default.
struct SceneTransform
{
    vec3 translation{0.0f};
    float scale = 1.0f; // > 0

    bool isIdentity() const { return translation == vec3(0.0f) && scale == 1.0f; }
    Transform worldFromScene() const { return Transform::translate(translation) * Transform::scale(vec3(scale)); }
    bool operator==(const SceneTransform&) const = default;
};

/// Applies `t` to every instance, the camera (look-from, look-at; focus distance times scale, so the lens
/// aperture scales with it and the defocus angle stays), the light list (re-derived from the moved
/// primitives), media (density is per world unit: divided by the scale) and the procedural textures'
/// frequencies (checker cells, noise). The background (directions only) does not change. Translation moves
/// world-space procedural textures (checker, Perlin) relative to the scene: their pattern shifts.
/// Throws UsageError when `t` is not finite, scale <= 0, or (with `limits` Enforce) the result is farther
/// from the origin, larger or smaller than float32 renders right (measured limits: SceneTransform.cpp,
/// docs/ROBUSTNESS.md; the message names the limit). Ignore is for the tests that show what goes wrong.
enum class FloatLimits
{
    Enforce,
    Ignore
};
void transformScene(Scene& scene, const SceneTransform& t, FloatLimits limits = FloatLimits::Enforce);

/// The same limits on a scene as built, whatever placed it (a scene file's instance or node transforms): throws
/// SceneError naming `source` (the file) when its size (bounds diagonal) is outside what float32 renders right,
/// or its bounds or camera lie farther from the origin than kMaxOffsetToSize times its size. A scene with no
/// geometry passes.
void checkFloatReach(const Scene& scene, const std::string& source);
} // namespace rt
