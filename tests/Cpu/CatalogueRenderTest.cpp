// Every scene of the catalogue renders on the single- and the multi-core engine, without a NaN or an
// infinite sample, and both engines agree bit for bit.
#include <gtest/gtest.h>

#include "RenderTestSupport.h"
#include "Scenes/Catalogue.h"
#include "Support/CatalogueCases.h"

namespace rt::test
{
namespace
{
class CpuCatalogue : public ::testing::TestWithParam<std::string>
{
};

TEST_P(CpuCatalogue, RendersWithoutNanOnBothEngines)
{
    const Scene scene = makeScene(GetParam());
    for (const Estimator estimator : {Estimator::BsdfOnly, Estimator::Mixture, Estimator::Nee, Estimator::NeeMis})
    {
        RenderSettings s = smallSettings(32, 4, 16, estimator, scene.defaults.aspect);
        s.unidirectionalLight = scene.defaults.unidirectionalLight;
        const RenderResult single = renderCpu(scene, s, EngineKind::Single);
        const RenderResult multi = renderCpu(scene, s, EngineKind::Multi);
        EXPECT_EQ(single.stats.nanSamples + single.stats.infSamples, 0u) << toString(estimator);
        EXPECT_EQ(multi.stats.nanSamples + multi.stats.infSamples, 0u) << toString(estimator);
        EXPECT_TRUE(bitIdentical(single.image, multi.image)) << toString(estimator);
        EXPECT_GT(single.image.mean().x + single.image.mean().y + single.image.mean().z, 0.0f) << "black image";
    }
}

INSTANTIATE_TEST_SUITE_P(AllScenes, CpuCatalogue, ::testing::ValuesIn(catalogueIds()),
                         [](const auto& param) { return testNameOf(param.param); });
} // namespace
} // namespace rt::test
