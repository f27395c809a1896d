#include "Scene/Camera.h"

#include <cmath>

#include "Sampling/Warps.h"

namespace rt
{
float CameraDesc::defocusAngleFromAperture(float aperture, float focusDistance)
{
    return 2.0f * std::atan(0.5f * aperture / focusDistance) * (180.0f / kPi);
}

Camera::Camera(const CameraDesc& desc, int width, int height)
{
    center = desc.lookFrom;
    const float h = std::tan(radians(desc.vfovDegrees) * 0.5f);
    const float viewportHeight = 2.0f * h * desc.focusDistance;
    const float viewportWidth = viewportHeight * static_cast<float>(width) / static_cast<float>(height);

    const vec3 w = glm::normalize(desc.lookFrom - desc.lookAt);
    const vec3 u = glm::normalize(glm::cross(desc.vup, w));
    const vec3 v = glm::cross(w, u);

    const vec3 viewportU = viewportWidth * u;
    const vec3 viewportV = -viewportHeight * v;
    pixelDeltaU = viewportU / static_cast<float>(width);
    pixelDeltaV = viewportV / static_cast<float>(height);
    const vec3 upperLeft = center - desc.focusDistance * w - 0.5f * viewportU - 0.5f * viewportV;
    pixel00 = upperLeft + 0.5f * (pixelDeltaU + pixelDeltaV);

    const float defocusRadius = desc.focusDistance * std::tan(radians(desc.defocusAngleDegrees * 0.5f));
    defocusDiskU = defocusRadius * u;
    defocusDiskV = defocusRadius * v;
    thinLens = desc.defocusAngleDegrees > 0.0f;
    shutterOpen = desc.shutterOpen;
    shutterClose = desc.shutterClose;
}

Ray Camera::generateRay(float x, float y, const vec2& lens, float u) const
{
    // pixel00 is the centre of pixel (0,0), i.e. raster (0.5, 0.5).
    const vec3 target = pixel00 + (x - 0.5f) * pixelDeltaU + (y - 0.5f) * pixelDeltaV;
    vec3 origin = center;
    if (thinLens)
    {
        const vec2 d = sampleUniformDiskConcentric(lens);
        origin += d.x * defocusDiskU + d.y * defocusDiskV;
    }
    return Ray{origin, target - origin, shutterOpen + u * (shutterClose - shutterOpen)};
}
} // namespace rt
