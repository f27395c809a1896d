// The windows' interactive camera: WASD (+ Q/E down/up) moves, Shift faster, Ctrl slower, a mouse drag turns,
// the wheel zooms. Pure functions on a copy of the scene's CameraDesc; a window passes the result to the engines
// (the GPU window's ray tracer and preview, the CPU window's RenderRequest::camera), so nothing of the scene is
// rebuilt.
#pragma once

#include "Math/Math.h"
#include "Scene/Camera.h"

namespace rt
{
/// Unit axes of the view: forward (lookFrom to lookAt), right, and up (vup made orthogonal to forward).
struct CameraAxes
{
    vec3 forward;
    vec3 right;
    vec3 up;
};

CameraAxes cameraAxes(const CameraDesc& camera);

/// Moves lookFrom and lookAt by `offset` given in view axes (x right, y up, z forward), world units.
CameraDesc moveCamera(const CameraDesc& camera, const vec3& offset);

/// Turns the view: positive yaw to the right (about vup), positive pitch upwards (about the right axis). The
/// distance to lookAt is kept; a pitch that would bring the view within 1 degree of vup is not applied.
CameraDesc turnCamera(const CameraDesc& camera, float yawDegrees, float pitchDegrees);

/// The vertical field of view, clamped to [kMinFov, kMaxFov].
CameraDesc withFov(const CameraDesc& camera, float vfovDegrees);
inline constexpr float kMinFov = 1.0f;
inline constexpr float kMaxFov = 160.0f;

/// The lens diameter that gives the camera's defocus angle at its focus distance (the thesis' "aperture").
float apertureOf(const CameraDesc& camera);
/// The defocus angle of lens diameter `aperture` (>= 0) at the camera's focus distance.
CameraDesc withAperture(const CameraDesc& camera, float aperture);
/// A new focus distance (> 0) with the same lens diameter, as turning a real lens' focus ring does.
CameraDesc withFocusDistance(const CameraDesc& camera, float focusDistance);

/// WASD speed in world units per second: a quarter of the scene camera's distance to its target, so that
/// a Cornell box (800 units away) and the books' spheres (13 units) both feel alike.
float movementSpeed(const CameraDesc& sceneCamera);

/// The windows' camera input, the same in both: a drag turns by kTurnDegreesPerPixel per screen pixel, a wheel
/// step changes the field of view by kFovDegreesPerWheelStep.
inline constexpr float kTurnDegreesPerPixel = 0.2f;
inline constexpr float kFovDegreesPerWheelStep = 2.0f;

/// The movement keys held in a frame: W/S forward and back, D/A right and left, E/Q up and down, Shift x4, Ctrl x1/4.
struct MoveKeys
{
    bool forward = false, back = false, right = false, left = false, up = false, down = false;
    bool fast = false, slow = false;
};
/// The offset in view axes (x right, y up, z forward) that `keys` move by in a frame whose normal-speed move is
/// `distance` world units; zero when no movement key is held.
vec3 keyMove(const MoveKeys& keys, float distance);
} // namespace rt
