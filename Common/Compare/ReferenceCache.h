// The reference images of --compare, kept on disk between runs: a reference at thousands of spp costs more
// than the whole ladder it measures, and a user tries many ladders against one scene. An entry is a linear PFM
// (the mean of the reference's two halves, Image/Metrics.h) and a JSON file of what made it (scene id, a
// fingerprint of the built scene, engine, every render setting, spp, seed) with the reference's own relMSE; a
// lookup re-uses an entry only when all of that matches, so a changed scene, flag or seed renders a new
// reference.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "Image/Image.h"
#include "Image/Metrics.h"
#include "Render/RenderRequest.h"
#include "Render/RenderSettings.h"
#include "Scene/Scene.h"

namespace rt::compare
{
/// $RT_REFERENCE_CACHE ('off': none, an empty path), else $XDG_CACHE_HOME/ray-tracing/references, else
/// ~/.cache/ray-tracing/references.
std::filesystem::path defaultReferenceCacheDir();

/// 64-bit FNV-1a over everything an engine renders from `scene` (camera, background, materials, textures,
/// image texels, meshes, groups, instances, lights): equal for equal scenes, different when any value differs.
std::uint64_t sceneFingerprint(const Scene& scene);

class ReferenceCache
{
public:
    /// An empty `dir` disables the cache (every lookup misses, store does nothing).
    explicit ReferenceCache(std::filesystem::path dir) : m_dir(std::move(dir)) {}

    /// The cached reference rendered for exactly (scene, request, engine), or nullopt.
    std::optional<TwoHalfReference> find(const Scene& scene, const RenderRequest& request,
                                         EngineKind engine) const;
    /// Stores `reference` as that reference (atomically; a failure to write is reported, not thrown: the
    /// comparison does not depend on the cache). Returns the PFM's path, empty when not stored.
    std::filesystem::path store(const Scene& scene, const RenderRequest& request, EngineKind engine,
                                const TwoHalfReference& reference) const;

    /// The JSON text that identifies an entry (the key a lookup compares whole).
    static std::string key(const Scene& scene, const RenderRequest& request, EngineKind engine);

private:
    std::filesystem::path pathFor(const std::string& key, const char* extension) const;

    std::filesystem::path m_dir;
};
} // namespace rt::compare
