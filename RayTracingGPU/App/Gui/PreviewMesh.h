// The rasterised preview's geometry, made from the Common scene on the host (pure: tested without a device).
// Quads, boxes and meshes become world-space triangles with flat normals; spheres (and spherical media) become
// instances of one tessellated unit sphere; box media become boxes. Each surface gets one colour for its
// material: a texture's mean (solid colour, checker average, image mean, 0.5 for Perlin textures), glass a
// pale blue, an emitter its emission scaled to a maximum of 1 and drawn flat (alpha 0).
#pragma once

#include <cstdint>
#include <vector>

#include "Math/Math.h"
#include "Scene/Scene.h"

namespace rt::gpu::gui
{
/// Vertex of binding 0 (locations 0-2 of Preview.vert).
struct PreviewVertex
{
    vec3 position;
    vec3 normal;
    vec4 color; // rgb linear; a: 1 shaded, 0 emitter
};

/// Instance of binding 1 (locations 3-4): a sphere, or the identity (centre 0, radius 1, white) for triangles.
struct PreviewInstance
{
    vec4 sphere; // centre, radius
    vec4 color;
};

struct PreviewGeometry
{
    std::vector<PreviewVertex> triangles; // 3 per triangle, world space
    std::vector<PreviewInstance> spheres;
};

/// The colour the preview draws `material` with (see the file comment).
vec4 previewColor(const Scene& scene, std::uint32_t material);

PreviewGeometry buildPreviewGeometry(const Scene& scene);

/// A unit sphere around the origin, `slices` around the axis and `stacks` from pole to pole, white.
std::vector<PreviewVertex> unitSphereMesh(int slices, int stacks);
} // namespace rt::gpu::gui
