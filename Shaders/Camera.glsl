// Camera samples and rays: the thin-lens camera of RTIOW §12-13 with RTTNW §2's shutter (Common/Scene/
// Camera.h). The host computes the camera frame for the image size (rt::Camera) into RenderUniforms.
// Reads the global `uniforms` (Bindings.glsl).
#ifndef RT_CAMERA_GLSL
#define RT_CAMERA_GLSL

#include "Shared/Random.h"
#include "Shared/Warps.h"
#include "Shared/HostDevice.h"

struct CameraSample
{
    vec2 raster; // continuous raster position, pixel centres at +0.5, y down
    vec2 lens; // in [0,1)^2, used only with a thin lens
    float time; // in [shutterOpen, shutterClose)
};

/// Whether the camera samples its lens (kHasThinLens: the pipeline was compiled for a camera with one).
bool thinLens() { return kHasThinLens && uniforms.thinLens != 0u; }

/// The numbers of camera sample `sampleIndex` of `pixel`, by the render's pixel sampling.
Rng rngForCameraSample(uvec2 pixel, uint sampleIndex)
{
    uint pixelIndex = pixel.y * uniforms.width + pixel.x;
    return settingSampling() == PixelSampling_Sobol ? rngForSobolSample(uniforms.seed, pixelIndex, sampleIndex)
                                                    : rngForSample(uniforms.seed, pixelIndex, sampleIndex);
}

/// Draws the camera sample of `sampleIndex` from the start of its stream, in the CPU engine's order: pixel
/// jitter (2), lens (2, only with a thin lens), time (1).
CameraSample drawCameraSample(inout Rng rng, uvec2 pixel, uint sampleIndex)
{
    vec2 jitter = nextFloat2(rng);
    CameraSample cs;
    if (settingSampling() == PixelSampling_Stratified)
    {
        uint n = uniforms.strata;
        vec2 stratum = vec2(float(sampleIndex % n), float(sampleIndex / n));
        cs.raster = vec2(pixel) + (stratum + jitter) / float(n);
    }
    else
        cs.raster = vec2(pixel) + jitter;
    cs.lens = thinLens() ? nextFloat2(rng) : vec2(0.5);
    float u = nextFloat(rng);
    cs.time = uniforms.shutterOpen + u * (uniforms.shutterClose - uniforms.shutterOpen);
    return cs;
}

/// Camera::generateRay: the direction reaches the focus plane (not unit length).
void generateRay(CameraSample cs, out vec3 origin, out vec3 direction)
{
    vec3 target = uniforms.pixel00 + (cs.raster.x - 0.5) * uniforms.pixelDeltaU +
                  (cs.raster.y - 0.5) * uniforms.pixelDeltaV;
    origin = uniforms.cameraCenter;
    if (thinLens())
    {
        vec2 d = sampleUniformDiskConcentric(cs.lens);
        origin += d.x * uniforms.defocusDiskU + d.y * uniforms.defocusDiskV;
    }
    direction = target - origin;
}

/// The shutter time of the ray being traced for (pixel, sampleIndex). Intersection shaders cannot read the
/// payload, so they replay the first numbers of the sample's stream; the time stays the same along a path.
float cameraSampleTime(uvec2 pixel, uint sampleIndex)
{
    Rng rng = rngForCameraSample(pixel, sampleIndex);
    return drawCameraSample(rng, pixel, sampleIndex).time;
}

#endif
