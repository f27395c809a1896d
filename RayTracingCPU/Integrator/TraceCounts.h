// What the CPU's path loops count as they trace: rays by kind and NEE's light samples by outcome (the engine's
// SampleTally, Render/RenderEngine.h). Plain sums, one per row of a frame: no atomics on the hot path.
#pragma once

#include "Render/LightSampleCounts.h"
#include "Render/RayCounts.h"

namespace rt::cpu
{
struct TraceCounts
{
    RayCounts rays;
    LightSampleCounts lightSamples;

    TraceCounts& operator+=(const TraceCounts& o)
    {
        rays += o.rays;
        lightSamples += o.lightSamples;
        return *this;
    }
};
} // namespace rt::cpu
