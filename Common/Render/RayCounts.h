// Rays an engine traced, by kind, and their rates: the field's unit of tracing speed (pbrt-v4's and Cycles'
// statistics count rays the same way). A path's first segment is its camera ray, each later segment an extension
// ray; shadow rays are the visibility tests of NEE and of restir-di's reservoirs. restir-di's passes trace a
// camera path twice (the candidates pass to find the resampled vertex, the shading pass again from the camera), and
// both count: the counts are the work done, not the image's paths.
#pragma once

#include <cstdint>

#include <nlohmann/json_fwd.hpp>

namespace rt
{
struct RayCounts
{
    std::uint64_t camera = 0;
    std::uint64_t extension = 0;
    std::uint64_t shadow = 0;

    std::uint64_t total() const { return camera + extension + shadow; }
    RayCounts& operator+=(const RayCounts& o)
    {
        camera += o.camera;
        extension += o.extension;
        shadow += o.shadow;
        return *this;
    }
    bool operator==(const RayCounts&) const = default;
};

/// {"camera": n, "extension": n, "shadow": n, "total": n, "mrays_per_second": {"camera": r, ..., "total": r}}: the
/// rates over `seconds` (> 0; else the rates are 0), in millions of rays per second.
nlohmann::json toJson(const RayCounts& rays, double seconds);
/// The counts of toJson's object (its rates are ignored). Throws nlohmann::json::exception when one is missing.
RayCounts rayCountsFromJson(const nlohmann::json& j);
} // namespace rt
