#include "Scene/Perlin.h"

#include <utility>

#include "Random/Pcg.h"

namespace rt
{
namespace
{
shader::PerlinData generate()
{
    shader::PerlinData t{};
    SceneRandom rnd(0x9e3779b9u);
    for (vec3& g : t.gradients)
    {
        vec3 v;
        do
        {
            const float x = rnd.uniform(-1.0f, 1.0f);
            const float y = rnd.uniform(-1.0f, 1.0f);
            const float z = rnd.uniform(-1.0f, 1.0f);
            v = vec3(x, y, z);
        } while (lengthSquared(v) < 1e-4f);
        g = glm::normalize(v);
    }
    for (shader::uint* perm : {t.permX, t.permY, t.permZ})
    {
        for (shader::uint i = 0; i < shader::kPerlinPointCount; ++i)
            perm[i] = i;
        for (int i = static_cast<int>(shader::kPerlinPointCount) - 1; i > 0; --i)
            std::swap(perm[i], perm[rnd.integer(0, i)]);
    }
    return t;
}
} // namespace

const shader::PerlinData& perlinTables()
{
    static const shader::PerlinData tables = generate();
    return tables;
}

} // namespace rt
