#include "Scene/LightLookup.h"

namespace rt
{
LightLookup::LightLookup(const Scene& scene)
{
    for (std::size_t i = 0; i < scene.lightSources.size(); ++i)
    {
        const LightSource& s = scene.lightSources[i];
        if (s.kind != LightSource::Kind::Target)
            m_lights.emplace(Key{s.kind, s.instance, s.meshRef, s.primitive}, static_cast<std::uint32_t>(i));
    }
}

std::size_t LightLookup::KeyHash::operator()(const Key& k) const
{
    std::uint64_t h = static_cast<std::uint64_t>(k.kind);
    for (std::uint32_t v : {k.instance, k.meshRef, k.primitive})
        h = (h ^ v) * 0x100000001B3ull; // FNV-1a step per field
    return static_cast<std::size_t>(h ^ (h >> 29));
}

std::uint32_t LightLookup::find(LightSource::Kind kind, std::uint32_t instance, std::uint32_t meshRef,
                                std::uint32_t primitive) const
{
    if (m_lights.empty())
        return kNoIndex;
    const auto it = m_lights.find(Key{kind, instance, meshRef, primitive});
    return it == m_lights.end() ? kNoIndex : it->second;
}

std::uint32_t LightLookup::quad(std::uint32_t instance, std::uint32_t quad) const
{
    return find(LightSource::Kind::Quad, instance, 0, quad);
}

std::uint32_t LightLookup::sphere(std::uint32_t instance, std::uint32_t sphere) const
{
    return find(LightSource::Kind::Sphere, instance, 0, sphere);
}

std::uint32_t LightLookup::triangle(std::uint32_t instance, std::uint32_t meshRef, std::uint32_t triangle) const
{
    return find(LightSource::Kind::Triangle, instance, meshRef, triangle);
}
} // namespace rt
