// --count-rays (HostDevice.h's TraceCounters): adds to the 64-bit count of one kind of ray (or of the light samples of
// NEE and restir-di's candidates by outcome) in one slot. Each invocation counts its rays in registers and adds them
// once, as it ends (Rays.glsl flushRayCounts); the wavefront adds the lengths of its queues, once per segment
// (Wavefront/Prepare.comp), and its vertices' light samples once per subgroup (Wavefront/Shade.comp): an atomic per
// ray cost the H100 up to 4x on the books' scenes (docs/notebook/PERFORMANCE.md §24).
// Needs the traceCounters of Bindings.glsl.
#ifndef RT_RAY_COUNT_GLSL
#define RT_RAY_COUNT_GLSL

#include "Shared/Lights/LightSample.h"

/// Adds n to the count of `kind` (kRayCamera, kRayExtension, kRayShadow, kCountLight*) in slot `slot` (mod
/// kTraceCounterSlots): the low word's add that wraps carries one into the high word.
void addCount(uint slot, uint kind, uint n)
{
    const uint word = ((slot % kTraceCounterSlots) * kCountKinds + kind) * 2u;
    const uint before = atomicAdd(traceCounters.words[word], n);
    if (before > 0xFFFFFFFFu - n)
        atomicAdd(traceCounters.words[word + 1u], 1u);
}

/// The outcomes of one ShadowRay::lightSample (Shared/Lights/LightSample.h) as 0 or 1 in the order of the
/// counters (kCountLightDrawn, kCountLightFallback, kCountLightDeclined): component k adds to kCountLightDrawn + k.
uvec3 lightSampleOutcomes(uint lightSample)
{
    return uvec3(notEqual(uvec3(lightSample) & uvec3(kLightSampleDrawn, kLightSampleFallback, kLightSampleDeclined),
                          uvec3(0u)));
}

#endif
