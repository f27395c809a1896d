// The host/device contract: every type tag, struct layout, binding number and push constant shared by the
// C++ engines and the GLSL shaders lives here, once. C++ includes it as a header; the shaders include it
// with glslang's #include (GL_GOOGLE_include_directive).
//
// Layout rule: every buffer uses the `scalar` block layout (GL_EXT_scalar_block_layout), so a GLSL vec3 is
// 12 bytes aligned to 4 exactly like glm::vec3 and no padding is hidden. The C++ side checks each size
// and the offsets that matter with static_assert (at the end of this file).
#ifndef RT_HOST_DEVICE_H
#define RT_HOST_DEVICE_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

namespace rt::shader
{
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uvec2 = glm::uvec2;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;
using uint = std::uint32_t;

// A closed set of tags: a C++ `enum class`, a set of `const uint NAME_VALUE` in GLSL.
#define RT_ENUM_BEGIN(Name) enum class Name : std::uint32_t {
#define RT_ENUM_VALUE(Name, Value, Index) Value = Index,
#define RT_ENUM_END(Name) };
#define RT_CONST(Type, Name, Value) inline constexpr Type Name = Value;
#define RT_TAG(Enum) Enum // a tag field: the enum in C++, a uint in GLSL (both 4 bytes)
#else
#define RT_ENUM_BEGIN(Name)
#define RT_ENUM_VALUE(Name, Value, Index) const uint Name##_##Value = Index;
#define RT_ENUM_END(Name)
#define RT_CONST(Type, Name, Value) const Type Name = Value;
#define RT_TAG(Enum) uint
#endif

// ---- Type tags --------------------------------------------------------------------------------------------

RT_ENUM_BEGIN(MaterialType)
RT_ENUM_VALUE(MaterialType, Lambertian, 0)   // albedo texture; cosine-weighted scattering
RT_ENUM_VALUE(MaterialType, Metal, 1)        // albedo texture; mirror reflection with `fuzz` sphere around it
RT_ENUM_VALUE(MaterialType, Dielectric, 2)   // index of refraction `ior`; Fresnel reflectance by `fresnel`
RT_ENUM_VALUE(MaterialType, DiffuseLight, 3) // emission texture only; does not scatter
RT_ENUM_VALUE(MaterialType, Isotropic, 4)    // phase function of constant media; albedo texture
RT_ENUM_VALUE(MaterialType, Conductor, 5)    // GGX rough metal (Shared/Bsdf/Conductor.h): alpha, Fresnel from eta + i k or F0
RT_ENUM_VALUE(MaterialType, RoughDielectric, 6) // GGX rough glass (Shared/Bsdf/RoughDielectric.h): alphaX, ior
RT_ENUM_VALUE(MaterialType, GltfPbr, 7)      // glTF 2.0 metallic-roughness BRDF (Shared/Bsdf/GltfPbr.h)
RT_ENUM_END(MaterialType)

// A dielectric's Fresnel reflectance (--fresnel; Shared/SpecularScattering.h).
RT_ENUM_BEGIN(FresnelModel)
RT_ENUM_VALUE(FresnelModel, Schlick, 0) // Schlick's approximation, as the books compute it
RT_ENUM_VALUE(FresnelModel, Exact, 1)   // the unpolarised Fresnel equations, as pbrt-v4 and Mitsuba compute it
RT_ENUM_END(FresnelModel)

RT_ENUM_BEGIN(TextureType)
RT_ENUM_VALUE(TextureType, Solid, 0)      // color0
RT_ENUM_VALUE(TextureType, Checker, 1)    // 3-D checker: color0 / color1, cell size `scale`
RT_ENUM_VALUE(TextureType, Image, 2)      // image `image`, sampled at the surface (u, v), nearest texel
RT_ENUM_VALUE(TextureType, Noise, 3)      // Perlin: 0.5 (1 + noise(scale p))
RT_ENUM_VALUE(TextureType, Turbulence, 4) // Perlin: turb(scale p), 7 octaves
RT_ENUM_VALUE(TextureType, Marble, 5)     // Perlin: 0.5 (1 + sin(scale p.z + 10 turb(p))): RTTNW §5.8 as coded
RT_ENUM_END(TextureType)

RT_ENUM_BEGIN(BackgroundType)
RT_ENUM_VALUE(BackgroundType, Constant, 0) // color0 in every direction
RT_ENUM_VALUE(BackgroundType, Gradient, 1) // lerp(color0, color1, 0.5 (dir.y + 1)), dir normalised
RT_ENUM_END(BackgroundType)

// Shapes a light sampler can sample (the scene's light list is in world space).
RT_ENUM_BEGIN(LightShape)
RT_ENUM_VALUE(LightShape, Quad, 0)     // p0 = corner Q, p1 = edge u, p2 = edge v
RT_ENUM_VALUE(LightShape, Sphere, 1)   // p0 = centre, radius
RT_ENUM_VALUE(LightShape, Triangle, 2) // p0 = vertex, p1 and p2 = edges from p0
RT_ENUM_END(LightShape)

// Estimators (--estimator; --pdf off = BsdfOnly, --pdf on = Mixture).
RT_ENUM_BEGIN(Estimator)
RT_ENUM_VALUE(Estimator, BsdfOnly, 0) // books 1-2: follow the sampled BSDF direction only
RT_ENUM_VALUE(Estimator, Mixture, 1)  // book 3: 1/2 BSDF pdf + 1/2 uniform pick over the light list, no shadow ray
RT_ENUM_VALUE(Estimator, Nee, 2)      // a shadow ray to one sampled light per diffuse vertex; BSDF rays skip lights
RT_ENUM_VALUE(Estimator, NeeMis, 3)   // NEE and BSDF sampling weighted by the power heuristic (Veach 1997, §9.2)
// At the first vertex where NEE would run, direct light by spatiotemporal reservoir resampling (Bitterli et al.
// 2020; Shared/Shading/Restir.h); nee-mis at the path's later vertices
RT_ENUM_VALUE(Estimator, RestirDi, 4)
RT_ENUM_END(Estimator)

// How NEE samples a point on a light (--light-sampler). Book 3's mixture keeps its own: cones for spheres,
// area for quads and triangles. SolidAngle: sphere cones, spherical rectangles (Ureña et al. 2013) and
// spherical triangles (Arvo 1995). Projected: by the receiver's cosine over caps above its horizon, and over
// rectangles and triangles by a bilinear warp of their spherical maps; elsewhere as SolidAngle. ProjectedExact:
// quads and triangles by their exact projected solid angle (Lights/ProjectedPolygon.h), spheres as Projected.
RT_ENUM_BEGIN(LightSampler)
RT_ENUM_VALUE(LightSampler, Area, 0)       // uniform over the light's area (a sphere's whole surface)
RT_ENUM_VALUE(LightSampler, SolidAngle, 1) // uniform over the solid angle
RT_ENUM_VALUE(LightSampler, Projected, 2)  // by the receiver's cosine
RT_ENUM_VALUE(LightSampler, ProjectedExact, 3) // by the receiver's cosine exactly (Peters 2021) over polygons
RT_ENUM_END(LightSampler)

// How Russian roulette ends paths (--russian-roulette, Shared/RussianRoulette.h): from the third segment, with a
// survival probability from the throughput's largest component m < 1.
RT_ENUM_BEGIN(RussianRoulette)
RT_ENUM_VALUE(RussianRoulette, Off, 0)        // paths run to the depth
RT_ENUM_VALUE(RussianRoulette, Throughput, 1) // survival m (pbrt-v4)
RT_ENUM_VALUE(RussianRoulette, Sqrt, 2)       // survival sqrt(m) (Blender Cycles): fewer paths end early
RT_ENUM_END(RussianRoulette)

// How NEE picks the light it samples (--light-selection).
RT_ENUM_BEGIN(LightSelection)
RT_ENUM_VALUE(LightSelection, Uniform, 0) // every emitter 1 / N
RT_ENUM_VALUE(LightSelection, Power, 1)   // in proportion to emitted power (an alias table, LightSelection.h)
RT_ENUM_VALUE(LightSelection, Bvh, 2)     // by importance seen from the shading point (a light BVH, LightBvh.h)
RT_ENUM_END(LightSelection)

RT_ENUM_BEGIN(PixelSampling)
RT_ENUM_VALUE(PixelSampling, Random, 0)     // uniform jitter in the pixel, every sample independent
RT_ENUM_VALUE(PixelSampling, Stratified, 1) // floor(sqrt(spp))^2 jittered strata; true spp is that square
RT_ENUM_VALUE(PixelSampling, Accumulate, 2) // random jitter, rendered as progressive 1-spp passes
RT_ENUM_VALUE(PixelSampling, Sobol, 3)      // every 2D draw of a sample Owen-scrambled Sobol over the pixel's samples (Shared/Sobol.h)
RT_ENUM_END(PixelSampling)

RT_CONST(uint, kNoIndex, 0xFFFFFFFFu)

// ---- Plain data of the scene description, read as is by both engines (scalar layout on the GPU) ----

struct TextureData
{
    RT_TAG(TextureType) type;
    uint image; // index into the sampler array for TextureType::Image
    float scale;
    uint linear; // Image: 1 when the texels are linear data (glTF's metallic-roughness), 0 sRGB-encoded colour
    vec3 color0;
    vec3 color1;
    // Checker, Noise, Turbulence, Marble (solid textures): the pattern is evaluated at p + origin, p the render-space
    // point (Scene/RenderSpace.h), so that it stays attached to the scene's own coordinates wherever the scene
    // and its camera lie (the camera's position in them, plus a scene file's texture "offset").
    vec3 origin;
};

struct MaterialData
{
    RT_TAG(MaterialType) type;
    uint albedoTexture; // Lambertian, Metal, Isotropic: albedo; Conductor (Schlick): F0; GltfPbr: base colour
    uint emissionTexture; // kNoIndex if the material does not emit
    float fuzz; // Metal: radius of the fuzz sphere around the mirror direction
    float ior; // Dielectric, RoughDielectric: index of refraction (inside / outside); GltfPbr: the dielectric's
    RT_TAG(FresnelModel) fresnel; // Dielectric: how its reflectance is computed; Conductor: Exact (eta, k) or Schlick (F0)
    // GGX roughness (>= kMinMicrofacetAlpha) along the shading frame's tangents (Conductor; RoughDielectric
    // reads alphaX); GltfPbr: alpha at a roughness texel of 1 (roughnessFactor^2), the texel g giving alphaX g^2.
    float alphaX;
    float alphaY;
    vec3 eta; // Conductor (Exact): real part of the complex index of refraction, per RGB channel
    float metallic; // GltfPbr: metallicFactor
    vec3 k; // Conductor (Exact): imaginary part (extinction coefficient)
    uint metallicRoughnessTexture; // GltfPbr: b = metallic, g = roughness (linear); kNoIndex if none
};

/// One slot of a light's alias table (Walker 1977; Vose 1991): slot i keeps light i with probability
/// `threshold`, else gives `alias`; `pmf` is light i's own probability (for MIS).
struct AliasEntry
{
    float threshold;
    uint alias;
    float pmf;
};

/// One node of the light BVH (Shared/LightBvh.h; built by Sampling/LightBvh.h), depth first: an interior
/// node's first child follows it, its second is at `child`; a leaf is one emitter. What it bounds, for every
/// emitter below it: their points (the sphere around their box, world space), their summed power, and the
/// directions they emit in: within theta_e of some direction within theta_o of `axis` (Estevez Conty & Kulla
/// 2018, "Importance Sampling of Many Lights with Adaptive Tree Splitting", HPG, §4.1; pbrt-v4's
/// LightBounds). Three 16-byte words: the GPU reads a node in three aligned loads.
struct LightBvhNode
{
    vec3 centre; // of the box around the emitters' points
    float radius2; // squared radius of the sphere through the box's corners
    vec3 axis; // unit axis of the cone of the emitters' normals
    float cosThetaO; // cos of that cone's half-angle (-1: every direction)
    float power; // summed power of the emitters below (Sampling/LightPower.h's units)
    float cosThetaE; // how far beyond its normal an emitter emits: cos(pi/2) = 0 for diffuse emitters
    uint child; // interior: index of the second child; leaf: kLightBvhLeaf | the emitter's index into LightData[]
    uint parent; // the parent's index (kNoIndex at the root)
};

RT_CONST(uint, kLightBvhLeaf, 0x80000000u) // LightBvhNode::child's flag of a leaf

struct LightData
{
    RT_TAG(LightShape) shape;
    uint material; // emitting material, or kNoIndex for a pure sampling target (book 3's glass sphere)
    float radius; // Sphere
    float area; // Quad / Triangle: area in world units^2
    vec3 p0;
    vec3 p1;
    vec3 p2;
    vec3 normal; // Quad / Triangle: unit geometric normal (u x v direction)
    // Quad / Triangle: the point p0 + a p1 + b p2 of the light's plane has a = (x - p0) . dualU and
    // b = (x - p0) . dualV, with w = (p1 x p2) / |p1 x p2|^2, dualU = p2 x w, dualV = w x p1 (RTTNW §6.4);
    // kept here so a pdf evaluation needs no cross product.
    vec3 dualU;
    vec3 dualV;
    // Quad / Triangle: |p0|, |dualU|, |dualV| and |dualU + dualV|, the lengths planarHit's rounding slack
    // scales with, computed once (setPlanarSlackLengths), so that planarHit can test its slack bounds on every
    // call without four square roots (docs/notebook/PERFORMANCE.md §6.2).
    float p0Length;
    float dualULength;
    float dualVLength;
    float dualSumLength;
};

// Perlin noise tables (RTTNW §5): 256 random unit gradients and three permutations of 0..255, generated
// once in Common (Scene/Perlin.cpp) from a fixed seed and uploaded unchanged, so both engines see one noise.
RT_CONST(uint, kPerlinPointCount, 256u)

struct PerlinData
{
    vec3 gradients[kPerlinPointCount];
    uint permX[kPerlinPointCount];
    uint permY[kPerlinPointCount];
    uint permZ[kPerlinPointCount];
};

// ---- What both engines' shading reads besides the scene (scalar layout on the GPU) -------------------------

/// Everything a render's shading reads that is not scene geometry: the camera frame of rt::Camera for this
/// image size (world space), the settings and the background (Render/RenderUniforms.h fills it). The GPU's
/// uniform buffer, written before a render; the CPU engine's shading holds it as it is.
struct RenderUniforms
{
    vec3 cameraCenter;
    float shutterOpen;
    vec3 pixel00; // centre of pixel (0, 0)
    float shutterClose;
    vec3 pixelDeltaU;
    uint thinLens; // 1: sample the defocus disk (defocus angle > 0)
    vec3 pixelDeltaV;
    uint width;
    vec3 defocusDiskU;
    uint height;
    vec3 defocusDiskV;
    uint depth; // path segments traced at most
    vec3 background0;
    RT_TAG(BackgroundType) backgroundType;
    vec3 background1;
    RT_TAG(Estimator) estimator;
    RT_TAG(PixelSampling) sampling;
    uint strata; // stratified sampling: n, with n * n strata per pixel
    uint seed;
    uint unidirectionalLight; // 1: emitters emit from their front face only
    uint lightCount; // LightData[]: the emitters, then the mixture's sampling targets
    uint emitterCount; // LightData[0, emitterCount) emit: what NEE samples
    RT_TAG(RussianRoulette) russianRoulette; // how paths end by Russian roulette on their throughput
    RT_TAG(LightSampler) lightSampler; // NEE's
    RT_TAG(LightSelection) lightSelection; // NEE's
    uint restirCandidates; // restir-di: light samples per pixel and iteration (M of Bitterli et al. 2020)
    uint restirSpatial; // restir-di: neighbours of spatial reuse per pixel and iteration (k)
    uint restirBiased; // restir-di: 1: the biased combination (1 / sum of M), without the neighbours' shadow rays
    uint restirTemporalCap; // restir-di: the last iteration's M capped at this many times restirCandidates; 0: none
    uint countRays; // 1: count the rays traced by kind in TraceCounters (GPU, --count-rays)
    /// 0: every camera sample on `seed`. n > 0: seed blocks of n samples (RenderEngine::setSeedBlock): sample s is
    /// sample s mod n of seed + s / n, summed into an accumulation image of its own (Shading/Camera.h).
    uint seedBlock;
    uint restirRadius; // restir-di: spatial reuse's neighbours drawn within this many pixels
};

/// What a traced path ray brings back to the path vertex (Shared/Shading/PathVertex.h): the GPU's payload at
/// kPayloadPath (the kWaveHit* fields in the wavefront), the CPU's hit turned into it. The hit shaders describe
/// the hit; all shading (textures, materials, the estimator) happens after the trace.
struct HitPayload
{
    vec3 position; // world-space hit point, computed accurately (barycentrics, re-projection)
    uint material; // kNoIndex: the ray missed
    vec3 normal; // world-space unit geometric normal, outward (arbitrary inside a medium)
    uint flags; // kHitMedium
    vec2 uv;
    float offsetScale; // offsetRayOrigin's scale: the largest |vertex coordinate| of a triangle, else 1
    uint lightSlot; // where the host finds the hit primitive's light, if any (emitterOfSlot; only read by NEE)
};
RT_CONST(uint, kHitMedium, 1u) // HitPayload::flags: scattered inside a constant medium (frontFace, origin = position)

/// restir-di's record of a pixel's vertex whose direct light is resampled (Shared/Shading/Restir.h): what a
/// neighbour needs to evaluate its target function there. 64 bytes.
struct RestirSurface
{
    HitPayload hit; // material kNoIndex: the pixel's path reached no such vertex
    vec3 incoming; // direction of the ray that found the vertex (not necessarily unit)
    float depth; // length of the camera path to the vertex, for the neighbours' similarity test
};

/// restir-di's reservoir (Bitterli et al. 2020, §3 and Alg. 2): one light point chosen by resampling, its
/// unbiased contribution weight W (per unit area at the point) and the count M of candidates behind it. 32
/// bytes: a pixel holds two (after temporal reuse; after spatial reuse, which the next iteration reads).
struct Reservoir
{
    vec3 point; // y, on light `light` (world space)
    uint light; // kNoIndex: empty
    float weight; // W: 0 when the point is occluded from the reservoir's own vertex (visibility reuse)
    float count; // M
    float target; // the target function at the reservoir's own vertex: luminance of restirIntegrand(y)
    float pad;
};

// ==== GPU engine only (RayTracingGPU, Shaders): bindings, uniforms and geometry records ====================
// Nothing above depends on this section; the CPU engine ignores it. Layout rule as above (scalar).

// Descriptor set 0 of the ray-tracing pipeline. kBindingImages is last: it is the variable-count sampler array.
RT_CONST(uint, kBindingTlas, 0u)              // accelerationStructureEXT
RT_CONST(uint, kBindingAccumulation, 1u)      // rgba32f storage image: sum of sample radiances per pixel
RT_CONST(uint, kBindingUniforms, 2u)          // uniform RenderUniforms
RT_CONST(uint, kBindingMaterials, 3u)         // MaterialData[]
RT_CONST(uint, kBindingTextures, 4u)          // TextureData[]
RT_CONST(uint, kBindingLights, 5u)            // LightData[] (world space)
RT_CONST(uint, kBindingPerlin, 6u)            // PerlinData
RT_CONST(uint, kBindingInstances, 7u)         // InstanceRecord[], indexed by the TLAS instanceCustomIndex
RT_CONST(uint, kBindingPositions, 8u)         // vec3[]: object-space vertices of every triangle BLAS
RT_CONST(uint, kBindingUvs, 9u)               // vec2[]: vertex uvs, where a mesh has them
RT_CONST(uint, kBindingTriangles, 10u)        // uvec3[]: vertex indices, relative to InstanceRecord::firstVertex
RT_CONST(uint, kBindingTriangleMaterials, 11u) // uint[]: per-triangle materials, where a mesh has them
RT_CONST(uint, kBindingSpheres, 12u)          // SphereRecord[] (object space)
RT_CONST(uint, kBindingMedia, 13u)            // MediumRecord[] (object space)
RT_CONST(uint, kBindingCounters, 14u)         // SampleCounters
RT_CONST(uint, kBindingPrimitiveLights, 15u)  // uint[]: per primitive of a record, its index into LightData[] or kNoIndex
RT_CONST(uint, kBindingLightAlias, 16u)       // AliasEntry[]: the emitters' power alias table
RT_CONST(uint, kBindingLightBvh, 17u)         // LightBvhNode[]: the emitters' light BVH
RT_CONST(uint, kBindingLightBvhLeaves, 18u)   // uint[]: per emitter, its leaf in LightBvhNode[] (kNoIndex: no power)
RT_CONST(uint, kBindingCompensation, 19u)     // rgba32f storage image: rgb the Kahan compensation of the sum
RT_CONST(uint, kBindingMixtureLights, 20u)    // uniform LightData[kMixtureUniformLights]: the first lights again
RT_CONST(uint, kBindingWavePaths, 21u)        // uvec4[kWaveFieldCount * capacity]: the wavefront's paths
RT_CONST(uint, kBindingWaveQueues, 22u)       // uint[kWaveQueueCount * capacity]: its queues of path indices
RT_CONST(uint, kBindingWaveCounters, 23u)     // WaveCounters: its queue lengths and indirect launch sizes
RT_CONST(uint, kBindingRestirSurfaces, 24u)   // RestirSurface[width * height]: restir-di's vertices (Shaders/Restir/)
RT_CONST(uint, kBindingRestirTemporal, 25u)   // Reservoir[width * height]: after candidates and temporal reuse
RT_CONST(uint, kBindingRestirFinal, 26u)      // Reservoir[width * height]: after spatial reuse, the next history
RT_CONST(uint, kBindingRestirTraced, 27u)     // uvec2[width * height]: the camera sample a restir ray is traced as
RT_CONST(uint, kBindingTraceCounters, 28u)      // TraceCounters: rays by kind, light samples by outcome (--count-rays)
RT_CONST(uint, kBindingImages, 29u)           // sampler2D[]: the scene's images, 8-bit sRGB
RT_CONST(uint, kBindingCount, 30u)
// The mixture's pdf reads every light at every vertex, all threads the same light at once: from a uniform
// buffer (a GPU's constant cache, which broadcasts) when the scene has at most this many. 64 x 104 bytes fit
// in the 16 KiB that Vulkan guarantees for a uniform buffer range.
RT_CONST(uint, kMixtureUniformLights, 64u)

// The wavefront integrator (Shaders/Wavefront/, RayTracingGPU/Engine/WavefrontPipeline.h): a launch's paths
// live in the kWave* fields between its kernels; queue 0 and 1 hold the paths to extend at even and odd segments,
// queue kWaveShadowQueue those with a shadow ray to trace. The compute kernels run kWaveGroupSize threads per
// workgroup.
RT_CONST(uint, kWaveQueueCount, 3u)
RT_CONST(uint, kWaveShadowQueue, 2u)
RT_CONST(uint, kWaveGroupSize, 64u)

// Shader binding table: two miss records (traceRayEXT's missIndex; each with its payload location), and per
// TLAS instance a hit-group record offset.
RT_CONST(uint, kMissBackground, 0u) // path rays, payload 0 (HitPayload): the background radiance
RT_CONST(uint, kMissShadow, 1u)     // shadow rays, payload 1 (uint): 1 = reached the light unoccluded
RT_CONST(uint, kPayloadPath, 0u)
RT_CONST(uint, kPayloadShadow, 1u)
// Hit groups: which SBT hit record each kind of geometry takes depends on the kinds a scene has (no sphere group
// without spheres): RayTracingGPU/RayTracing/HitGroupLayout.h assigns them; the shaders never name a record.

// Specialization constants of the path-tracing pipeline (Shaders/Specialization.glsl). The first four stand
// each for one RenderUniforms field, so that a pipeline compiled for one estimator, light sampler, light
// selection and sampling carries only their code (the driver folds the rest away: 1.1x to 5x faster on an H100,
// docs/notebook/PERFORMANCE.md §4.2); the value kSpecDynamic reads the uniform instead: the general pipeline.
// kSpecIdFeatures is a mask of the kFeature* bits below: what the scene (and the render's camera) uses; the
// shaders test `if (kHasX)` on it and the driver drops the code of every absent feature. kSpecDynamic (every
// bit set) is the general pipeline again: every feature present. Each specialisation is a compilation (tens
// of seconds on lavapipe, well under a second on an H100).
RT_CONST(uint, kSpecDynamic, 0xFFFFFFFFu)
RT_CONST(uint, kSpecIdEstimator, 0u)      // RenderUniforms::estimator
RT_CONST(uint, kSpecIdLightSampler, 1u)   // RenderUniforms::lightSampler
RT_CONST(uint, kSpecIdLightSelection, 2u) // RenderUniforms::lightSelection
RT_CONST(uint, kSpecIdSampling, 3u)       // RenderUniforms::sampling
RT_CONST(uint, kSpecIdFeatures, 4u)       // kFeature* bits
// 0: the sphere tests take float's c of their quadratic, for a scene without huge spheres (SceneFeatures::
// hugeSpheres); else (kSpecDynamic included) the exact c where it cancels (Shared/SphereQuadratic.h). Not a
// feature bit: the mixture, whose pipeline leaves the feature mask dynamic (docs/notebook/PERFORMANCE.md §4.3), sets
// it too. The exact c's code alone, never run, cost the light book scenes 3-9 % on an H100 (§8.8).
RT_CONST(uint, kSpecIdExactSphereC, 5u)
// 0: the closest-hit shaders leave a hit's uv at 0, for a scene without image textures (SceneFeatures::
// imageTextures), the only readers of a hit's uv; else (kSpecDynamic included) they compute it: the sphere uv's
// acos and atan, a mesh's uv interpolation. Not a feature bit either, so that the mixture's pipelines set it
// too: computing the uv cost the light book scenes and furnace 1-6 % on an H200 (§8.10).
RT_CONST(uint, kSpecIdHitUv, 6u)
// RenderUniforms::countRays: 1 counts every ray traced in TraceCounters (--count-rays); 0, the default, leaves the
// counting code out of the pipeline.
RT_CONST(uint, kSpecIdCountRays, 7u)
RT_CONST(uint, kSpecIdCount, 8u)
// Set by the pipeline's kind, not by the render (not in PipelineSpecialization's key): 1 in the wavefront
// integrator's pipelines, where the intersection shaders find their path's pixel and sample in the queues.
RT_CONST(uint, kSpecIdWavefront, 8u)
// 1 in restir-di's pipelines (Shaders/Restir/): the intersection shaders find the camera sample a ray is traced as
// in kBindingRestirTraced (a neighbour's shadow ray is traced as the neighbour's sample).
RT_CONST(uint, kSpecIdRestir, 9u)

// The bits of kSpecIdFeatures (PipelineSpecialization.cpp sets them from rt::SceneFeatures and the uniforms).
RT_CONST(uint, kFeatureTriangles, 0x1u)          // quads or meshes: Triangle.rchit's hit group
RT_CONST(uint, kFeatureSpheres, 0x2u)            // Sphere.rint/.rchit's hit group
RT_CONST(uint, kFeatureMedia, 0x4u)              // Medium.rint/.rchit's hit group, scattering inside media
RT_CONST(uint, kFeatureMotion, 0x8u)             // a moving sphere: Sphere.rint replays the ray's time
RT_CONST(uint, kFeatureLambertian, 0x10u)        // materials some primitive uses
RT_CONST(uint, kFeatureMetal, 0x20u)
RT_CONST(uint, kFeatureDielectric, 0x40u)
RT_CONST(uint, kFeatureCheckerTextures, 0x80u)   // textures some used material reads (solid colours always)
RT_CONST(uint, kFeatureImageTextures, 0x100u)
RT_CONST(uint, kFeatureNoiseTextures, 0x200u)    // noise, turbulence, marble
RT_CONST(uint, kFeatureSphereLights, 0x400u)     // shapes in LightData[] (emitters and the mixture's targets)
RT_CONST(uint, kFeatureQuadLights, 0x800u)
RT_CONST(uint, kFeatureTriangleLights, 0x1000u)
RT_CONST(uint, kFeatureThinLens, 0x2000u)        // RenderUniforms::thinLens (the render's camera, not the scene's)
RT_CONST(uint, kFeatureGradientBackground, 0x4000u) // RenderUniforms::backgroundType
RT_CONST(uint, kFeatureIsotropic, 0x8000u)       // an isotropic material (media's phase functions)
RT_CONST(uint, kFeatureConductor, 0x10000u)      // the microfacet materials
RT_CONST(uint, kFeatureRoughDielectric, 0x20000u)
RT_CONST(uint, kFeatureGltfPbr, 0x40000u)

RT_ENUM_BEGIN(MediumBoundary)
RT_ENUM_VALUE(MediumBoundary, Sphere, 0) // center, radius
RT_ENUM_VALUE(MediumBoundary, Box, 1)    // boxMin, boxMax (axis-aligned in object space)
RT_ENUM_END(MediumBoundary)

/// Per vkCmdTraceRaysKHR: each launch traces sampleCount camera samples per pixel, one after the other.
/// Several per launch keep a GPU without ray-tracing cores busy between the barriers that order launches.
struct TracePushConstants
{
    uint firstSample; // index of the launch's first sample within the whole render (not the dispatch)
    uint sampleCount;
    uint firstRow; // position of the launch's row 0 in the frame's row order: a launch may cover a band of rows
    uint rowInterleave; // that order (Shared/BandOrder.h): 1, top to bottom; kBandInterleave, spread
    // The wavefront integrator's (0 for the megakernel's RayGen.rgen): a wave is sampleCount samples of each
    // of wavePixelCount pixels from index wavePixelBegin on, an index being position * width + x in the row
    // order above (bandOrderPixel() gives the image pixel; kWaveOriginPixel holds y * width + x), path p =
    // pixel offset * sampleCount + sample offset; waveSegment is the segment a kernel extends or shades,
    // waveQueue the queue a ray-tracing launch reads (its intersection shaders find their path through it),
    // waveCapacity the paths each queue holds.
    uint wavePixelBegin;
    uint wavePixelCount;
    uint waveSegment;
    uint waveQueue;
    uint waveCapacity;
    uint restirHistory; // restir-di's candidates pass: 1 when the final reservoirs hold the last iteration's
};

// A wavefront wave's paths between its kernels, stored field by field (structure of arrays): field f of path
// p is the uvec4 at f * capacity + p of kBindingWavePaths, so that a subgroup's loads and stores of one field
// are contiguous (with a structure per path, the scattered accesses made BSDF sampling on the H100 take 2.7x
// the megakernel's time).
// Floats are stored as their bits. The fields (Shaders/Wavefront/WavePath.glsl reads and writes them):
RT_CONST(uint, kWaveOriginPixel, 0u)     // xyz: the next ray's origin; w: pixel index y * width + x
RT_CONST(uint, kWaveDirectionSample, 1u) // xyz: the next ray's direction; w: the camera sample's index
RT_CONST(uint, kWaveRadiance, 2u)        // xyz: radiance gathered so far; w: pendingSurvival
RT_CONST(uint, kWaveBeta, 3u)            // xyz: throughput; w: previousBsdfPdf
RT_CONST(uint, kWaveNormalRng, 4u)       // xyz: previousNormal; w: the random generator's state
RT_CONST(uint, kWaveSobol, 5u)           // x: the Sobol seed, y: 2D draws made (Owen-scrambled Sobol sampling only)
RT_CONST(uint, kWaveShadowOrigin, 6u)    // xyz: the shadow ray's origin; w: its length
RT_CONST(uint, kWaveShadowDirection, 7u) // xyz: its direction
RT_CONST(uint, kWaveShadowLight, 8u)     // xyz: its contribution, added to the radiance when unoccluded
RT_CONST(uint, kWaveHitPoint, 9u)        // the hit: xyz its position; w material (kNoIndex: a miss)
RT_CONST(uint, kWaveHitNormal, 10u)      // xyz: its geometric normal; w: flags
RT_CONST(uint, kWaveHitSurface, 11u)     // xy: uv; z: offsetScale; w: lightSlot
RT_CONST(uint, kWaveFieldCount, 12u)

/// The wavefront's queue lengths, laid out as the indirect launches read them (VkTraceRaysIndirectCommandKHR,
/// VkDispatchIndirectCommand): Prepare.comp turns what a shade kernel pushed into the next launches' sizes.
struct WaveCounters
{
    uvec4 extendRays; // x: the paths to extend (queue waveSegment & 1), y = z = 1; w unused
    uvec4 shadeGroups; // x: workgroups of the shade kernel over them, y = z = 1
    uvec4 shadowRays; // x: the shadow rays to trace (queue kWaveShadowQueue), y = z = 1
    uint pushed; // paths the shade kernel queued for the next segment
    uint shadowsPushed; // shadow rays it queued
    uint segments; // segments the wave's paths have needed so far: 1 + the last one whose queue was not empty
    uint pad0;
};

/// What the shaders need to find one TLAS instance's geometry, at instanceCustomIndex in InstanceRecord[].
/// Indices are into the global arrays of the bindings above; kNoIndex where the instance has none.
RT_CONST(uint, kQuadUvs, 0xFFFFFFFEu) // InstanceRecord::firstUv of quads: no uv buffer (Shared/QuadUv.h)

struct InstanceRecord
{
    uint firstVertex; // triangles: first vertex (positions, and uvs when firstUv != kNoIndex)
    uint firstUv; // triangles: first vertex uv; kNoIndex: the uv is the barycentrics (b1, b2); kQuadUvs: quadUv
    uint firstTriangle; // triangles: gl_PrimitiveID 0 is this triangle
    uint firstTriangleMaterial; // triangles: per-triangle materials start here, or kNoIndex: use `material`
    uint material; // triangles: material of every triangle without a per-triangle one
    uint firstSphere; // procedural: sphere geometry primitive 0
    uint firstMedium; // procedural: medium geometry primitive 0
    // Where this record's primitives (triangles, spheres; quad k = triangles 2k and 2k + 1) start in the
    // primitive-light array, or kNoIndex when none of them is a light.
    uint firstPrimitiveLight;
};

/// A sphere moving linearly from center0 (time 0) to center1 (time 1), object space.
struct SphereRecord
{
    vec3 center0;
    float radius;
    vec3 center1;
    uint material;
};

/// A constant-density medium bounded by a sphere or a box, object space (RTTNW §9).
struct MediumRecord
{
    vec3 center;
    float radius;
    vec3 boxMin;
    float density; // extinction coefficient per world unit
    vec3 boxMax;
    RT_TAG(MediumBoundary) boundary;
    uint phaseMaterial; // Isotropic
    uint pad0;
    uint pad1;
    uint pad2;
};

/// Camera samples the raygen shader dropped because their radiance was not finite.
struct SampleCounters
{
    uint nanSamples;
    uint infSamples;
};

// TraceCounters (--count-rays): the rays of each kind (Render/RayCounts.h) and NEE's light samples by outcome
// (Render/LightSampleCounts.h) as 64-bit counts of two words, low and high, which 32-bit atomics keep (the
// invocation whose add wraps the low word carries one into the high word), so that no device needs 64-bit atomics.
// Each kind has kTraceCounterSlots such counts, an invocation adding to the slot of its launch column (the
// wavefront's Shade.comp: of its workgroup; Prepare.comp: slot 0): the invocations of a subgroup add to different
// addresses instead of queueing on one. Device-local (an atomic over
// PCIe per ray would be the render's cost); the host sums the slots.
RT_CONST(uint, kRayCamera, 0u)
RT_CONST(uint, kRayExtension, 1u)
RT_CONST(uint, kRayShadow, 2u)
RT_CONST(uint, kRayKinds, 3u)
RT_CONST(uint, kCountLightDrawn, 3u) // light samples drawn by NEE and restir-di's candidates (kLightSampleDrawn)
RT_CONST(uint, kCountLightFallback, 4u) // ... made by a fallback sampler (kLightSampleFallback)
RT_CONST(uint, kCountLightDeclined, 5u) // ... declined (kLightSampleDeclined)
RT_CONST(uint, kCountKinds, 6u)
RT_CONST(uint, kTraceCounterSlots, 32u)
RT_CONST(uint, kTraceCounterWords, 384u) // kTraceCounterSlots x kCountKinds x 2 words: (slot x kCountKinds + kind) x 2 (+ 1: high)

struct TraceCounters
{
    uint words[kTraceCounterWords];
};

// ---- The window of ray-tracing-gpu (RayTracingGPU/App/Gui): heatmap, display pass, raster preview ----------

// Descriptor set 1 of the timed ray-generation shader (RayGenCost.rgen); set 0 is the path tracer's. One set
// per frame in flight: each frame has its own CostMax, which the host reads once the frame is done.
RT_CONST(uint, kSetCost, 1u)
RT_CONST(uint, kBindingCost, 0u)      // r32f storage image: shader-clock ticks of the pixel's samples, summed
RT_CONST(uint, kBindingCostStats, 1u) // CostStats

/// Pixels' ticks per sample after one frame's samples, for the heatmap's legend and automatic scale: the
/// largest, and how many fall in each power of two (the scale is a high percentile: the largest is often a
/// pixel whose invocation was descheduled, far above the rest).
RT_CONST(uint, kCostBuckets, 32u) // bucket b: ticks per sample in [2^b, 2^(b+1)); bucket 0 also holds [0, 1)
struct CostStats
{
    uint maxBits; // floatBitsToUint of a non-negative float: atomicMax on the bits orders the floats
    uint buckets[kCostBuckets];
};

// Descriptor set 0 of the display pass (Display.vert/.frag), which draws the ray tracer's image into its
// rectangle of the window (letterboxed beside the panel).
RT_CONST(uint, kDisplayBindingAccumulation, 0u) // rgba32f storage image: radiance sum, sample count
RT_CONST(uint, kDisplayBindingCost, 1u)         // r32f storage image: ticks summed (kBindingCost's image)

RT_ENUM_BEGIN(DisplayMode)
RT_ENUM_VALUE(DisplayMode, Radiance, 0) // radiance sum / samples, clamped to [0, 1], sRGB-encoded
RT_ENUM_VALUE(DisplayMode, Cost, 1)     // ticks per sample / costScale through heatmapColor (HeatmapPalette.h)
RT_ENUM_END(DisplayMode)

struct DisplayPushConstants
{
    RT_TAG(DisplayMode) mode;
    uint encodeSrgb; // 1: the swapchain stores what it is given (UNORM), so the shader encodes sRGB
    float costScale; // Cost: ticks per sample shown as the top of the palette
    uint pad;
    vec2 imageOrigin; // framebuffer pixel of the image rectangle's top-left corner
    vec2 texelsPerPixel; // image texels per framebuffer pixel, x and y (the letterbox's scale, inverted)
};

/// The rasterised preview (Preview.vert/.frag): one pipeline draws the scene's triangles (per-vertex world
/// positions, sphere instance = identity) and its spheres (a unit sphere mesh, per-instance centre and radius).
struct PreviewPushConstants
{
    mat4 clipFromWorld; // Vulkan clip space: y down, depth in [0, 1]
    vec3 eye; // camera centre, for the head-light shading
    uint encodeSrgb; // as in DisplayPushConstants
};

#ifdef __cplusplus
static_assert(sizeof(LightBvhNode) == 48);
static_assert(sizeof(TracePushConstants) == 40);
static_assert(sizeof(WaveCounters) == 64 && offsetof(WaveCounters, shadowRays) == 32);
static_assert(sizeof(InstanceRecord) == 32);
static_assert(sizeof(SphereRecord) == 32);
static_assert(offsetof(SphereRecord, center1) == 16);
static_assert(sizeof(MediumRecord) == 64);
static_assert(offsetof(MediumRecord, boxMax) == 32);
static_assert(offsetof(MediumRecord, phaseMaterial) == 48);
static_assert(sizeof(SampleCounters) == 8);
static_assert(kTraceCounterWords == kTraceCounterSlots * kCountKinds * 2 && sizeof(TraceCounters) == 4 * kTraceCounterWords);
static_assert(sizeof(CostStats) == 4 * (1 + kCostBuckets));
static_assert(sizeof(DisplayPushConstants) == 32 && offsetof(DisplayPushConstants, imageOrigin) == 16);
static_assert(sizeof(PreviewPushConstants) == 80 && offsetof(PreviewPushConstants, eye) == 64);
#endif
// ==== end of the GPU engine section ==========================================================================

#ifdef __cplusplus
static_assert(sizeof(PerlinData) == 256 * 12 + 3 * 256 * 4);
static_assert(sizeof(RenderUniforms) == 192);
static_assert(offsetof(RenderUniforms, background0) == 96);
static_assert(offsetof(RenderUniforms, sampling) == 128);
static_assert(sizeof(HitPayload) == 48);
static_assert(sizeof(RestirSurface) == 64);
static_assert(sizeof(Reservoir) == 32);
static_assert(sizeof(TextureData) == 52);
static_assert(sizeof(MaterialData) == 64);
static_assert(sizeof(LightData) == 104);
static_assert(sizeof(AliasEntry) == 12);
static_assert(offsetof(LightData, p0) == 16);
static_assert(offsetof(TextureData, color0) == 16);
} // namespace rt::shader
#endif

#endif // RT_HOST_DEVICE_H
