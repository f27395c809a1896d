// Render space: the scene's coordinates moved so that the camera sits at their origin, the frame both engines
// trace rays in. pbrt-v4 renders in the same "camera-world" space (Pharr, Jakob & Humphreys, Physically Based
// Rendering, 4th ed., §5.1.1) for the reason that matters here: float32 is most precise near 0, and the camera
// is where the image's detail is. A scene placed 1e6 units away (--translate-scene, a scene file's "origin")
// keeps its float coordinates small, because the placement lives in Scene::origin, in double; render space
// subtracts the camera in the scene's own coordinates, so the image does not depend on where the scene lies.
#pragma once

namespace rt
{
struct Scene;

/// Moves `scene` by minus the camera's look-from: instance transforms (one float rounding of each translation),
/// the camera (look-from becomes exactly 0), sampling targets, the light list (derived again from the moved
/// primitives); adds the look-from to Scene::origin (double) and to every solid texture's origin, so that the
/// world and the textures' patterns stay where they were. Precondition: `scene` passes Scene::validate.
void toRenderSpace(Scene& scene);
} // namespace rt
