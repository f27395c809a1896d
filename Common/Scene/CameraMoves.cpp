#include "Scene/CameraMoves.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>

namespace rt
{
namespace
{
constexpr float kMinAngleToVup = 1.0f; // degrees

float distanceToTarget(const CameraDesc& camera) { return glm::length(camera.lookAt - camera.lookFrom); }
} // namespace

CameraAxes cameraAxes(const CameraDesc& camera)
{
    const vec3 forward = glm::normalize(camera.lookAt - camera.lookFrom);
    const vec3 right = glm::normalize(glm::cross(forward, camera.vup));
    return {forward, right, glm::cross(right, forward)};
}

CameraDesc moveCamera(const CameraDesc& camera, const vec3& offset)
{
    const CameraAxes axes = cameraAxes(camera);
    const vec3 world = offset.x * axes.right + offset.y * axes.up + offset.z * axes.forward;
    CameraDesc moved = camera;
    moved.lookFrom += world;
    moved.lookAt += world;
    return moved;
}

CameraDesc turnCamera(const CameraDesc& camera, float yawDegrees, float pitchDegrees)
{
    const CameraAxes axes = cameraAxes(camera);
    const vec3 up = glm::normalize(camera.vup);
    vec3 forward = glm::angleAxis(radians(-yawDegrees), up) * axes.forward;
    const vec3 pitched = glm::angleAxis(radians(pitchDegrees), glm::normalize(glm::cross(forward, up))) * forward;
    const float angleToUp = std::acos(std::clamp(glm::dot(glm::normalize(pitched), up), -1.0f, 1.0f)) * (180.0f / kPi);
    if (angleToUp > kMinAngleToVup && angleToUp < 180.0f - kMinAngleToVup)
        forward = pitched;
    CameraDesc turned = camera;
    turned.lookAt = camera.lookFrom + distanceToTarget(camera) * glm::normalize(forward);
    return turned;
}

CameraDesc withFov(const CameraDesc& camera, float vfovDegrees)
{
    CameraDesc zoomed = camera;
    zoomed.vfovDegrees = std::clamp(vfovDegrees, kMinFov, kMaxFov);
    return zoomed;
}

float apertureOf(const CameraDesc& camera)
{
    return 2.0f * camera.focusDistance * std::tan(0.5f * radians(camera.defocusAngleDegrees));
}

CameraDesc withAperture(const CameraDesc& camera, float aperture)
{
    CameraDesc lens = camera;
    lens.defocusAngleDegrees = CameraDesc::defocusAngleFromAperture(std::max(aperture, 0.0f), camera.focusDistance);
    return lens;
}

CameraDesc withFocusDistance(const CameraDesc& camera, float focusDistance)
{
    CameraDesc focused = camera;
    focused.focusDistance = std::max(focusDistance, 1e-4f);
    return withAperture(focused, apertureOf(camera));
}

float movementSpeed(const CameraDesc& sceneCamera) { return 0.25f * std::max(distanceToTarget(sceneCamera), 1e-3f); }
vec3 keyMove(const MoveKeys& keys, float distance)
{
    const auto axis = [](bool plus, bool minus) { return float(plus) - float(minus); };
    const vec3 direction(axis(keys.right, keys.left), axis(keys.up, keys.down), axis(keys.forward, keys.back));
    if (direction == vec3(0.0f))
        return vec3(0.0f);
    if (keys.fast)
        distance *= 4.0f;
    if (keys.slow)
        distance *= 0.25f;
    return distance * direction;
}
} // namespace rt
