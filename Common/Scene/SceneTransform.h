// The stress knobs --translate-scene and --scale-scene: the whole scene, camera included, moved and scaled
// by one similarity, so that the image stays the same in exact arithmetic and every difference a render shows
// is float32 precision (research notes §3.4). Applied by the catalogue (makeScene) to the scene a SceneRef
// names, so the headless runs and both windows render the same moved scene.
#pragma once

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

/// How far float32 carries a scene, measured by tests/Cpu/StressTest.cpp on the Cornell boxes (docs/ROBUSTNESS.md):
/// the largest |coordinate| of the scene and its camera may be at most kMaxOffsetToSize times the scene's
/// size (the diagonal of its bounds). Past it the ray offsets that keep rays off the surface they leave
/// (256 ulps of the coordinate, RTG ch. 6) grow into a visible fraction of the scene: light leaks at corners.
inline constexpr float kMaxOffsetToSize = 128.0f;
/// The size range float32 carries without tripping the absolute offset near zero (1/65536, below) or
/// overflowing the squares of the intersection tests.
inline constexpr float kMinSceneSize = 1e-2f;
inline constexpr float kMaxSceneSize = 1e12f;

/// Applies `t` to every instance, the camera (look-from, look-at; focus distance times scale, so the lens
/// aperture scales with it and the defocus angle stays), the light list (re-derived from the moved
/// primitives), media (density is per world unit: divided by the scale) and the procedural textures'
/// frequencies (checker cells, noise). The background (directions only) does not change. Translation moves
/// world-space procedural textures (checker, Perlin) relative to the scene: their pattern shifts.
/// Throws UsageError when `t` is not finite, scale <= 0, or the result leaves the range above (the message
/// names the limit), rather than render an image float32 cannot get right.
void transformScene(Scene& scene, const SceneTransform& t);
} // namespace rt
