#include "Engine/PipelineSpecialization.h"

#include "Render/RenderSettings.h"
#include "Shared/Estimator.h"

namespace rt::gpu
{
using namespace shader;

namespace
{
struct FeatureName
{
    std::uint32_t bit;
    const char* name;
};

constexpr FeatureName kFeatureNames[] = {
    {kFeatureTriangles, "triangles"},
    {kFeatureSpheres, "spheres"},
    {kFeatureMedia, "media"},
    {kFeatureMotion, "motion"},
    {kFeatureLambertian, "lambertian"},
    {kFeatureMetal, "metal"},
    {kFeatureDielectric, "dielectric"},
    {kFeatureCheckerTextures, "checker"},
    {kFeatureImageTextures, "image"},
    {kFeatureNoiseTextures, "noise"},
    {kFeatureSphereLights, "sphere-lights"},
    {kFeatureQuadLights, "quad-lights"},
    {kFeatureTriangleLights, "triangle-lights"},
    {kFeatureThinLens, "thin-lens"},
    {kFeatureGradientBackground, "gradient"},
    {kFeatureIsotropic, "isotropic"},
    {kFeatureConductor, "conductor"},
    {kFeatureRoughDielectric, "rough-dielectric"},
    {kFeatureGltfPbr, "gltf-pbr"},
};

/// The bits the render decides, not the scene: a window may open the lens of a pinhole scene's camera.
std::uint32_t uniformFeatureBits(const RenderUniforms& u)
{
    std::uint32_t bits = 0;
    if (u.thinLens != 0u)
        bits |= kFeatureThinLens;
    if (u.backgroundType == BackgroundType::Gradient)
        bits |= kFeatureGradientBackground;
    return bits;
}
} // namespace

PipelineSpecialization PipelineSpecialization::general()
{
    PipelineSpecialization s;
    s.constants.fill(kSpecDynamic);
    return s;
}

PipelineSpecialization PipelineSpecialization::strategyOf(const RenderUniforms& u)
{
    PipelineSpecialization s = general();
    s.constants[kSpecIdEstimator] = static_cast<std::uint32_t>(u.estimator);
    // Only NEE samples lights: the other estimators share one pipeline whatever the sampler and selection.
    const bool nee = shader::usesNee(u.estimator);
    s.constants[kSpecIdLightSampler] = nee ? static_cast<std::uint32_t>(u.lightSampler) : 0u;
    s.constants[kSpecIdLightSelection] = nee ? static_cast<std::uint32_t>(u.lightSelection) : 0u;
    // Accumulate is random jitter to the shaders (the passes are the host's): one pipeline serves both.
    const PixelSampling sampling = u.sampling == PixelSampling::Accumulate ? PixelSampling::Random : u.sampling;
    s.constants[kSpecIdSampling] = static_cast<std::uint32_t>(sampling);
    s.constants[kSpecIdCountRays] = u.countRays != 0u ? 1u : 0u;
    static_assert(kSpecIdCount == 8, "a new constant id needs its value here");
    return s;
}

PipelineSpecialization PipelineSpecialization::of(const RenderUniforms& u, std::uint32_t sceneFeatures,
                                                  bool hugeSpheres)
{
    PipelineSpecialization s = strategyOf(u);
    s.constants[kSpecIdFeatures] = (sceneFeatures & ~(kFeatureThinLens | kFeatureGradientBackground)) |
                                   uniformFeatureBits(u);
    s.setSceneConstants(sceneFeatures, hugeSpheres);
    return s;
}

PipelineSpecialization PipelineSpecialization::of(Specialize specialize, const RenderUniforms& u,
                                                  std::uint32_t sceneFeatures, bool hugeSpheres)
{
    switch (specialize)
    {
    case Specialize::Off: return general();
    case Specialize::Strategy: return strategyOf(u);
    case Specialize::Full:
    {
        // Measured on the H100 (docs/notebook/PERFORMANCE.md §9.6, which overturns §4.3's rule of a mixture
        // keyed on its strategy alone): with the scene's feature mask, book 3's mixture renders the book scenes
        // 1.04-1.12x faster and cornell-box-lights as fast, but rtnw-cornell-smoke 0.93x. So a mixture in a
        // scene with media keeps its mask dynamic, with the sphere tests' c (§8.8) and the hit's uv (§8.10).
        // Its mask leaves out only the microfacet materials the scene lacks, which came after that measurement
        // (rtnw-cornell-smoke 0.94x with their code compiled in; docs/notebook §10).
        if (u.estimator == Estimator::Mixture && (sceneFeatures & kFeatureMedia) != 0u)
        {
            PipelineSpecialization s = strategyOf(u);
            constexpr std::uint32_t microfacet = kFeatureConductor | kFeatureRoughDielectric | kFeatureGltfPbr;
            s.constants[kSpecIdFeatures] = kSpecDynamic & ~(microfacet & ~sceneFeatures);
            s.setSceneConstants(sceneFeatures, hugeSpheres);
            return s;
        }
        return of(u, sceneFeatures, hugeSpheres);
    }
    }
    return general();
}

void PipelineSpecialization::setSceneConstants(std::uint32_t sceneFeatures, bool hugeSpheres)
{
    constants[kSpecIdExactSphereC] = hugeSpheres ? 1u : 0u;
    constants[kSpecIdHitUv] = (sceneFeatures & kFeatureImageTextures) != 0u ? 1u : 0u;
}

HitGroupLayout PipelineSpecialization::hitGroups() const
{
    return {has(kFeatureTriangles), has(kFeatureSpheres), has(kFeatureMedia)};
}

std::string PipelineSpecialization::describe() const
{
    if (*this == general())
        return "general";
    // By the command line's names; "any": read from the uniforms at run time.
    const auto value = [this](std::uint32_t id, auto name) -> std::string {
        return constants[id] == kSpecDynamic ? "any" : name(constants[id]);
    };
    std::string s = "estimator=" + value(kSpecIdEstimator, [](std::uint32_t v) { return toString(Estimator(v)); }) +
                    " sampler=" + value(kSpecIdLightSampler, [](std::uint32_t v) { return toString(LightSampler(v)); }) +
                    " selection=" +
                    value(kSpecIdLightSelection, [](std::uint32_t v) { return toString(LightSelection(v)); }) +
                    " sampling=" + value(kSpecIdSampling, [](std::uint32_t v) { return toString(PixelSampling(v)); }) +
                    " sphere-c=" +
                    value(kSpecIdExactSphereC, [](std::uint32_t v) { return v != 0u ? "exact" : "float"; }) +
                    " uv=" + value(kSpecIdHitUv, [](std::uint32_t v) { return v != 0u ? "on" : "off"; }) +
                    (constants[kSpecIdCountRays] == 1u ? " rays=counted " : " ");
    s += "features=";
    if (features() == kSpecDynamic)
        return s + "all";
    bool first = true;
    for (const FeatureName& f : kFeatureNames)
        if (has(f.bit))
        {
            if (!first)
                s += '+';
            s += f.name;
            first = false;
        }
    return first ? s + "none" : s;
}

std::uint32_t featureBitsOf(const Scene& scene, const HitGroupLayout& hitGroups)
{
    return featureBitsOf(scene, featuresOf(scene), hitGroups);
}

std::uint32_t featureBitsOf(const Scene& scene, const SceneFeatures& f, const HitGroupLayout& hitGroups)
{
    std::uint32_t bits = 0;
    const auto set = [&bits](bool on, std::uint32_t bit) { bits |= on ? bit : 0u; };
    set(hitGroups.has(HitGroupKind::Triangles), kFeatureTriangles);
    set(hitGroups.has(HitGroupKind::Spheres), kFeatureSpheres);
    set(hitGroups.has(HitGroupKind::Media), kFeatureMedia);
    set(f.motionBlur, kFeatureMotion);
    set(f.lambertian, kFeatureLambertian);
    set(f.metal, kFeatureMetal);
    set(f.dielectric, kFeatureDielectric);
    set(f.conductor, kFeatureConductor);
    set(f.roughDielectric, kFeatureRoughDielectric);
    set(f.gltfPbr, kFeatureGltfPbr);
    // Any isotropic material, used or not (SceneFeatures counts them under media; one on a surface is legal).
    for (const MaterialData& m : scene.materials)
        set(m.type == MaterialType::Isotropic, kFeatureIsotropic);
    set(f.checkerTextures, kFeatureCheckerTextures);
    set(f.imageTextures, kFeatureImageTextures);
    set(f.noiseTextures, kFeatureNoiseTextures);
    // Every light, not only the emitters: the mixture samples the sampling targets too (book 3's glass sphere).
    for (const LightData& light : scene.lights)
        switch (light.shape)
        {
        case LightShape::Sphere: bits |= kFeatureSphereLights; break;
        case LightShape::Quad: bits |= kFeatureQuadLights; break;
        case LightShape::Triangle: bits |= kFeatureTriangleLights; break;
        }
    return bits;
}
} // namespace rt::gpu
