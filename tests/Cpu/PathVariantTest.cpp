// The path loop's specialised instances (Integrator/PathVariants.h, issue 11) against the general one: each is
// compiled without what the scene lacks, draws the same random numbers, and so must render the same image bit
// for bit, for every catalogue scene and every estimator. A variant that dropped a feature the scene has
// (media, a texture) would differ here.
#include <gtest/gtest.h>

#include <spdlog/fmt/fmt.h>

#include "Integrator/PathVariants.h"
#include "RenderTestSupport.h"
#include "Render/RenderDriver.h"
#include "Scene/SceneFeatures.h"
#include "Scenes/Catalogue.h"
#include "Support/RenderWithSettings.h"

namespace rt::test
{
namespace
{
Image renderWith(const Scene& scene, const RenderSettings& settings, bool specialize, std::string* variant = nullptr)
{
    cpu::CpuEngine engine(EngineKind::Multi, specialize);
    engine.setScene(scene);
    RenderControl control;
    Image image = renderWithSettings(engine, settings, control).image;
    if (variant)
        *variant = engine.pathVariant();
    return image;
}

TEST(CpuPathVariants, EverySceneAndEstimatorRendersTheGeneralLoopsImageBitForBit)
{
    for (const SceneInfo& info : sceneCatalogue())
    {
        SceneOptions options;
        if (info.takes & kTakesCount)
            options.count = info.id == "many-lights" ? 40 : 200; // the scene, smaller
        const Scene scene = makeScene(info.id, options);
        for (const Estimator estimator : {Estimator::BsdfOnly, Estimator::Mixture, Estimator::Nee, Estimator::NeeMis})
        {
            const RenderSettings s = smallSettings(20, 2, 8, estimator, 1.5f);
            std::string variant;
            const Image specialised = renderWith(scene, s, true, &variant);
            EXPECT_NE(variant, "general");
            EXPECT_TRUE(bitIdentical(specialised, renderWith(scene, s, false)))
                << info.id << " with " << toString(estimator) << ": " << variant;
        }
    }
}

TEST(CpuPathVariants, TheChoiceFollowsTheScenesFeaturesAndTheEstimator)
{
    const SceneFeatures smoke = featuresOf(makeScene("rtnw-cornell-smoke"));
    const cpu::PathVariant v = cpu::choosePathVariant(smoke, Estimator::Nee, true);
    EXPECT_FALSE(v.code.general);
    EXPECT_EQ(v.code.estimator, Estimator::Nee);
    EXPECT_TRUE(v.code.media);
    EXPECT_FALSE(v.code.textures);
    EXPECT_EQ(v.describe(), "nee, media, solid colours only");

    const cpu::PathVariant earth =
        cpu::choosePathVariant(featuresOf(makeScene("rtnw-earth")), Estimator::Mixture, true);
    EXPECT_TRUE(earth.code.textures);
    EXPECT_FALSE(earth.code.media);
    EXPECT_NE(earth.trace, v.trace);

    // --stats says which loop ran (frame_configuration).
    const Scene earthScene = makeScene("rtnw-earth"); // the engine keeps a pointer to it
    cpu::CpuEngine engine(EngineKind::Single);
    engine.setScene(earthScene);
    RenderControl control;
    const RenderResult r = renderWithSettings(engine, smallSettings(8, 1, 4, Estimator::Mixture), control);
    EXPECT_EQ(r.stats.frameConfiguration,
              fmt::format("path loop: mixture, no media, textures or microfacet, {} rays at a time "
                          "(scene: spheres lambertian "
                          "image-textures)",
                          cpu::kLanes));

    // kLanes paths at a time only where the scene's rays can be tested in lanes, for every estimator; never
    // in the general loop nor with media.
    const SceneFeatures lights = featuresOf(makeScene("cornell-box-lights"));
    for (const Estimator e : {Estimator::BsdfOnly, Estimator::Mixture, Estimator::Nee, Estimator::NeeMis})
    {
        EXPECT_NE(cpu::choosePathVariant(lights, e, true, true).traceLanes, nullptr);
        EXPECT_EQ(cpu::choosePathVariant(lights, e, true, false).traceLanes, nullptr);
        EXPECT_EQ(cpu::choosePathVariant(lights, e, false, true).traceLanes, nullptr);
        EXPECT_EQ(cpu::choosePathVariant(smoke, e, true, true).traceLanes, nullptr); // media
    }
    EXPECT_EQ(cpu::choosePathVariant(lights, Estimator::Mixture, true, false).describe(),
              "mixture, no media, solid colours only");

    const cpu::PathVariant general = cpu::choosePathVariant(smoke, Estimator::Nee, false);
    EXPECT_TRUE(general.code.general);
    EXPECT_EQ(general.describe(), "general");
}
} // namespace
} // namespace rt::test
