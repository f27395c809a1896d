#include "RayTracing/HitGroupLayout.h"

#include "Check.h"

namespace rt::gpu
{
std::uint32_t HitGroupLayout::count() const
{
    std::uint32_t n = 0;
    for (bool has : m_has)
        n += has ? 1u : 0u;
    return n;
}

std::uint32_t HitGroupLayout::record(HitGroupKind kind) const
{
    RT_CHECK(has(kind));
    std::uint32_t record = 0;
    for (std::uint32_t k = 0; k < index(kind); ++k)
        record += m_has[k] ? 1u : 0u;
    return record;
}

HitGroupKind HitGroupLayout::kindAt(std::uint32_t record) const
{
    for (std::uint32_t k = 0; k < kHitGroupKindCount; ++k)
        if (m_has[k] && record-- == 0)
            return static_cast<HitGroupKind>(k);
    RT_CHECK(false && "hit record beyond the layout");
    return HitGroupKind::Triangles;
}

bool HitGroupLayout::covers(const HitGroupLayout& other) const
{
    for (std::uint32_t k = 0; k < kHitGroupKindCount; ++k)
        if (other.m_has[k] && !m_has[k])
            return false;
    return true;
}

std::vector<std::uint32_t> hitRecordGroups(const HitGroupLayout& scene, const HitGroupLayout& pipeline,
                                           std::uint32_t missCount)
{
    RT_CHECK(pipeline.covers(scene));
    std::vector<std::uint32_t> groups;
    for (std::uint32_t r = 0; r < scene.count(); ++r)
        groups.push_back(1 + missCount + pipeline.record(scene.kindAt(r)));
    return groups;
}
} // namespace rt::gpu
