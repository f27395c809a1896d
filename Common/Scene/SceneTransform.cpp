#include "Scene/SceneTransform.h"

#include <algorithm>
#include <cmath>

#include <spdlog/fmt/fmt.h>

#include "Error.h"
#include "Sampling/LightSampling.h"
#include "Scene/EmitterLight.h"
#include "Scene/Scene.h"

namespace rt
{
namespace
{
/// How far float32 carries a scene, measured on the Cornell boxes (docs/ROBUSTNESS.md §2): the largest
/// |coordinate| of the scene and its camera may be at most kMaxOffsetToSize times the scene's size (the
/// diagonal of its bounds). At 32 times, 128-pixel renders of both boxes agree with the untranslated ones
/// block for block; at 53 times cornell-box-lights no longer does, at 100 times neither does (rounding at
/// that magnitude, and the ray offsets that grow with it, RTG ch. 6, become a visible part of the room).
inline constexpr float kMaxOffsetToSize = 32.0f;
/// The sizes (bounds diagonal, world units) float32 carries: measured right from 3e-3 to 3e9; at 1e-3 a
/// block of cornell-box-lights differs, at 1e10 the image is black (squared distances times areas overflow).
inline constexpr float kMinSceneSize = 1e-2f;
inline constexpr float kMaxSceneSize = 1e9f;

bool finite(const vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

float maxAbs(const vec3& v) { return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}); }

/// Largest |coordinate| of the scene's bounds and its camera, and the bounds' diagonal.
struct Reach
{
    float farthest = 0.0f;
    float size = 0.0f;
};

Reach reach(const Scene& s)
{
    const Aabb box = s.bounds();
    return {std::max({maxAbs(box.min), maxAbs(box.max), maxAbs(s.camera.lookFrom)}), glm::length(box.extent())};
}
} // namespace

void checkFloatReach(const Scene& s, const std::string& source)
{
    const Aabb box = s.bounds();
    if (!(box.min.x <= box.max.x && box.min.y <= box.max.y && box.min.z <= box.max.z))
        return; // nothing placed
    const Reach r = reach(s);
    if (!std::isfinite(r.farthest) || !std::isfinite(r.size) || r.size > kMaxSceneSize || r.size < kMinSceneSize)
        throw SceneError(fmt::format("{}: the scene is {:g} world units across; float32 renders it right "
                                     "between {:g} and {:g} (docs/ROBUSTNESS.md)",
                                     source, r.size, kMinSceneSize, kMaxSceneSize));
    if (r.farthest > kMaxOffsetToSize * r.size)
        throw SceneError(fmt::format("{}: the scene (size {:g}) reaches {:g} world units from the origin of its "
                                     "coordinates (the camera, as rendered), {:.0f} times its size; float32 renders "
                                     "it right up to {:g} times its size (docs/ROBUSTNESS.md)",
                                     source, r.size, r.farthest, r.farthest / r.size, kMaxOffsetToSize));
}

void moveScene(Scene& s, const SceneTransform& t)
{
    const Transform w = t.worldFromScene();

    for (InstanceDesc& inst : s.instances)
        inst.worldFromObject = w * inst.worldFromObject;
    s.camera.lookFrom = w.point(s.camera.lookFrom);
    s.camera.lookAt = w.point(s.camera.lookAt);
    s.camera.focusDistance *= t.scale; // the defocus angle stays: the lens grows with the focus distance
    for (GroupDesc& g : s.groups)
        for (MediumDesc& m : g.media)
            m.density /= t.scale; // extinction per world unit: the same optical depth along a scaled path
    for (TextureData& tex : s.textures)
    {
        if (tex.type == TextureType::Checker)
            tex.scale *= t.scale; // cell size, world units
        else if (tex.type == TextureType::Noise || tex.type == TextureType::Turbulence ||
                 tex.type == TextureType::Marble)
            tex.scale /= t.scale; // frequency, per world unit
    }
    for (std::size_t i = 0; i < s.lights.size(); ++i)
    {
        const LightSource& source = s.lightSources[i];
        if (source.kind == LightSource::Kind::Target)
        {
            s.lights[i] = makeSphereLight(w.point(s.lights[i].p0), s.lights[i].radius * t.scale, kNoIndex);
            continue;
        }
        const auto light = emitterLight(s, source);
        if (!light)
            throw UsageError(fmt::format("--scale-scene {}: an emitter of scene '{}' has no area left in float32",
                                         t.scale, s.id));
        s.lights[i] = *light;
    }
}

void transformScene(Scene& s, const SceneTransform& t, FloatLimits limits)
{
    if (!finite(t.translation))
        throw UsageError(fmt::format("--translate-scene must be finite (got {},{},{})", t.translation.x,
                                     t.translation.y, t.translation.z));
    if (!(std::isfinite(t.scale) && t.scale > 0.0f))
        throw UsageError(fmt::format("--scale-scene must be a finite number > 0 (got {})", t.scale));
    if (t.isIdentity())
        return;
    const Reach before = reach(s);
    moveScene(s, t);

    // Refuse rather than render what float32 cannot: the limits are measured (above).
    const Reach after = reach(s);
    if (limits == FloatLimits::Ignore)
    {
        s.validate();
        return;
    }
    // A scene already outside a limit as built may stay where it is, not go farther.
    const bool tooSmall = after.size < kMinSceneSize && after.size < before.size;
    const bool tooLarge = after.size > kMaxSceneSize && after.size > before.size;
    if (!std::isfinite(after.farthest) || tooSmall || tooLarge)
        throw UsageError(fmt::format("--scale-scene {} makes scene '{}' {:g} world units across; float32 renders "
                                     "it right between {:g} and {:g}",
                                     t.scale, s.id, after.size, kMinSceneSize, kMaxSceneSize));
    const float allowed = std::max(kMaxOffsetToSize, before.farthest / before.size);
    if (after.farthest > allowed * after.size)
        throw UsageError(fmt::format(
            "--translate-scene puts scene '{}' (size {:g}) {:g} world units from the origin, {:.0f} times its "
            "size; float32 renders it right up to {:g} times its size (docs/ROBUSTNESS.md)",
            s.id, after.size, after.farthest, after.farthest / after.size, allowed));
    s.validate();
}

void placeScene(Scene& s, const SceneTransform& t)
{
    if (!finite(t.translation))
        throw UsageError(fmt::format("--translate-scene must be finite (got {},{},{})", t.translation.x,
                                     t.translation.y, t.translation.z));
    transformScene(s, {vec3(0.0f), t.scale});
    // world = origin + p scales about the world's origin with p, then moves by the translation; in double, so that
    // the scene's own coordinates (and the image) do not depend on where it is placed.
    s.origin = static_cast<double>(t.scale) * s.origin + dvec3(t.translation);
}
} // namespace rt
