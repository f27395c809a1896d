// The wavefront integrator's paths and queues (HostDevice.h kWave* fields, WaveCounters; the kernels of this
// folder, recorded by RayTracingGPU/Engine/WavefrontPipeline.cpp). A wave is push.sampleCount samples of each
// of push.wavePixelCount pixels; path p, pixel offset p / sampleCount, keeps its state in its fields from its
// camera ray (Generate.comp) to its sum (Accumulate.comp). Per segment, Extend.rgen traces the paths of
// queue (segment & 1) to their hits, Shade.comp shades those (Shared/Shading/PathVertex.h) and queues the ones that go on
// into the other queue and those with a shadow ray into kWaveShadowQueue, Prepare.comp turns the lengths into
// the next launches' sizes, and Shadow.rgen traces the shadow rays.
// Needs the globals of Bindings.glsl and Shared/PathState.h.
#ifndef RT_WAVE_PATH_GLSL
#define RT_WAVE_PATH_GLSL

/// Entry `index` of queue `queue`.
uint waveQueueEntry(uint queue, uint index) { return waveQueues[queue * push.waveCapacity + index]; }
void setWaveQueueEntry(uint queue, uint index, uint path) { waveQueues[queue * push.waveCapacity + index] = path; }

uvec4 waveField(uint field, uint p) { return waveFields[field * push.waveCapacity + p]; }
void setWaveField(uint field, uint p, uvec4 value) { waveFields[field * push.waveCapacity + p] = value; }
vec3 waveVec3(uint field, uint p) { return uintBitsToFloat(waveField(field, p).xyz); }
uvec4 packWaveField(vec3 xyz, uint w) { return uvec4(floatBitsToUint(xyz), w); }
uvec4 packWaveField(vec3 xyz, float w) { return uvec4(floatBitsToUint(xyz), floatBitsToUint(w)); }

/// The PathState of path p (its origin is where the ray of its last vertex left: previousPoint).
PathState loadPath(uint p)
{
    PathState path;
    uvec4 origin = waveField(kWaveOriginPixel, p);
    uvec4 direction = waveField(kWaveDirectionSample, p);
    uvec4 radiance = waveField(kWaveRadiance, p);
    uvec4 beta = waveField(kWaveBeta, p);
    uvec4 normalRng = waveField(kWaveNormalRng, p);
    path.origin = uintBitsToFloat(origin.xyz);
    path.direction = uintBitsToFloat(direction.xyz);
    path.radiance = uintBitsToFloat(radiance.xyz);
    path.pendingSurvival = uintBitsToFloat(radiance.w);
    path.beta = uintBitsToFloat(beta.xyz);
    path.previousBsdfPdf = uintBitsToFloat(beta.w);
    path.previousPoint = path.origin;
    path.previousNormal = uintBitsToFloat(normalRng.xyz);
    path.rng = Rng(normalRng.w, 0u, 0u, 0u, false);
    if (settingSampling() == PixelSampling_Sobol)
    {
        uvec4 sobol = waveField(kWaveSobol, p);
        path.rng = Rng(normalRng.w, sobol.x, sobol.z, sobol.y, true);
    }
    return path;
}

/// Stores what a vertex changed of path p (not its pixel and sample, set by Generate.comp).
void storePath(uint p, PathState path, uint pixel, uint sampleIndex)
{
    setWaveField(kWaveOriginPixel, p, packWaveField(path.origin, pixel));
    setWaveField(kWaveDirectionSample, p, packWaveField(path.direction, sampleIndex));
    setWaveField(kWaveRadiance, p, packWaveField(path.radiance, path.pendingSurvival));
    setWaveField(kWaveBeta, p, packWaveField(path.beta, path.previousBsdfPdf));
    setWaveField(kWaveNormalRng, p, packWaveField(path.previousNormal, path.rng.state));
    // z: the Sobol point's index, within its seed block (RenderUniforms::seedBlock), not the camera sample's.
    if (settingSampling() == PixelSampling_Sobol)
        setWaveField(kWaveSobol, p, uvec4(path.rng.sobolSeed, path.rng.dimension, path.rng.sampleIndex, 0u));
}

/// The hit path p's last ray found (Extend.rgen stores it).
HitPayload loadHit(uint p)
{
    uvec4 point = waveField(kWaveHitPoint, p);
    uvec4 normal = waveField(kWaveHitNormal, p);
    uvec4 surface = waveField(kWaveHitSurface, p);
    HitPayload hit;
    hit.material = point.w;
    hit.position = uintBitsToFloat(point.xyz);
    hit.normal = uintBitsToFloat(normal.xyz);
    hit.flags = normal.w;
    hit.uv = uintBitsToFloat(surface.xy);
    hit.offsetScale = uintBitsToFloat(surface.z);
    hit.lightSlot = surface.w;
    return hit;
}

void storeHit(uint p, HitPayload hit)
{
    setWaveField(kWaveHitPoint, p, packWaveField(hit.position, hit.material)); // a miss: the material alone counts
    if (hit.material != kNoIndex)
    {
        setWaveField(kWaveHitNormal, p, packWaveField(hit.normal, hit.flags));
        setWaveField(kWaveHitSurface, p, uvec4(floatBitsToUint(hit.uv), floatBitsToUint(hit.offsetScale), hit.lightSlot));
    }
}

#endif
