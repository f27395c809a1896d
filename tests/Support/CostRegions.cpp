#include "Support/CostRegions.h"

#include <algorithm>
#include <vector>

#include "Scene/Camera.h"

namespace rt::test
{
namespace
{
double trimmedMean(std::vector<float> values)
{
    if (values.empty())
        return 0.0;
    std::sort(values.begin(), values.end());
    const std::size_t cut = values.size() / 10;
    double sum = 0.0;
    for (std::size_t i = cut; i < values.size() - cut; ++i)
        sum += values[i];
    return sum / double(values.size() - 2 * cut);
}
} // namespace

CostRegions costAroundSphere(const CostMap& map, const Scene& scene, const vec3& center, float radius)
{
    const Camera camera(scene.camera, map.width, map.height);
    std::vector<float> sphere;
    std::vector<float> surroundings;
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x)
        {
            const Ray ray = camera.generateRay(float(x) + 0.5f, float(y) + 0.5f, vec2(0.5f), 0.0f);
            const vec3 d = normalize(ray.direction);
            const vec3 toCenter = center - ray.origin;
            const float along = dot(toCenter, d);
            const float miss = length(toCenter - along * d); // the ray's closest approach to the centre
            const float cost = map.perSample[std::size_t(y) * std::size_t(map.width) + std::size_t(x)];
            if (along > 0.0f && miss < 0.7f * radius)
                sphere.push_back(cost);
            else if (miss > 1.5f * radius)
                surroundings.push_back(cost);
        }
    return {trimmedMean(sphere), trimmedMean(surroundings), sphere.size(), surroundings.size()};
}
} // namespace rt::test
