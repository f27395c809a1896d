#include "Render/LightSampleCounts.h"

#include <nlohmann/json.hpp>

namespace rt
{
nlohmann::json toJson(const LightSampleCounts& counts)
{
    return {{"drawn", counts.drawn}, {"fallback", counts.fallback}, {"declined", counts.declined}};
}

LightSampleCounts lightSampleCountsFromJson(const nlohmann::json& j)
{
    return {j.at("drawn").get<std::uint64_t>(), j.at("fallback").get<std::uint64_t>(),
            j.at("declined").get<std::uint64_t>()};
}
} // namespace rt
