// The stress knobs --translate-scene and --scale-scene: the whole scene, camera included, moved and scaled
// by one similarity, so that the image stays the same in exact arithmetic and every difference a render shows
// is float32 precision (research notes §3.4). The catalogue (makeScene) places the scene a SceneRef names with
// placeScene: the scale in its float data, the translation in Scene::origin (double), so that the render space
// both engines draw in (Scene/RenderSpace.h) is the same wherever the scene lies. transformScene moves the
// float data themselves: what a renderer working in world space sees (the stress tests show it fail).
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

/// Applies `t` to the scene's float data: every instance, the camera (look-from, look-at; focus distance times scale, so the lens
/// aperture scales with it and the defocus angle stays), the light list (re-derived from the moved
/// primitives), media (density is per world unit: divided by the scale) and the procedural textures'
/// frequencies (checker cells, noise). The background (directions only) does not change. Translation moves
/// the scene relative to its solid textures (checker, Perlin): their pattern shifts (placeScene's does not).
/// Throws UsageError when `t` is not finite, scale <= 0, or (with `limits` Enforce) the result is farther
/// from the origin, larger or smaller than float32 renders right (measured limits: SceneTransform.cpp,
/// docs/ROBUSTNESS.md; the message names the limit). Ignore is for the tests that show what goes wrong.
enum class FloatLimits
{
    Enforce,
    Ignore
};
void transformScene(Scene& scene, const SceneTransform& t, FloatLimits limits = FloatLimits::Enforce);

/// transformScene's moves with no checks at all: the float data by `t`, the lights derived again.
/// Throws UsageError when an emitter has no area left in float32.
void moveScene(Scene& scene, const SceneTransform& t);

/// Places the scene in the world by `t`: scales its float data as transformScene (with its size limits) and
/// sets origin = scale * origin + translation in double, which leaves the scene's coordinates as they are however
/// far the translation goes. Throws UsageError as transformScene, or when the translation is not finite.
void placeScene(Scene& scene, const SceneTransform& t);

/// The same limits on a scene's coordinates, whatever placed it (a scene file's instance or node transforms):
/// throws SceneError naming `source` (the file or scene id) when its size (bounds diagonal) is outside what
/// float32 renders right, or its bounds or camera lie farther from the origin of its coordinates than
/// kMaxOffsetToSize times its size. makeScene checks the scene in render space, where that origin is the camera.
/// A scene with no geometry passes.
void checkFloatReach(const Scene& scene, const std::string& source);
} // namespace rt
