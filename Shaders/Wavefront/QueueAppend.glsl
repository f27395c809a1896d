// Appending to the wavefront's queues from a compute kernel: one atomic per subgroup, not per invocation (the
// subgroup's invocations that append take consecutive slots by their ballot).
// Needs GL_KHR_shader_subgroup_ballot and the waveCounters of Bindings.glsl.
#ifndef RT_QUEUE_APPEND_GLSL
#define RT_QUEUE_APPEND_GLSL

const uint kCounterPushed = 0u; // WaveCounters::pushed
const uint kCounterShadowsPushed = 1u; // WaveCounters::shadowsPushed

/// The slot of this invocation in the queue counted by `counter` when `append` (else meaningless). Every
/// active invocation of the subgroup must call it.
uint queueSlot(bool append, uint counter)
{
    uvec4 ballot = subgroupBallot(append);
    uint count = subgroupBallotBitCount(ballot);
    uint base = 0u;
    if (count > 0u && subgroupElect())
        base = counter == kCounterPushed ? atomicAdd(waveCounters.pushed, count)
                                         : atomicAdd(waveCounters.shadowsPushed, count);
    return subgroupBroadcastFirst(base) + subgroupBallotExclusiveBitCount(ballot);
}

#endif
