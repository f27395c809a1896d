// The interactive camera's moves on a copy of a CameraDesc.
#include <gtest/gtest.h>

#include "Scene/CameraMoves.h"

namespace rt
{
namespace
{
CameraDesc lookingDownMinusZ()
{
    CameraDesc c;
    c.lookFrom = vec3(0.0f, 0.0f, 0.0f);
    c.lookAt = vec3(0.0f, 0.0f, -10.0f);
    c.vup = vec3(0.0f, 1.0f, 0.0f);
    c.focusDistance = 10.0f;
    return c;
}

void expectNear(const vec3& a, const vec3& b, float tolerance = 1e-4f)
{
    EXPECT_NEAR(glm::length(a - b), 0.0f, tolerance) << a.x << "," << a.y << "," << a.z;
}

TEST(CameraMoves, AxesAreRightUpForward)
{
    const CameraAxes axes = cameraAxes(lookingDownMinusZ());
    expectNear(axes.forward, {0, 0, -1});
    expectNear(axes.right, {1, 0, 0});
    expectNear(axes.up, {0, 1, 0});
}

TEST(CameraMoves, MoveShiftsEyeAndTargetAlike)
{
    const CameraDesc moved = moveCamera(lookingDownMinusZ(), {1.0f, 2.0f, 3.0f});
    expectNear(moved.lookFrom, {1, 2, -3});
    expectNear(moved.lookAt, {1, 2, -13});
}

TEST(CameraMoves, YawTurnsRightAndKeepsTheDistance)
{
    const CameraDesc turned = turnCamera(lookingDownMinusZ(), 90.0f, 0.0f);
    expectNear(turned.lookAt, {10, 0, 0});
    expectNear(turned.lookFrom, {0, 0, 0});
}

TEST(CameraMoves, PitchTurnsUpButNeverOntoVup)
{
    expectNear(turnCamera(lookingDownMinusZ(), 0.0f, 45.0f).lookAt, {0, 10 * std::sqrt(0.5f), -10 * std::sqrt(0.5f)});
    // Straight up would make the view parallel to vup (no camera frame): refused, the view stays as it was.
    expectNear(turnCamera(lookingDownMinusZ(), 0.0f, 90.0f).lookAt, {0, 0, -10});
}

TEST(CameraMoves, FovIsClamped)
{
    EXPECT_FLOAT_EQ(withFov(lookingDownMinusZ(), 500.0f).vfovDegrees, kMaxFov);
    EXPECT_FLOAT_EQ(withFov(lookingDownMinusZ(), -3.0f).vfovDegrees, kMinFov);
}

TEST(CameraMoves, ApertureRoundTripsAndFocusKeepsIt)
{
    const CameraDesc lens = withAperture(lookingDownMinusZ(), 0.5f);
    EXPECT_NEAR(apertureOf(lens), 0.5f, 1e-5f);
    EXPECT_FLOAT_EQ(lens.defocusAngleDegrees, CameraDesc::defocusAngleFromAperture(0.5f, 10.0f));
    const CameraDesc refocused = withFocusDistance(lens, 4.0f);
    EXPECT_FLOAT_EQ(refocused.focusDistance, 4.0f);
    EXPECT_NEAR(apertureOf(refocused), 0.5f, 1e-5f);
    EXPECT_FLOAT_EQ(apertureOf(withAperture(lens, 0.0f)), 0.0f);
}

TEST(CameraMoves, SpeedFollowsTheSceneScale)
{
    EXPECT_FLOAT_EQ(movementSpeed(lookingDownMinusZ()), 2.5f);
}
} // namespace
} // namespace rt
