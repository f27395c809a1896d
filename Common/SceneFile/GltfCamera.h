// The camera of an imported glTF scene (glTF 2.0 spec §3.10 "Cameras"): the first perspective camera met in
// the node hierarchy, or, with none, one that frames the scene's bounds.
#pragma once

#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "Scene/Camera.h"
#include "SceneFile/GltfNodes.h"
#include "SceneFile/GltfNotes.h"

namespace rt
{
struct GltfCamera
{
    CameraDesc camera;
    std::optional<float> aspect; // width / height, where the file gives aspectRatio
};

/// The first node of `nodes` (the walk's order) with a perspective camera: glTF cameras look down their node's
/// -Z with +Y up, so lookFrom = W (0, 0, 0), lookAt = lookFrom + W (0, 0, -1) (unit length), vup = W (0, 1, 0)
/// for the node's world transform W; vfov = yfov (radians) in degrees; a pinhole (glTF has no lens).
/// znear and zfar are not used (the renderer clips nothing). Orthographic cameras are noted and passed over.
/// Throws SceneError naming the value for a camera index out of range, a yfov outside (0, 179] degrees, an
/// aspectRatio outside [1e-4, 1e4], a transform that collapses the view direction or makes it parallel to up.
std::optional<GltfCamera> gltfCamera(const GltfDocument& doc, const std::vector<GltfPlacedNode>& nodes,
                                     GltfNotes& notes);

/// The vertical field of view of the camera that frames a scene without one, degrees.
inline constexpr float kGltfFramingVfov = 40.0f;

/// A camera on the +Z side of the box [lo, hi] looking at its centre down -Z, +Y up, far enough that the
/// sphere around the box fills kGltfFramingVfov with a 10 % margin (at aspect 1 or wider).
CameraDesc gltfFramingCamera(const glm::dvec3& lo, const glm::dvec3& hi);
} // namespace rt
