// Which light of Scene::lights a primitive is, for the engines' hit records: an emitter hit by a BSDF ray
// needs its light's index for the MIS weight (selection pmf x light pdf) and so that NEE does not count it
// twice. Built once per scene from Scene::lightSources.
#pragma once

#include <cstdint>
#include <unordered_map>

#include "Scene/Scene.h"

namespace rt
{
class LightLookup
{
public:
    explicit LightLookup(const Scene& scene);

    /// The index into Scene::lights, or kNoIndex for a primitive that is not a light. Arguments are those of
    /// LightSource: the scene instance, the primitive's index in its group (and the group's mesh reference).
    std::uint32_t quad(std::uint32_t instance, std::uint32_t quad) const;
    std::uint32_t sphere(std::uint32_t instance, std::uint32_t sphere) const;
    std::uint32_t triangle(std::uint32_t instance, std::uint32_t meshRef, std::uint32_t triangle) const;

private:
    std::uint32_t find(LightSource::Kind kind, std::uint32_t instance, std::uint32_t meshRef,
                       std::uint32_t primitive) const;

    struct Key
    {
        LightSource::Kind kind;
        std::uint32_t instance, meshRef, primitive;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash
    {
        std::size_t operator()(const Key& k) const;
    };
    std::unordered_map<Key, std::uint32_t, KeyHash> m_lights;
};
} // namespace rt
