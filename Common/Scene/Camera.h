// The thin-lens camera of RTIOW §12-13 with RTTNW §2's shutter: plain settings (CameraDesc) and the
// derived pinhole/lens frame (Camera) that turns a raster position and lens/time samples into a ray.
#pragma once

#include "Math/Math.h"
#include "Math/Ray.h"

namespace rt
{
struct CameraDesc
{
    vec3 lookFrom{0.0f, 0.0f, 0.0f};
    vec3 lookAt{0.0f, 0.0f, -1.0f};
    vec3 vup{0.0f, 1.0f, 0.0f};
    float vfovDegrees = 90.0f; // vertical field of view
    float defocusAngleDegrees = 0.0f; // cone angle of rays through a pixel, apex at the focus plane; 0 = pinhole
    float focusDistance = 10.0f; // from lookFrom to the plane of perfect focus, world units
    float shutterOpen = 0.0f; // rays carry a time uniformly in [shutterOpen, shutterClose)
    float shutterClose = 1.0f;

    /// The thesis' GPU framework gave a lens *aperture* (diameter) instead of a defocus angle.
    static float defocusAngleFromAperture(float aperture, float focusDistance);

    /// Field by field: the windows restart accumulation when any of them changes.
    bool operator==(const CameraDesc&) const = default;
};

/// The camera frame for one image size. Raster coordinates: x right in [0, width), y down in [0, height).
struct Camera
{
    vec3 center{0.0f};
    vec3 pixel00{0.0f}; // centre of pixel (0, 0)
    vec3 pixelDeltaU{0.0f}; // one pixel to the right
    vec3 pixelDeltaV{0.0f}; // one pixel down
    vec3 defocusDiskU{0.0f}; // lens disk radius vectors
    vec3 defocusDiskV{0.0f};
    float shutterOpen = 0.0f;
    float shutterClose = 1.0f;
    bool thinLens = false;

    Camera() = default;
    Camera(const CameraDesc& desc, int width, int height);

    /// Ray through raster position (x, y) (continuous, pixel centres at +0.5), lens sample `lens` in [0,1)^2
    /// and time sample `u` in [0,1). The direction is not normalised (it reaches the focus plane).
    Ray generateRay(float x, float y, const vec2& lens, float u) const;
};
} // namespace rt
