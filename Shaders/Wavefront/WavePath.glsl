// The wavefront integrator's paths and queues (HostDevice.h WavePath, WaveCounters; the kernels of this
// folder, recorded by RayTracingGPU/Engine/WavefrontPipeline.cpp). A wave is push.sampleCount samples of each
// of push.wavePixelCount pixels; path p, pixel offset p / sampleCount, keeps its state in wavePaths[p] from
// its camera ray (Generate.comp) to its sum (Accumulate.comp). Per segment, Extend.rgen traces the paths of
// queue (segment & 1) to their hits, Shade.comp shades those (PathVertex.glsl) and queues the ones that go on
// into the other queue and those with a shadow ray into kWaveShadowQueue, Prepare.comp turns the lengths into
// the next launches' sizes, and Shadow.rgen traces the shadow rays.
// Needs the globals of Bindings.glsl and PathVertex.glsl's PathState.
#ifndef RT_WAVE_PATH_GLSL
#define RT_WAVE_PATH_GLSL

/// Entry `index` of queue `queue`.
uint waveQueueEntry(uint queue, uint index) { return waveQueues[queue * push.waveCapacity + index]; }
void setWaveQueueEntry(uint queue, uint index, uint path) { waveQueues[queue * push.waveCapacity + index] = path; }

/// The path state of wavePaths[p] (the fields PathState holds; not the hit nor the shadow ray).
PathState loadPath(uint p)
{
    PathState path;
    path.origin = wavePaths[p].origin;
    path.direction = wavePaths[p].direction;
    path.radiance = wavePaths[p].radiance;
    path.beta = wavePaths[p].beta;
    path.pendingSurvival = wavePaths[p].pendingSurvival;
    path.previousPoint = wavePaths[p].previousPoint;
    path.previousNormal = wavePaths[p].previousNormal;
    path.previousBsdfPdf = wavePaths[p].previousBsdfPdf;
    path.rng = Rng(wavePaths[p].rngState, wavePaths[p].rngSobolSeed, wavePaths[p].sampleIndex,
                   wavePaths[p].rngDimension, wavePaths[p].rngSobol != 0u);
    return path;
}

void storePath(uint p, PathState path)
{
    wavePaths[p].origin = path.origin;
    wavePaths[p].direction = path.direction;
    wavePaths[p].radiance = path.radiance;
    wavePaths[p].beta = path.beta;
    wavePaths[p].pendingSurvival = path.pendingSurvival;
    wavePaths[p].previousPoint = path.previousPoint;
    wavePaths[p].previousNormal = path.previousNormal;
    wavePaths[p].previousBsdfPdf = path.previousBsdfPdf;
    wavePaths[p].rngState = path.rng.state;
    wavePaths[p].rngSobolSeed = path.rng.sobolSeed;
    wavePaths[p].rngDimension = path.rng.dimension;
    wavePaths[p].rngSobol = path.rng.sobol ? 1u : 0u;
}

#endif
