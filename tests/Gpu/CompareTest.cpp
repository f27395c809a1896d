// The pieces of --compare that need no device: the strategy grid and its labels, the reference cache's
// matching, the CSV rows, the equal-time spp. (The app's runs are tests/Cli/compare.sh.)
#include <gtest/gtest.h>

#include <filesystem>
#include <climits>
#include <fstream>
#include <random>
#include <sstream>

#include "Compare/ConvergenceCsv.h"
#include "Compare/EqualTime.h"
#include "Compare/ReferenceCache.h"
#include "Compare/Strategy.h"
#include "Error.h"
#include "Render/EngineRegistry.h"
#include "Render/RenderRequest.h"
#include "Support/FileContents.h"

namespace rt::compare
{
namespace
{
std::filesystem::path freshFolder(const std::string& name)
{
    const auto dir = std::filesystem::temp_directory_path() /
                     (name + "-" + std::to_string(std::random_device{}()));
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace

TEST(StrategyGrid, EmptyListsGiveTheBaseSettings)
{
    RenderSettings base;
    base.estimator = Estimator::Mixture;
    base.sampling = PixelSampling::Sobol;
    const auto grid = strategyGrid({}, base);
    ASSERT_EQ(grid.size(), 1u);
    EXPECT_EQ(grid[0], Strategy::of(base));
    EXPECT_EQ(distinctLabels(grid), std::vector<std::string>{"mixture"});
}

TEST(StrategyGrid, CombinesListsAndKeepsOneOfWhatAnEstimatorIgnores)
{
    // The mixture and bsdf neither select nor sample lights: two samplers give them one strategy each.
    const auto grid = strategyGrid({{"--estimators", "bsdf,mixture,nee-mis"}, {"--light-samplers", "area,projected"}}, {});
    ASSERT_EQ(grid.size(), 4u);
    EXPECT_EQ(grid[0].settings.estimator, Estimator::BsdfOnly);
    EXPECT_EQ(grid[1].settings.estimator, Estimator::Mixture);
    EXPECT_EQ(grid[2].settings.lightSampler, LightSampler::Area);
    EXPECT_EQ(grid[3].settings.lightSampler, LightSampler::Projected);
    EXPECT_EQ(distinctLabels(grid),
              (std::vector<std::string>{"bsdf", "mixture", "nee-mis area", "nee-mis projected"}));
}

TEST(StrategyGrid, RouletteAndSamplingListsMultiply)
{
    const auto grid = strategyGrid({{"--samplings", "random,sobol"}, {"--roulettes", "on,off"}}, {});
    ASSERT_EQ(grid.size(), 4u);
    EXPECT_EQ(distinctLabels(grid),
              (std::vector<std::string>{"random rr-on", "random rr-off", "sobol rr-on", "sobol rr-off"}));
    EXPECT_EQ(grid[1].name(), "nee-mis projected bvh random rr-off");
}

TEST(StrategyGrid, BadNamesAreUsageErrorsNamingTheFlag)
{
    try
    {
        strategyGrid({{"--light-selections", "bvh,nearest"}}, {});
        FAIL() << "no error";
    }
    catch (const UsageError& e)
    {
        EXPECT_NE(std::string(e.what()).find("--light-selections"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("nearest"), std::string::npos) << e.what();
    }
    EXPECT_THROW(strategyGrid({{"--estimators", "mixture,"}}, {}), UsageError);
    EXPECT_THROW(strategyGrid({{"--roulettes", "yes"}}, {}), UsageError);
}

TEST(ReferenceCache, FindsOnlyTheReferenceOfTheSameSceneSettingsAndEngine)
{
    const auto dir = freshFolder("rt-reference-cache");
    const ReferenceCache cache(dir);
    const SceneRef ref{"rtnw-simple-light", {}};
    const Scene scene = buildScene(ref);
    RenderRequest request = defaultRequest(ref, scene);
    request.settings.width = 8;
    request.settings.aspect = 2.0f;
    Image image(8, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x)
            image.at(x, y) = vec3(float(x), float(y), 0.25f);

    EXPECT_FALSE(cache.find(scene, request, EngineKind::Gpu));
    ASSERT_FALSE(cache.store(scene, request, EngineKind::Gpu, {image, 3.5e-4}).empty());
    const auto found = cache.find(scene, request, EngineKind::Gpu);
    ASSERT_TRUE(found);
    EXPECT_EQ(found->mean.at(7, 3), image.at(7, 3));
    EXPECT_EQ(found->ownRelMse, 3.5e-4) << "the reference's own error comes back with it";

    EXPECT_FALSE(cache.find(scene, request, EngineKind::Multi)) << "another engine";
    RenderRequest otherSeed = request;
    otherSeed.settings.seed += 1;
    EXPECT_FALSE(cache.find(scene, otherSeed, EngineKind::Gpu)) << "another seed";
    RenderRequest otherSpp = request;
    otherSpp.settings.spp += 1;
    EXPECT_FALSE(cache.find(scene, otherSpp, EngineKind::Gpu)) << "another spp";
    Scene moved = scene;
    moved.lights.at(0).p0.x += 1e-3f;
    EXPECT_FALSE(cache.find(moved, request, EngineKind::Gpu)) << "a moved light";
    EXPECT_FALSE(ReferenceCache({}).find(scene, request, EngineKind::Gpu)) << "a disabled cache";
    std::filesystem::remove_all(dir);
}

TEST(SceneFingerprint, EqualForEqualScenesDifferentForAnyChangedValue)
{
    const Scene a = buildScene({"cornell-box-lights", {}});
    const Scene b = buildScene({"cornell-box-lights", {}});
    EXPECT_EQ(sceneFingerprint(a), sceneFingerprint(b));
    Scene c = a;
    c.camera.vfovDegrees += 0.5f;
    EXPECT_NE(sceneFingerprint(a), sceneFingerprint(c));
    Scene d = a;
    d.materials.back().fuzz += 0.01f;
    EXPECT_NE(sceneFingerprint(a), sceneFingerprint(d));
    Scene e = a;
    e.instances.back().worldFromObject.m[3][0] += 1.0f;
    EXPECT_NE(sceneFingerprint(a), sceneFingerprint(e));
}

TEST(ConvergenceCsv, WritesTheHeaderAndQuotesFieldsWithCommas)
{
    const auto dir = freshFolder("rt-convergence-csv");
    const auto path = dir / "rows.csv";
    {
        ConvergenceCsv csv(path);
        csv.append({"cornell-box-lights", "gpu", "llvmpipe (LLVM 15.0.7, 256 bits)", "nee-mis projected bvh random rr-on",
                    "nee-mis", 16, 12.5, 3.25, 1.5, 0.01, 0.02, 0.1, 0.00125, 7, 2, 0.015, 0.25, 0.0625, 3, 150.0,
                    225.5, 210.25});
    }
    const std::string text = test::fileContents(path);
    EXPECT_EQ(text.substr(0, text.find('\n')), ConvergenceCsv::header());
    EXPECT_NE(text.find(",\"llvmpipe (LLVM 15.0.7, 256 bits)\",nee-mis projected bvh random rr-on,nee-mis,16,12.5000,"
                        "3.2500,1.5000,0.01,0.02,0.1,0.00125,7,2,0.015,0.25,0.0625,3,150.0000,225.5000,210.2500\n"),
              std::string::npos)
        << text;
    EXPECT_THROW(ConvergenceCsv(dir / "missing" / "rows.csv"), OutputError);
    std::filesystem::remove_all(dir);
}

TEST(EqualTime, SppForBudgetRoundsDownAndStaysPositive)
{
    EXPECT_EQ(sppForBudget(1000.0, 2.5), 400);
    EXPECT_EQ(sppForBudget(1000.0, 3.0), 333);
    EXPECT_EQ(sppForBudget(1.0, 50.0), 1);
    EXPECT_EQ(sppForBudget(1e12, 1e-6), INT_MAX);
}
TEST(CompareEngines, AProgramLinkingBothEnginesOffersAllThreeThroughTheRegistry)
{
    // What --compare's default engine list is in both apps, which link rt_cpu_engines and rt_gpu_engine.
    EXPECT_EQ(engines::available(), (std::vector<EngineKind>{EngineKind::Single, EngineKind::Multi, EngineKind::Gpu}));
    const std::unique_ptr<RenderEngine> cpu = engines::make(EngineKind::Single);
    EXPECT_EQ(cpu->kind(), EngineKind::Single);
}
} // namespace rt::compare
