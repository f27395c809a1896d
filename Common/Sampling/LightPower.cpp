#include "Sampling/LightPower.h"

#include <numeric>

namespace rt
{
namespace
{
double meanLuminance(const Scene& scene, std::uint32_t texture)
{
    const TextureData& t = scene.textures[texture];
    switch (t.type)
    {
    case TextureType::Solid: return luminance(t.color0);
    case TextureType::Checker: return 0.5 * (luminance(t.color0) + luminance(t.color1));
    case TextureType::Image: return 1.0;
    case TextureType::Noise:
    case TextureType::Turbulence:
    case TextureType::Marble: return 0.5;
    }
    return 1.0;
}
} // namespace

std::vector<double> emitterPowers(const Scene& scene)
{
    std::vector<double> powers;
    const std::uint32_t emitters = scene.emitterCount();
    for (std::uint32_t i = 0; i < emitters; ++i)
    {
        const LightData& l = scene.lights[i];
        powers.push_back(double(l.area) * meanLuminance(scene, scene.materials[l.material].emissionTexture));
    }
    return powers;
}

std::vector<AliasEntry> makeAliasTable(const std::vector<double>& weights)
{
    const std::size_t n = weights.size();
    std::vector<AliasEntry> table(n);
    if (n == 0)
        return table;
    const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
    std::vector<double> scaled(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        const double p = total > 0.0 ? weights[i] / total : 1.0 / double(n);
        table[i].pmf = static_cast<float>(p);
        scaled[i] = p * double(n);
    }
    std::vector<std::uint32_t> small, large;
    for (std::uint32_t i = 0; i < n; ++i)
        (scaled[i] < 1.0 ? small : large).push_back(i);
    while (!small.empty() && !large.empty())
    {
        const std::uint32_t s = small.back(), l = large.back();
        small.pop_back();
        table[s].threshold = static_cast<float>(scaled[s]);
        table[s].alias = l;
        scaled[l] -= 1.0 - scaled[s]; // l gives slot s what s lacks
        if (scaled[l] < 1.0)
        {
            large.pop_back();
            small.push_back(l);
        }
    }
    // What remains is 1 up to rounding: those slots keep their own light.
    for (std::uint32_t i : small)
        table[i] = {1.0f, i, table[i].pmf};
    for (std::uint32_t i : large)
        table[i] = {1.0f, i, table[i].pmf};
    return table;
}

std::vector<AliasEntry> lightAliasTable(const Scene& scene)
{
    if (scene.emitterCount() == 0)
        return {{1.0f, 0u, 1.0f}};
    return makeAliasTable(emitterPowers(scene));
}
} // namespace rt
