// The pipeline cache's key (host only): what each --specialize mode keys on, the feature bits of catalogue
// scenes, and the hit groups a key's pipeline holds.
#include <gtest/gtest.h>

#include "Engine/PipelineSpecialization.h"
#include "RayTracing/SceneLayout.h"
#include "Scenes/Catalogue.h"

namespace rt::gpu
{
namespace
{
using namespace shader;

std::uint32_t bitsOf(const Scene& scene) { return featureBitsOf(scene, layoutScene(scene).hitGroups); }

RenderUniforms uniformsWith(Estimator estimator, bool thinLens, BackgroundType background)
{
    RenderUniforms u{};
    u.estimator = estimator;
    u.lightSampler = LightSampler::Projected;
    u.lightSelection = LightSelection::Bvh;
    u.sampling = PixelSampling::Accumulate;
    u.thinLens = thinLens ? 1u : 0u;
    u.backgroundType = background;
    return u;
}

TEST(PipelineSpecialization, ModesKeyOnWhatTheySay)
{
    const std::uint32_t scene = kFeatureTriangles | kFeatureLambertian | kFeatureQuadLights | kFeatureThinLens;
    const RenderUniforms u = uniformsWith(Estimator::NeeMis, false, BackgroundType::Constant);
    EXPECT_EQ(PipelineSpecialization::of(Specialize::Off, u, scene), PipelineSpecialization::general());
    const PipelineSpecialization strategy = PipelineSpecialization::of(Specialize::Strategy, u, scene);
    EXPECT_EQ(strategy.features(), kSpecDynamic) << "every feature";
    EXPECT_EQ(strategy.constants[kSpecIdLightSelection], std::uint32_t(LightSelection::Bvh));
    EXPECT_EQ(strategy.constants[kSpecIdSampling], std::uint32_t(PixelSampling::Random)) << "accumulate is random";
    const PipelineSpecialization full = PipelineSpecialization::of(Specialize::Full, u, scene);
    EXPECT_EQ(full.features(), kFeatureTriangles | kFeatureLambertian | kFeatureQuadLights)
        << "the lens is the render camera's, not the scene's";
    EXPECT_TRUE(PipelineSpecialization::of(uniformsWith(Estimator::NeeMis, true, BackgroundType::Gradient), 0)
                    .has(kFeatureThinLens | kFeatureGradientBackground));
    EXPECT_EQ(full.hitGroups(), HitGroupLayout(true, false, false));
    EXPECT_EQ(PipelineSpecialization::general().hitGroups(), HitGroupLayout::all());
    EXPECT_EQ(PipelineSpecialization::general().describe(), "general");
    EXPECT_NE(full.describe().find("features=triangles+lambertian+quad-lights"), std::string::npos) << full.describe();
    // The mixture samples no light by NEE: one key whatever the sampler and selection.
    RenderUniforms mixture = uniformsWith(Estimator::Mixture, false, BackgroundType::Constant);
    const PipelineSpecialization a = PipelineSpecialization::of(mixture, scene);
    mixture.lightSelection = LightSelection::Uniform;
    EXPECT_EQ(a, PipelineSpecialization::of(mixture, scene));
    // The mixture has its scene's mask under --specialize on, but in a scene with media (measured on the H100).
    EXPECT_EQ(PipelineSpecialization::of(Specialize::Full, mixture, scene).features(),
              kFeatureTriangles | kFeatureLambertian | kFeatureQuadLights);
    PipelineSpecialization mixtureInMedia =
        PipelineSpecialization::of(Specialize::Full, mixture, scene | kFeatureMedia | kFeatureIsotropic);
    EXPECT_EQ(mixtureInMedia.constants[kSpecIdExactSphereC], 1u);
    EXPECT_EQ(mixtureInMedia.constants[kSpecIdHitUv], 0u) << "no image texture";
    EXPECT_EQ(mixtureInMedia.features(), kSpecDynamic & ~(kFeatureConductor | kFeatureRoughDielectric | kFeatureGltfPbr))
        << "every feature but the microfacet materials the scene lacks";
    EXPECT_EQ(PipelineSpecialization::of(Specialize::Full, mixture, scene | kFeatureMedia | kFeatureConductor)
                  .features(),
              kSpecDynamic & ~(kFeatureRoughDielectric | kFeatureGltfPbr));
    mixtureInMedia.constants[kSpecIdExactSphereC] = kSpecDynamic;
    mixtureInMedia.constants[kSpecIdHitUv] = kSpecDynamic;
    mixtureInMedia.constants[kSpecIdFeatures] = kSpecDynamic;
    EXPECT_EQ(mixtureInMedia, PipelineSpecialization::strategyOf(mixture))
        << "but the sphere tests' c, the uv (below) and the microfacet materials";
    EXPECT_NE(PipelineSpecialization::of(Specialize::Full, u, scene | kFeatureMedia).features(), kSpecDynamic)
        << "NEE has its mask with media too";
    EXPECT_NE(PipelineSpecialization::of(Specialize::Full, u, scene), PipelineSpecialization::strategyOf(u));
}

// The sphere tests' exact c (kSpecIdExactSphereC): left out by --specialize on for a scene without huge spheres,
// the pipeline of a mixture with media included (its feature mask stays dynamic); kept by the general and
// strategy-only ones.
TEST(PipelineSpecialization, ExactSphereCOnlyForHugeSpheres)
{
    const std::uint32_t scene = kFeatureSpheres | kFeatureLambertian | kFeatureMedia | kFeatureIsotropic;
    for (const Estimator e : {Estimator::Mixture, Estimator::NeeMis})
    {
        const RenderUniforms u = uniformsWith(e, false, BackgroundType::Constant);
        const PipelineSpecialization small = PipelineSpecialization::of(Specialize::Full, u, scene, false);
        EXPECT_EQ(small.constants[kSpecIdExactSphereC], 0u);
        EXPECT_NE(small.describe().find("sphere-c=float"), std::string::npos) << small.describe();
        EXPECT_EQ(PipelineSpecialization::of(Specialize::Full, u, scene, true).constants[kSpecIdExactSphereC], 1u);
        EXPECT_NE(PipelineSpecialization::of(Specialize::Full, u, scene, true), small) << "two pipelines";
        EXPECT_EQ(PipelineSpecialization::of(Specialize::Strategy, u, scene, false).constants[kSpecIdExactSphereC],
                  kSpecDynamic);
        EXPECT_EQ(PipelineSpecialization::of(Specialize::Off, u, scene, false), PipelineSpecialization::general());
    }
    const RenderUniforms mixture = uniformsWith(Estimator::Mixture, false, BackgroundType::Constant);
    EXPECT_EQ(PipelineSpecialization::of(Specialize::Full, mixture, scene, false).features(),
              kSpecDynamic & ~(kFeatureConductor | kFeatureRoughDielectric | kFeatureGltfPbr))
        << "the mixture's feature mask stays dynamic in a scene with media, but for the microfacet materials";
}

// The hit's uv (kSpecIdHitUv): computed only for a scene with image textures under --specialize on, the mixture's
// pipeline included; always by the general and strategy-only ones.
TEST(PipelineSpecialization, HitUvOnlyWithImageTextures)
{
    const std::uint32_t plain = kFeatureSpheres | kFeatureTriangles | kFeatureLambertian | kFeatureCheckerTextures |
                                kFeatureNoiseTextures;
    const std::uint32_t textured = plain | kFeatureImageTextures;
    for (const Estimator e : {Estimator::Mixture, Estimator::NeeMis, Estimator::BsdfOnly})
    {
        const RenderUniforms u = uniformsWith(e, false, BackgroundType::Constant);
        const PipelineSpecialization without = PipelineSpecialization::of(Specialize::Full, u, plain, false);
        EXPECT_EQ(without.constants[kSpecIdHitUv], 0u);
        EXPECT_NE(without.describe().find("uv=off"), std::string::npos) << without.describe();
        const PipelineSpecialization with = PipelineSpecialization::of(Specialize::Full, u, textured, false);
        EXPECT_EQ(with.constants[kSpecIdHitUv], 1u);
        EXPECT_NE(with, without) << "two pipelines";
        EXPECT_EQ(PipelineSpecialization::of(Specialize::Strategy, u, plain, false).constants[kSpecIdHitUv],
                  kSpecDynamic);
    }
    EXPECT_EQ(PipelineSpecialization::of(Specialize::Full, uniformsWith(Estimator::Mixture, false, BackgroundType::Constant),
                                         bitsOf(makeScene("rtnw-earth")), false)
                  .constants[kSpecIdHitUv],
              1u)
        << "the earth's image texture reads the sphere's uv";
}

TEST(PipelineSpecialization, CatalogueScenesHaveTheirFeatureBits)
{
    const std::uint32_t glass = bitsOf(makeScene("rtrol-cornell-glass"));
    EXPECT_EQ(glass & (kFeatureTriangles | kFeatureSpheres | kFeatureMedia), kFeatureTriangles | kFeatureSpheres);
    EXPECT_TRUE(glass & kFeatureSphereLights) << "the glass sphere is the mixture's sampling target";
    EXPECT_TRUE(glass & kFeatureQuadLights);
    EXPECT_FALSE(glass & (kFeatureTriangleLights | kFeatureMetal | kFeatureIsotropic | kFeatureImageTextures));
    const std::uint32_t smoke = bitsOf(makeScene("rtnw-cornell-smoke"));
    EXPECT_TRUE((smoke & kFeatureMedia) && (smoke & kFeatureIsotropic));
    EXPECT_FALSE(smoke & (kFeatureSpheres | kFeatureMotion));
    const std::uint32_t earth = bitsOf(makeScene("rtnw-earth"));
    EXPECT_EQ(earth & (kFeatureImageTextures | kFeatureTriangles), kFeatureImageTextures);
    EXPECT_TRUE(bitsOf(makeScene("rtnw-motion-blur")) & kFeatureMotion);
    EXPECT_TRUE(bitsOf(makeScene("triangle-lights")) & kFeatureTriangleLights);
    EXPECT_EQ(bitsOf(makeScene("rtnw-quads")) & (kFeatureSphereLights | kFeatureQuadLights | kFeatureTriangleLights),
              0u) << "no light";
}
} // namespace
} // namespace rt::gpu
