#include "Render/RayCounts.h"

#include <nlohmann/json.hpp>

namespace rt
{
nlohmann::json toJson(const RayCounts& rays, double seconds)
{
    const auto rate = [seconds](std::uint64_t n) { return seconds > 0.0 ? double(n) / seconds * 1e-6 : 0.0; };
    return {{"camera", rays.camera},
            {"extension", rays.extension},
            {"shadow", rays.shadow},
            {"total", rays.total()},
            {"mrays_per_second",
             {{"camera", rate(rays.camera)},
              {"extension", rate(rays.extension)},
              {"shadow", rate(rays.shadow)},
              {"total", rate(rays.total())}}}};
}

RayCounts rayCountsFromJson(const nlohmann::json& j)
{
    return {j.at("camera").get<std::uint64_t>(), j.at("extension").get<std::uint64_t>(),
            j.at("shadow").get<std::uint64_t>()};
}
} // namespace rt
