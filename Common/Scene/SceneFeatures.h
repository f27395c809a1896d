// What a scene uses, so that an engine can leave out what it does not (issue 11: "skip what a scene doesn't
// need"): the CPU engine picks a path loop compiled without the unused branches, the GPU engine a pipeline
// specialised on the same set. Computed once per scene, from the description alone; two scenes with equal
// features run the same specialised code.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "Scene/Scene.h"

namespace rt
{
/// SceneFeatures::hugeSpheres: a near root's rounding above 1e-4 of the rest of the scene, 1/17 of a pixel of a
/// 600-pixel image that frames it, at most (kSphereRootError is a bound of 8 roundings).
inline constexpr float kHugeSphereTolerance = 1e-4f;

struct SceneFeatures
{
    // Geometry
    bool spheres = false; // procedural spheres (the GPU's AABB hit group)
    bool quads = false;
    bool meshes = false; // triangles
    bool media = false; // constant media (their boundaries, the isotropic phase function)
    bool motionBlur = false; // a moving sphere: rays need their time
    // A sphere (surface or medium boundary) so large against the rest of the scene that float's c = |o - centre|^2
    // - r^2 of its ray quadratic cannot place a hit near its surface well enough: a near root's rounding,
    // about kSphereRootError times its radius, above kHugeSphereTolerance of the size (bounding-box diagonal) of
    // the region rays start from: every other primitive, the camera and the sphere's point nearest the camera
    // (a 1e6-radius ground under a 6-unit light, 1.5 units below the camera). The GPU computes the exact c only
    // then (Shared/SphereQuadratic.h); rtow's radius-1000 ground beside 22 units of spheres is not huge.
    bool hugeSpheres = false;
    bool transformedInstances = false; // an instance rotated, scaled or sheared (not only translated)
    // Materials that some primitive uses
    bool lambertian = false;
    bool metal = false;
    bool dielectric = false;
    bool conductor = false; // the microfacet materials (Shared/Bsdf/)
    bool roughDielectric = false;
    bool gltfPbr = false;
    bool diffuseLight = false;
    // Textures that some used material reads, by kind (solid colours are always there)
    bool checkerTextures = false;
    bool imageTextures = false;
    bool noiseTextures = false; // noise, turbulence, marble (Perlin)
    // Emitters by shape (Scene::lights up to emitterCount)
    bool sphereEmitters = false;
    bool quadEmitters = false;
    bool triangleEmitters = false;
    // Camera and background
    bool thinLens = false; // defocus angle > 0
    BackgroundType background = BackgroundType::Constant;
    bool blackBackground = false; // a constant background of 0: missed rays add nothing

    bool emitters() const { return sphereEmitters || quadEmitters || triangleEmitters; }
    bool textures() const { return checkerTextures || imageTextures || noiseTextures; }

    bool operator==(const SceneFeatures&) const = default;

    /// One short word per feature present ("spheres quads dielectric ..."), for logs.
    std::string describe() const;
    /// Every field by name, for --stats.
    nlohmann::json toJson() const;
};

/// The features of `scene`, which must be valid (Scene::validate). Materials and textures count only when a
/// primitive of an instanced group (or a medium) uses them, so a catalogue scene's unused materials cost nothing.
SceneFeatures featuresOf(const Scene& scene);
} // namespace rt
