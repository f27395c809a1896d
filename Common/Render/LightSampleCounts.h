// NEE's light samples by outcome (Shared/Lights/LightSample.h): how many the vertices drew, how many of them a
// fallback sampler made (by area where the strategy asked for another: a polygon too small for its spherical or
// projected sampler, a quad that is not a rectangle), and how many were declined (off the light as its pdf finds
// it, by rounding or for a receiver in the light's plane: no shadow ray, no contribution). Counted beside the rays (SampleTally::raysCounted: always on the CPU,
// with --count-rays on the GPU); restir-di counts each candidate's (Shading/Restir.h restirCandidate).
#pragma once

#include <cstdint>

#include <nlohmann/json_fwd.hpp>

#include "Shared/Lights/LightSample.h"

namespace rt
{
struct LightSampleCounts
{
    std::uint64_t drawn = 0;
    std::uint64_t fallback = 0; // of the drawn
    std::uint64_t declined = 0; // of the drawn

    LightSampleCounts& operator+=(const LightSampleCounts& o)
    {
        drawn += o.drawn;
        fallback += o.fallback;
        declined += o.declined;
        return *this;
    }
    bool operator==(const LightSampleCounts&) const = default;
};

/// Adds one vertex's ShadowRay::lightSample (its kLightSampleDrawn, kLightSampleFallback, kLightSampleDeclined
/// bits; 0 when it drew none). Inline: the CPU's path loops call it at every vertex, where the two outcomes are
/// rare (three adds there cost rtrol-cornell-box 2 % on one core).
inline void countLightSample(LightSampleCounts& counts, std::uint32_t lightSample)
{
    counts.drawn += lightSample != 0;
    if (lightSample & (shader::kLightSampleFallback | shader::kLightSampleDeclined)) [[unlikely]]
    {
        counts.fallback += (lightSample & shader::kLightSampleFallback) != 0;
        counts.declined += (lightSample & shader::kLightSampleDeclined) != 0;
    }
}

/// {"drawn": n, "fallback": n, "declined": n}.
nlohmann::json toJson(const LightSampleCounts& counts);
/// toJson's counts. Throws nlohmann::json::exception when one is missing.
LightSampleCounts lightSampleCountsFromJson(const nlohmann::json& j);
} // namespace rt
