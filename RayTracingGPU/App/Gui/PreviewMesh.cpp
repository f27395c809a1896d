#include "App/Gui/PreviewMesh.h"

#include <algorithm>
#include <cmath>

#include "Image/ImageIO.h"

namespace rt::gpu::gui
{
namespace
{
constexpr vec4 kGlass{0.75f, 0.85f, 1.0f, 1.0f};

vec3 imageMean(const ImageData& image)
{
    vec3 sum(0.0f);
    const std::size_t pixels = image.rgba.size() / 4;
    for (std::size_t i = 0; i < pixels; ++i)
        sum += vec3(srgb8ToLinear(image.rgba[4 * i]), srgb8ToLinear(image.rgba[4 * i + 1]),
                    srgb8ToLinear(image.rgba[4 * i + 2]));
    return pixels > 0 ? sum / static_cast<float>(pixels) : vec3(0.5f);
}

vec3 textureMean(const Scene& scene, std::uint32_t texture)
{
    const TextureData& t = scene.textures.at(texture);
    switch (t.type)
    {
    case TextureType::Solid: return t.color0;
    case TextureType::Checker: return 0.5f * (t.color0 + t.color1);
    case TextureType::Image: return imageMean(scene.images.at(t.image));
    case TextureType::Noise:
    case TextureType::Turbulence:
    case TextureType::Marble: return vec3(0.5f);
    }
    return vec3(0.5f);
}

void addTriangle(std::vector<PreviewVertex>& out, const vec3& a, const vec3& b, const vec3& c, const vec4& color)
{
    const vec3 n = cross(b - a, c - a);
    const float length = std::sqrt(dot(n, n));
    if (!(length > 0.0f))
        return; // degenerate: nothing to draw, and no normal
    const vec3 normal = n / length;
    for (const vec3& p : {a, b, c})
        out.push_back({p, normal, color});
}

void addQuad(std::vector<PreviewVertex>& out, const Transform& m, const vec3& q, const vec3& u, const vec3& v,
             const vec4& color)
{
    const vec3 p0 = m.point(q), p1 = m.point(q + u), p2 = m.point(q + u + v), p3 = m.point(q + v);
    addTriangle(out, p0, p1, p2, color);
    addTriangle(out, p0, p2, p3, color);
}

void addBox(std::vector<PreviewVertex>& out, const Transform& m, const vec3& lo, const vec3& hi, const vec4& color)
{
    const vec3 d = hi - lo;
    const vec3 dx(d.x, 0, 0), dy(0, d.y, 0), dz(0, 0, d.z);
    addQuad(out, m, lo, dx, dy, color);
    addQuad(out, m, lo + dz, dx, dy, color);
    addQuad(out, m, lo, dy, dz, color);
    addQuad(out, m, lo + dx, dy, dz, color);
    addQuad(out, m, lo, dx, dz, color);
    addQuad(out, m, lo + dy, dx, dz, color);
}
} // namespace

vec4 previewColor(const Scene& scene, std::uint32_t material)
{
    const MaterialData& m = scene.materials.at(material);
    if (m.emissionTexture != kNoIndex)
    {
        const vec3 emission = textureMean(scene, m.emissionTexture);
        const float peak = std::max({emission.x, emission.y, emission.z});
        return vec4(peak > 0.0f ? emission / peak : emission, 0.0f);
    }
    if (m.type == MaterialType::Dielectric)
        return kGlass;
    return vec4(m.albedoTexture != kNoIndex ? textureMean(scene, m.albedoTexture) : vec3(0.5f), 1.0f);
}

PreviewGeometry buildPreviewGeometry(const Scene& scene)
{
    // One colour per material, computed once: an image texture's mean reads every texel.
    std::vector<vec4> colors;
    colors.reserve(scene.materials.size());
    for (std::uint32_t material = 0; material < scene.materials.size(); ++material)
        colors.push_back(previewColor(scene, material));
    const auto colorOf = [&](std::uint32_t material) { return colors.at(material); };

    PreviewGeometry g;
    for (const InstanceDesc& instance : scene.instances)
    {
        const GroupDesc& group = scene.groups.at(instance.group);
        const Transform& m = instance.worldFromObject;
        // Scene::validate allows spheres only under similarity transforms.
        const float scale = m.uniformScale().value_or(1.0f);
        for (const QuadDesc& q : group.quads)
            addQuad(g.triangles, m, q.q, q.u, q.v, colorOf(q.material));
        for (const MeshRef& ref : group.meshes)
        {
            const MeshData& mesh = scene.meshes.at(ref.mesh);
            for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
            {
                const std::uint32_t material = mesh.triangleMaterials.empty() ? ref.material : mesh.triangleMaterials[t];
                addTriangle(g.triangles, m.point(mesh.positions[mesh.indices[3 * t]]),
                            m.point(mesh.positions[mesh.indices[3 * t + 1]]),
                            m.point(mesh.positions[mesh.indices[3 * t + 2]]), colorOf(material));
            }
        }
        for (const SphereDesc& s : group.spheres)
            g.spheres.push_back({vec4(m.point(s.centerAt(0.5f)), s.radius * scale), colorOf(s.material)});
        for (const MediumDesc& medium : group.media)
        {
            const vec4 color = colorOf(medium.phaseMaterial);
            if (medium.boundary == MediumDesc::Boundary::Sphere)
                g.spheres.push_back({vec4(m.point(medium.center), medium.radius * scale), color});
            else
                addBox(g.triangles, m, medium.boxMin, medium.boxMax, color);
        }
    }
    return g;
}

std::vector<PreviewVertex> unitSphereMesh(int slices, int stacks)
{
    const auto point = [&](int slice, int stack) {
        const float theta = kPi * static_cast<float>(stack) / static_cast<float>(stacks);
        const float phi = 2.0f * kPi * static_cast<float>(slice) / static_cast<float>(slices);
        return vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    };
    std::vector<PreviewVertex> out;
    const vec4 white(1.0f);
    for (int stack = 0; stack < stacks; ++stack)
        for (int slice = 0; slice < slices; ++slice)
        {
            const vec3 a = point(slice, stack), b = point(slice + 1, stack), c = point(slice + 1, stack + 1),
                       d = point(slice, stack + 1);
            // On a unit sphere the normal is the position. At the poles one of the two triangles has no area.
            for (const vec3& p : {a, c, b})
                out.push_back({p, p, white});
            for (const vec3& p : {a, d, c})
                out.push_back({p, p, white});
        }
    return out;
}
} // namespace rt::gpu::gui
