// Pipelines specialised on a scene's features (issue 11) against the general pipeline, on the device: the
// same image within round-off for scenes that together use every feature, the hit groups and features the
// specialised pipeline was compiled with, and acceleration structures kept when only materials change.
#include <algorithm>
#include <cmath>

#include <limits>
#include <optional>

#include <gtest/gtest.h>

#include "Engine/GpuScene.h"
#include "Engine/PipelineSpecialization.h"
#include "Engine/SceneTracer.h"
#include "GpuTestEnvironment.h"
#include "RayTracing/SceneLayout.h"
#include "Scene/SceneBuilder.h"
#include "Scenes/Catalogue.h"
#include "Support/CatalogueCases.h"
#include "Support/PairedDifference.h"
#include "Support/SmallSettings.h"

namespace rt::gpu::test
{
namespace
{
using namespace shader;
using ::rt::test::differingPixels;
using ::rt::test::pairedZ;

// Together: media, motion, every texture kind, every material, every light shape (emitters and the mixture's
// sphere target), meshes, spheres and quads, thin lens, both backgrounds, and each estimator family.
const std::vector<std::string> kFeatureScenes = {
    "rtnw-final", // media, motion, image and noise textures, metal, dielectric, instances, a quad light
    "rtow-final", // spheres only, thin lens, gradient sky
    "rtnw-motion-blur", // checker texture, moving spheres
    "triangle-lights", // triangle emitters (NEE + MIS)
    "sphere-light-closeup", // sphere emitters (NEE + MIS)
    "rtrol-cornell-glass", // the mixture's sphere target beside quad emitters
    "cornell-box-and-mesh", // a mesh
};

/// The bits a render of `scene` at its own camera specialises on.
std::uint32_t renderFeatureBits(const Scene& scene)
{
    RenderUniforms u{};
    u.thinLens = scene.camera.defocusAngleDegrees > 0.0f ? 1u : 0u;
    u.backgroundType = scene.background.type;
    return PipelineSpecialization::of(u, featureBitsOf(scene, layoutScene(scene).hitGroups)).features();
}

TEST(FeatureCoverage, TheSameImageScenesUseEveryFeature)
{
    std::uint32_t all = 0;
    bool pinhole = false;
    bool constantBackground = false;
    for (const std::string& id : kFeatureScenes)
    {
        const Scene scene = makeScene(id);
        all |= renderFeatureBits(scene);
        pinhole = pinhole || scene.camera.defocusAngleDegrees == 0.0f;
        constantBackground = constantBackground || scene.background.type == BackgroundType::Constant;
    }
    EXPECT_EQ(all, 0xFFFFu) << PipelineSpecialization{{0, 0, 0, 0, all}}.describe();
    EXPECT_TRUE(pinhole && constantBackground);
}

class GpuFeatureSpecialization : public ::testing::TestWithParam<std::string>
{
protected:
    void SetUp() override
    {
        RT_REQUIRE_GPU();
        ASSERT_TRUE(sharedEngine()->validationEnabled());
        m_messagesBefore = sharedEngine()->validationMessages();
    }
    void TearDown() override
    {
        if (sharedEngine())
        {
            sharedEngine()->setSpecialize(Specialize::Full);
            EXPECT_EQ(sharedEngine()->validationMessages(), m_messagesBefore) << "Vulkan validation messages";
        }
    }

private:
    std::uint64_t m_messagesBefore = 0;
};

// The specialised pipeline leaves out code the scene cannot reach and hit groups it has no geometry for: the
// same numbers, the same paths (lavapipe: the same image bit for bit). A driver may fold arithmetic
// differently once branches are gone, and a float comparison that flips (a dielectric's reflection choice)
// sends a path elsewhere; in a medium, whose free-flight numbers hash the ray's bits, one ulp of a ray gives
// a new number, so on the H100 half of rtnw-final's pixels differ at 4 spp. The images must then agree
// within noise: the paired z of their difference under 4 (a scene rendered without a feature it needs is far
// outside that).
TEST_P(GpuFeatureSpecialization, SpecialisedAndGeneralPipelinesRenderTheSameImage)
{
    GpuEngine& engine = *sharedEngine();
    const Scene scene = makeScene(GetParam());
    RenderSettings s = ::rt::test::settingsFor(scene, 24, 4, 8);
    s.estimator = Estimator::NeeMis; // the estimator whose pipelines key on the features (the mixture's do not)

    engine.setSpecialize(Specialize::Full);
    const RenderResult specialised = renderOnGpu(scene, s);
    const PipelineScene& onDevice = engine.tracer().gpuScene().pipelineScene();
    EXPECT_EQ(onDevice.features & ~(kFeatureThinLens | kFeatureGradientBackground),
              renderFeatureBits(scene) & ~(kFeatureThinLens | kFeatureGradientBackground));
    EXPECT_NE(onDevice.features, kSpecDynamic);
    // The pipeline specialised on the settings alone (--specialize strategy) keeps every feature's code, the general
    // pipeline's: one scene of many features checks it. On lavapipe with its shader cache cold (CI's every run) its
    // compile cost each case 33 s of 84 (triangle-lights), the seven some 115 s of the default suite's 1005 s on two
    // cores; Full above folds the same settings in every scene.
    std::optional<RenderResult> strategy;
    if (GetParam() == "rtnw-final")
    {
        engine.setSpecialize(Specialize::Strategy);
        strategy = renderOnGpu(scene, s);
    }
    engine.setSpecialize(Specialize::Off);
    const RenderResult general = renderOnGpu(scene, s);

    EXPECT_EQ(specialised.stats.nanSamples + specialised.stats.infSamples, 0u);
    EXPECT_GT(specialised.image.mean().x + specialised.image.mean().y + specialised.image.mean().z, 0.0f);
    EXPECT_LT(std::abs(pairedZ(specialised.image, general.image)), 4.0)
        << differingPixels(specialised.image, general.image) << " pixels differ beyond round-off";
    if (strategy)
    {
        EXPECT_LT(std::abs(pairedZ(strategy->image, general.image)), 4.0)
            << differingPixels(strategy->image, general.image) << " pixels differ beyond round-off";
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, GpuFeatureSpecialization, ::testing::ValuesIn(kFeatureScenes),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                             return ::rt::test::testNameOf(param.param);
                         });

using GpuAccelerationStructures = GpuFeatureSpecialization;

// The window rebuilds the Scene when only the Fresnel model or a material changes: the engine keeps the
// BLASes and the TLAS (same geometry fingerprint) and uploads the rest, and the image is the one a fresh
// build gives.
TEST_F(GpuAccelerationStructures, KeptWhenOnlyMaterialsChange)
{
    GpuEngine& engine = *sharedEngine();
    SceneOptions schlick;
    schlick.fresnel = FresnelModel::Schlick;
    SceneOptions exact;
    exact.fresnel = FresnelModel::Exact;
    const Scene glassSchlick = makeScene("rtrol-cornell-glass", schlick);
    const Scene glassExact = makeScene("rtrol-cornell-glass", exact);
    const Scene other = makeScene("rtnw-quads");
    RenderSettings s = ::rt::test::settingsFor(glassExact, 16, 2, 6);
    s.estimator = Estimator::Mixture;

    engine.setScene(glassSchlick);
    const AccelerationStructureBuilds before = engine.accelerationStructureBuilds();
    const RenderResult kept = renderOnGpu(glassExact, s);
    EXPECT_EQ(engine.accelerationStructureBuilds().blas, before.blas);
    EXPECT_EQ(engine.accelerationStructureBuilds().tlas, before.tlas);
    EXPECT_EQ(engine.tracer().gpuScene().geometryReuse(), GeometryReuse::Reused);
    EXPECT_EQ(engine.buildSeconds(), 0.0);
    EXPECT_EQ(engine.stageSeconds().count("blas_build_gpu"), 0u) << "nothing built";

    engine.setScene(other);
    EXPECT_EQ(engine.accelerationStructureBuilds().blas, before.blas + 1);
    const RenderResult fresh = renderOnGpu(glassExact, s);
    EXPECT_EQ(engine.accelerationStructureBuilds().blas, before.blas + 2);
    EXPECT_EQ(engine.accelerationStructureBuilds().tlas, before.tlas + 2);
    EXPECT_EQ(kept.image.pixels(), fresh.image.pixels());
}

// Instances that move keep their BLASes: only the TLAS is built again.
TEST_F(GpuAccelerationStructures, OnlyTheTlasWhenInstancesMove)
{
    GpuEngine& engine = *sharedEngine();
    const auto scene = [](float x) {
        SceneBuilder b("moving-box");
        const std::uint32_t g = b.group("box");
        b.box(g, vec3(-0.5f), vec3(0.5f), b.lambertian(vec3(0.7f, 0.3f, 0.3f)));
        b.sphere(g, vec3(0.0f, 1.0f, 0.0f), 0.5f, b.metal(vec3(0.8f), 0.1f));
        b.instance(g, Transform::translate(vec3(x, 0.0f, 0.0f)));
        b.quad(b.world(), vec3(-2, 3, -2), vec3(4, 0, 0), vec3(0, 0, 4), b.diffuseLight(vec3(4.0f)));
        b.scene().camera.lookFrom = vec3(0.0f, 1.0f, 6.0f);
        b.scene().camera.lookAt = vec3(0.0f, 0.5f, 0.0f);
        return b.finish();
    };
    const Scene left = scene(-0.5f);
    const Scene right = scene(0.5f);
    const Scene other = makeScene("rtnw-quads");
    const RenderSettings s = ::rt::test::settingsFor(right, 16, 2, 6);

    engine.setScene(left);
    const AccelerationStructureBuilds before = engine.accelerationStructureBuilds();
    const RenderResult moved = renderOnGpu(right, s);
    EXPECT_EQ(engine.accelerationStructureBuilds().blas, before.blas);
    EXPECT_EQ(engine.accelerationStructureBuilds().tlas, before.tlas + 1);
    EXPECT_EQ(engine.tracer().gpuScene().geometryReuse(), GeometryReuse::TlasRebuilt);

    engine.setScene(other);
    const RenderResult fresh = renderOnGpu(right, s);
    EXPECT_EQ(engine.tracer().gpuScene().geometryReuse(), GeometryReuse::Built);
    EXPECT_EQ(moved.image.pixels(), fresh.image.pixels());
}
} // namespace
} // namespace rt::gpu::test
