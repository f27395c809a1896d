#include "Assets/MeshFit.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rt
{
std::optional<std::vector<vec3>> fitMesh(std::span<const dvec3> positions, std::string& why)
{
    if (positions.empty())
    {
        why = "it has no vertices";
        return std::nullopt;
    }
    dvec3 lo(std::numeric_limits<double>::infinity());
    dvec3 hi(-std::numeric_limits<double>::infinity());
    for (const dvec3& p : positions)
    {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    // Halves throughout: hi - lo overflows for coordinates near the largest double, hi / 2 - lo / 2 cannot.
    const dvec3 half = hi / 2.0 - lo / 2.0;
    const dvec3 centreHalf = hi / 4.0 + lo / 4.0; // half of the centre
    const double widest = std::max({half.x, half.y, half.z});
    const double fitHalf = std::max(half.y, kFlatMeshRatio * widest); // half the fit height
    if (widest == 0.0)
    {
        why = "all its vertices are one point";
        return std::nullopt;
    }
    if (!std::isfinite(1.0 / fitHalf))
    {
        why = "its extent is too small to scale up in double precision";
        return std::nullopt;
    }
    std::vector<vec3> fitted;
    fitted.reserve(positions.size());
    for (const dvec3& p : positions)
    {
        const dvec3 ph = p / 2.0;
        fitted.emplace_back(static_cast<float>((ph.x - centreHalf.x) / fitHalf),
                            static_cast<float>((ph.y - lo.y / 2.0) / fitHalf),
                            static_cast<float>((ph.z - centreHalf.z) / fitHalf));
    }
    return fitted;
}
} // namespace rt
