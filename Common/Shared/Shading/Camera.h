// Camera samples and rays, written once for both engines: a host's shading scope (Shading/README.md). The
// thin-lens camera of RTIOW §12-13 with RTTNW §2's shutter (Scene/Camera.h computes its frame for the image
// size into RenderUniforms).
#ifndef RT_SHADING_CAMERA_H
#define RT_SHADING_CAMERA_H

#include "Shared/HostDevice.h"
#include "Shared/PathState.h"
#include "Shared/Random.h"
#include "Shared/Warps.h"

/// Whether the camera samples its lens (kHasThinLens: the render was compiled for a camera with one).
RT_FN bool thinLens()
{
    return kHasThinLens && uniforms.thinLens != 0u;
}

/// The seed block of camera sample `sampleIndex` (RenderUniforms::seedBlock): 0 without blocks. Block k is drawn on
/// seed + k and summed apart, so that one frame holds independent renders of consecutive seeds (--strategy auto's
/// two halves of a measurement in one launch, each bit for bit the render of its seed alone).
RT_FN uint seedBlockOf(uint sampleIndex)
{
    return uniforms.seedBlock == 0u ? 0u : sampleIndex / uniforms.seedBlock;
}

/// The seed camera sample `sampleIndex` is drawn on: the render's, plus its seed block.
RT_FN uint cameraSampleSeed(uint sampleIndex)
{
    return uniforms.seed + seedBlockOf(sampleIndex);
}

/// Camera sample `sampleIndex`'s index within its seed block: the index its seed alone would give it.
RT_FN uint sampleInSeedBlock(uint sampleIndex)
{
    return sampleIndex - seedBlockOf(sampleIndex) * uniforms.seedBlock;
}

/// The numbers of sample `index` of a seed block drawn on `seed` (cameraSampleSeed, sampleInSeedBlock) at `pixel`, by
/// the render's pixel sampling. A caller whose samples lie in one block computes its seed and first index once: the
/// H200's nee-mis megakernel ran 4-6 % slower with both worked out again per sample (notebook §56).
RT_FN Rng rngForBlockSample(uvec2 pixel, uint seed, uint index)
{
    const uint pixelIndex = pixel.y * uniforms.width + pixel.x;
    return settingSampling() == RT_ENUM(PixelSampling, Sobol) ? rngForSobolSample(seed, pixelIndex, index)
                                                              : rngForSample(seed, pixelIndex, index);
}

/// The numbers of camera sample `sampleIndex` of `pixel`, by the render's pixel sampling.
RT_FN Rng rngForCameraSample(uvec2 pixel, uint sampleIndex)
{
    return rngForBlockSample(pixel, cameraSampleSeed(sampleIndex), sampleInSeedBlock(sampleIndex));
}

/// Draws sample `index` of its seed block at `pixel` from the start of its stream: pixel jitter (2), lens (2, only
/// with a thin lens), time (1). Stratified sampling puts sample s in stratum (s mod n, s / n) of the pixel's n x n.
RT_FN CameraSample drawBlockSample(RT_INOUT(Rng) rng, uvec2 pixel, uint index)
{
    const vec2 jitter = nextFloat2(rng);
    CameraSample cs;
    if (settingSampling() == RT_ENUM(PixelSampling, Stratified))
    {
        const uint n = uniforms.strata;
        const vec2 stratum = vec2(float(index % n), float(index / n));
        cs.raster = vec2(pixel) + (stratum + jitter) / float(n);
    }
    else
        cs.raster = vec2(pixel) + jitter;
    cs.lens = thinLens() ? nextFloat2(rng) : vec2(0.5f);
    const float u = nextFloat(rng);
    cs.time = uniforms.shutterOpen + u * (uniforms.shutterClose - uniforms.shutterOpen);
    return cs;
}

/// Draws camera sample `sampleIndex` of `pixel` (drawBlockSample of its index within its seed block).
RT_FN CameraSample drawCameraSample(RT_INOUT(Rng) rng, uvec2 pixel, uint sampleIndex)
{
    return drawBlockSample(rng, pixel, sampleInSeedBlock(sampleIndex));
}

/// The camera ray of `cs`: from the lens point (the centre without a thin lens) to the raster position's point
/// of the focus plane (the direction is not unit length).
RT_FN void generateRay(RT_IN(CameraSample) cs, RT_OUT(vec3) origin, RT_OUT(vec3) direction)
{
    const vec3 target =
        uniforms.pixel00 + (cs.raster.x - 0.5f) * uniforms.pixelDeltaU + (cs.raster.y - 0.5f) * uniforms.pixelDeltaV;
    origin = uniforms.cameraCenter;
    if (thinLens())
    {
        const vec2 d = sampleUniformDiskConcentric(cs.lens);
        origin += d.x * uniforms.defocusDiskU + d.y * uniforms.defocusDiskV;
    }
    direction = target - origin;
}

/// The shutter time of camera sample `sampleIndex` of `pixel`: the first numbers of its stream replayed (a GPU
/// intersection shader cannot read the path's payload); the time stays the same along a path.
RT_FN float cameraSampleTime(uvec2 pixel, uint sampleIndex)
{
    Rng rng = rngForCameraSample(pixel, sampleIndex);
    return drawCameraSample(rng, pixel, sampleIndex).time;
}

#endif
