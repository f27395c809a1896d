#include "Scene/Perlin.h"

#include <cmath>
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

float perlinNoise(const shader::PerlinData& t, const vec3& p)
{
    const vec3 f = glm::floor(p);
    const vec3 w = p - f;
    const int i = static_cast<int>(f.x);
    const int j = static_cast<int>(f.y);
    const int k = static_cast<int>(f.z);
    const vec3 s = w * w * (3.0f - 2.0f * w); // Hermite smoothing
    float accum = 0.0f;
    for (int di = 0; di < 2; ++di)
        for (int dj = 0; dj < 2; ++dj)
            for (int dk = 0; dk < 2; ++dk)
            {
                const vec3& g = t.gradients[t.permX[(i + di) & 255] ^ t.permY[(j + dj) & 255] ^ t.permZ[(k + dk) & 255]];
                const float weight = (di ? s.x : 1.0f - s.x) * (dj ? s.y : 1.0f - s.y) * (dk ? s.z : 1.0f - s.z);
                accum += weight * glm::dot(g, w - vec3(di, dj, dk));
            }
    return accum;
}

float perlinTurbulence(const shader::PerlinData& t, const vec3& p, int depth)
{
    float accum = 0.0f;
    vec3 q = p;
    float weight = 1.0f;
    for (int i = 0; i < depth; ++i)
    {
        accum += weight * perlinNoise(t, q);
        weight *= 0.5f;
        q *= 2.0f;
    }
    return std::fabs(accum);
}
} // namespace rt
