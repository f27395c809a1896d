// --count-rays (HostDevice.h's RayCounters): adds to the 64-bit count of one kind of ray in one slot. Each invocation
// counts its rays in registers and adds them once, as it ends (Rays.glsl flushRayCounts); the wavefront adds
// the lengths of its queues, once per segment (Wavefront/Prepare.comp): an atomic per ray cost the H100 up to 4x
// on the books' scenes (docs/notebook/PERFORMANCE.md §24).
// Needs the rayCounters of Bindings.glsl.
#ifndef RT_RAY_COUNT_GLSL
#define RT_RAY_COUNT_GLSL

/// Adds n rays of `kind` (kRayCamera, kRayExtension, kRayShadow) to slot `slot` (mod kRayCounterSlots): the low
/// word's add that wraps carries one into the high word.
void addRays(uint slot, uint kind, uint n)
{
    const uint word = ((slot % kRayCounterSlots) * kRayKinds + kind) * 2u;
    const uint before = atomicAdd(rayCounters.words[word], n);
    if (before > 0xFFFFFFFFu - n)
        atomicAdd(rayCounters.words[word + 1u], 1u);
}

#endif
