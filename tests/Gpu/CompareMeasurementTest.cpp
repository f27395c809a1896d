// --compare's measurements as a paper would print them (issue 39): the same strategy listed first and last must
// come out equally efficient within the 95 % interval of their ratio, on the CPU and on the GPU. Without the
// untimed render of every strategy before timing and the interleaved rounds, the first row pays the pipeline's
// compilation and the code path's first use (on an H200, 115 ms on a 44 ms row; on lavapipe seconds): with
// neither (no warm-up, one round) this test fails on lavapipe, checked by hand.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <vector>

#include <nlohmann/json.hpp>

#include "Compare/Compare.h"
#include "Compare/Confidence.h"
#include "GpuTestEnvironment.h"
#include "Render/EngineRegistry.h"
#include "Scenes/Catalogue.h"

namespace rt::compare
{
namespace
{
/// The test process's one GPU engine (a process drives one Vulkan device) behind the factory --compare takes.
class SharedGpuEngine final : public RenderEngine
{
public:
    EngineKind kind() const override { return m_engine.kind(); }
    std::string deviceName() const override { return m_engine.deviceName(); }
    double setScene(const Scene& scene) override { return m_engine.setScene(scene); }
    const Scene* scene() const override { return m_engine.scene(); }
    double buildSeconds() const override { return m_engine.buildSeconds(); }
    std::uint64_t pathsPerBatch() const override { return m_engine.pathsPerBatch(); }
    void beginFrame(const RenderSettings& settings) override { m_engine.beginFrame(settings); }
    BatchResult traceSamples(std::uint32_t first, std::uint32_t count, RenderControl& control) override
    {
        return m_engine.traceSamples(first, count, control);
    }
    Image estimate(std::uint32_t samples) override { return m_engine.estimate(samples); }
    std::vector<double> radianceSums() override { return m_engine.radianceSums(); }
    SampleTally tally() const override { return m_engine.tally(); }

private:
    RenderEngine& m_engine = *gpu::test::sharedEngine();
};

/// relMSE x ms of each seed of one engine's row of the ladder's JSON, at the median of the seed's rounds.
std::vector<double> inverseEfficiency(const nlohmann::json& row)
{
    std::vector<double> out;
    const auto relMse = row.at("relmse_seeds").get<std::vector<double>>();
    const auto rounds = row.at("ms_rounds").get<std::vector<std::vector<double>>>();
    for (std::size_t k = 0; k < relMse.size(); ++k)
    {
        std::vector<double> t = rounds.at(k);
        std::sort(t.begin(), t.end());
        out.push_back(relMse[k] * t[t.size() / 2]);
    }
    return out;
}

TEST(CompareMeasurement, TheSameStrategyFirstAndLastIsEquallyEfficient)
{
    RT_REQUIRE_GPU();
    const Scene scene = makeScene("cornell-box-lights");
    RenderRequest base;
    base.scene.id = scene.id;
    base.settings.width = 32;
    base.settings.aspect = 1.0f;
    base.settings.depth = 8;
    base.settings.seed = 11;
    base.settings.estimator = Estimator::Mixture; // the reference's: NEE's code is cold when its first row starts
    base.settings.sampling = PixelSampling::Random;
    RenderSettings nee = base.settings;
    nee.estimator = Estimator::NeeMis;
    const RenderSettings& mixture = base.settings;
    const auto dir = std::filesystem::temp_directory_path() /
                     ("rt-compare-measurement-" + std::to_string(std::random_device{}()));
    std::filesystem::create_directories(dir);

    CompareOptions options;
    options.spps = {16};
    options.engines = {EngineKind::Multi, EngineKind::Gpu};
    options.strategies = {Strategy::of(nee), Strategy::of(mixture), Strategy::of(nee)};
    options.referenceSpp = 256;
    options.json = (dir / "table.json").string();
    options.seeds = 5;
    options.rounds = 3;
    const auto makeEngine = [](EngineKind kind) -> std::unique_ptr<RenderEngine> {
        if (kind == EngineKind::Gpu)
            return std::make_unique<SharedGpuEngine>();
        return engines::make(kind);
    };
    ASSERT_EQ(runComparison(scene, base, options, makeEngine), 0);

    const nlohmann::json table = nlohmann::json::parse(std::ifstream(dir / "table.json"));
    const nlohmann::json& rows = table.at("rows");
    ASSERT_EQ(rows.size(), 3u); // one spp for each of the three strategies, in their order
    for (const char* engine : {"multi", "gpu"})
    {
        SCOPED_TRACE(engine);
        const nlohmann::json& first = rows.at(0).at(engine);
        const nlohmann::json& last = rows.at(2).at(engine);
        EXPECT_EQ(first.at("relmse_seeds"), last.at("relmse_seeds")) << "the same seeds render the same images";
        // At 99 %: two engines' 95 % intervals would miss 1 one run in ten by chance alone (seen on the H100);
        // without warm-up and rounds the first row's ratio is far outside either.
        const Interval ratio = ratioInterval(inverseEfficiency(first), inverseEfficiency(last), 0.99);
        EXPECT_TRUE(ratio.contains(1.0)) << "first / last efficiency " << ratio.mean << " [" << ratio.lo << ", "
                                         << ratio.hi << "]";
    }
    std::filesystem::remove_all(dir);
}
} // namespace
} // namespace rt::compare
