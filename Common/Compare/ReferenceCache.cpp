#include "Compare/ReferenceCache.h"

#include <type_traits>

#include <nlohmann/json.hpp>
#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "Compare/CacheEntry.h"
#include "Compare/Fnv1a.h"
#include "Error.h"
#include "IO/AtomicFile.h"
#include "Image/ImageIO.h"

namespace rt::compare
{

std::filesystem::path defaultReferenceCacheDir() { return cacheFolder("RT_REFERENCE_CACHE", "references"); }

std::uint64_t sceneFingerprint(const Scene& scene)
{
    // Field by field where a struct may have padding; whole arrays where HostDevice.h fixes the layout.
    Fnv1a h;
    h.string(scene.id);
    const CameraDesc& c = scene.camera;
    h.value(c.lookFrom), h.value(c.lookAt), h.value(c.vup), h.value(c.vfovDegrees);
    h.value(c.defocusAngleDegrees), h.value(c.focusDistance), h.value(c.shutterOpen), h.value(c.shutterClose);
    h.value(scene.background.type), h.value(scene.background.color0), h.value(scene.background.color1);
    h.vector(scene.textures);
    h.vector(scene.materials);
    for (const ImageData& image : scene.images)
        h.value(image.width), h.value(image.height), h.vector(image.rgba);
    for (const MeshData& mesh : scene.meshes)
        h.vector(mesh.positions), h.vector(mesh.normals), h.vector(mesh.uvs), h.vector(mesh.indices),
            h.vector(mesh.triangleMaterials);
    for (const GroupDesc& group : scene.groups)
    {
        for (const SphereDesc& s : group.spheres)
            h.value(s.center0), h.value(s.center1), h.value(s.radius), h.value(s.material);
        for (const QuadDesc& q : group.quads)
            h.value(q.q), h.value(q.u), h.value(q.v), h.value(q.material);
        for (const MeshRef& m : group.meshes)
            h.value(m.mesh), h.value(m.material);
        for (const MediumDesc& m : group.media)
            h.value(m.boundary), h.value(m.center), h.value(m.radius), h.value(m.boxMin), h.value(m.boxMax),
                h.value(m.density), h.value(m.phaseMaterial);
        h.value(std::uint32_t{0xFFFFFFFFu}); // the end of a group
    }
    for (const InstanceDesc& instance : scene.instances)
        h.value(instance.group), h.value(instance.worldFromObject.m);
    h.vector(scene.lights);
    return h.hash();
}

std::string ReferenceCache::key(const Scene& scene, const RenderRequest& request, EngineKind engine)
{
    nlohmann::json k;
    k["version"] = 3; // bump when the engines' output changes for the same settings (3: two halves)
    k["scene"] = request.scene.id;
    k["scene_fingerprint"] = hex(sceneFingerprint(scene));
    k["engine"] = toString(engine);
    k["settings"] = toJson(request.settings); // every field, so one added later is part of the key too
    if (const auto& c = request.camera) // a window's moved camera (the scene's is in the fingerprint)
        k["camera"] = {c->lookFrom.x, c->lookFrom.y, c->lookFrom.z, c->lookAt.x, c->lookAt.y, c->lookAt.z,
                       c->vup.x,      c->vup.y,      c->vup.z,      c->vfovDegrees, c->defocusAngleDegrees,
                       c->focusDistance, c->shutterOpen, c->shutterClose};
    return k.dump();
}

std::filesystem::path ReferenceCache::pathFor(const std::string& key, const char* extension) const
{
    Fnv1a h;
    h.string(key);
    return m_dir / (hex(h.hash()) + extension);
}

std::optional<TwoHalfReference> ReferenceCache::find(const Scene& scene, const RenderRequest& request,
                                                     EngineKind engine) const
{
    if (m_dir.empty())
        return std::nullopt;
    const std::string k = key(scene, request, engine);
    const std::optional<nlohmann::json> stored = readCacheEntry(pathFor(k, ".json"), k);
    if (!stored || !stored->contains("own_relmse") || !(*stored)["own_relmse"].is_number())
        return std::nullopt; // none, a hash collision or a damaged entry: render anew
    try
    {
        Image image = readPfm(pathFor(k, ".pfm"));
        if (image.width() != request.settings.width || image.height() != request.settings.height())
            return std::nullopt;
        return TwoHalfReference{std::move(image), (*stored)["own_relmse"].get<double>()};
    }
    catch (const AssetError& e)
    {
        spdlog::warn("reference cache: {}: rendering it again", e.what());
        return std::nullopt;
    }
}

std::filesystem::path ReferenceCache::store(const Scene& scene, const RenderRequest& request, EngineKind engine,
                                            const TwoHalfReference& reference) const
{
    if (m_dir.empty())
        return {};
    const std::string k = key(scene, request, engine);
    try
    {
        std::filesystem::create_directories(m_dir);
        const std::filesystem::path pfm = pathFor(k, ".pfm");
        writePfm(pfm, reference.mean);
        // The JSON last: an entry without it is never found.
        writeFileAtomically(pathFor(k, ".json"),
                            nlohmann::json{{"key", nlohmann::json::parse(k)},
                                           {"image", pfm.filename().string()},
                                           {"own_relmse", reference.ownRelMse}}
                                    .dump(2) +
                                "\n");
        return pfm;
    }
    catch (const std::exception& e)
    {
        spdlog::warn("reference cache: could not store the reference in {}: {}", m_dir.string(), e.what());
        return {};
    }
}
} // namespace rt::compare
