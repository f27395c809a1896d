// restir-di on the GPU (Bitterli et al. 2020; docs/RESTIR.md): the host of Shared/Shading/Restir.h's per-sample
// math and what its passes share. An iteration is one sample per pixel in three launches over the image, each
// invocation a pixel, the CPU's two passes (RayTracingCPU/Integrator/RestirPasses.cpp) with spatial reuse apart:
//   Candidates.rgen: the camera path to its resampled vertex (restirSurfaces), M candidates resampled into a
//                    reservoir, its visibility, the combination with the pixel's last final reservoir (restirTemporal);
//   Spatial.rgen:    the combination with k neighbours' reservoirs (restirFinal);
//   Shade.rgen:      the camera path again with f(y) W as its direct light there, nee-mis beyond, added to the
//                    accumulation image.
// A ray traced for another camera sample (a neighbour's, the pixel's last) names that sample in the launch pixel's
// slot of restirTraced, where the intersection shaders read it (Bindings.glsl tracedPixel): its shutter time
// where a sphere moves, its medium seed in media.
// Needs Bindings.glsl and the payloads `payload` (kPayloadPath) and `shadowVisible` (kPayloadShadow); a pass
// defines the input hooks declared below.
#ifndef RT_RESTIR_HOST_GLSL
#define RT_RESTIR_HOST_GLSL

#include "Integrator.glsl"
#include "SampleSum.glsl"
#include "Shared/Restir.h"
#include "Shared/Shading/Camera.h"

// Shared/Shading/Restir.h's hooks: the visibility test below, and the inputs of the pass's combination.
bool restirVisible(RestirVertex v, vec3 point, uvec2 pixel, uint sampleIndex);
Reservoir restirInputReservoir(int i);
RestirVertex restirInputVertex(int i);
uvec2 restirInputPixel(int i);
uint restirInputSample(int i);

#include "Shared/Shading/Restir.h"

// The streams of a (seed, pixel, sample) apart from the camera path's own: the CPU's.
const uint kRestirCandidateStream = 0x52535431u;
const uint kRestirSpatialStream = 0x52535432u;

/// Names camera sample `sampleIndex` of `pixel` as the one the next rays are traced for, where an intersection
/// shader needs it.
void restirTraceAs(uvec2 pixel, uint sampleIndex)
{
    if (!kHasMotion && !kHasMedia)
        return;
    restirTraced[restirTracedSlot()] = uvec2(pixel.y * uniforms.width + pixel.x, sampleIndex);
    // The intersection shaders of this invocation's next trace read it.
    memoryBarrierBuffer();
}

bool restirVisible(RestirVertex v, vec3 point, uvec2 pixel, uint sampleIndex)
{
    ShadowRay s = restirShadowRay(v, point);
    restirTraceAs(pixel, sampleIndex);
    return unoccluded(s.origin, s.direction, s.distance);
}

/// The camera path `path` of the launch's sample, traced to its first vertex where NEE would run: the surface
/// there (material kNoIndex if it has none). The CPU's findSurface.
RestirSurface findRestirSurface(inout PathState path)
{
    RestirSurface surface;
    surface.hit.position = vec3(0.0);
    surface.hit.material = kNoIndex;
    surface.hit.normal = vec3(0.0);
    surface.hit.flags = 0u;
    surface.hit.uv = vec2(0.0);
    surface.hit.offsetScale = 1.0;
    surface.hit.lightSlot = kNoIndex;
    surface.incoming = vec3(0.0);
    surface.depth = 0.0;
    float depth = 0.0;
    restirTraceAs(launchPixel(), push.firstSample);
    for (uint segment = 0u; segment < uniforms.depth; ++segment)
    {
        if (!isFiniteVec(path.origin) || !isFiniteVec(path.direction))
            break;
        traceToFirstHit(path.origin, path.direction, segment == 0u);
        if (payload.material != kNoIndex)
            depth += length(payload.position - path.origin);
        if (resamplesDirectAt(payload, segment, path))
        {
            surface.hit = payload;
            surface.incoming = path.direction;
            surface.depth = depth;
            return surface;
        }
        ShadowRay shadow;
        if (!shadePathVertex(path, segment, payload, shadow, false))
            break; // no shadow ray is pending: NEE runs only where the vertex would be resampled
    }
    return surface;
}

/// The camera path of the launch's pixel and sample from its start (drawn as the megakernel draws it).
PathState restirCameraPath(uvec2 pixel, uint sampleIndex)
{
    Rng rng = rngForCameraSample(pixel, sampleIndex);
    CameraSample cs = drawCameraSample(rng, pixel, sampleIndex);
    vec3 origin;
    vec3 direction;
    generateRay(cs, origin, direction);
    return startPath(origin, direction, rng);
}

#endif
