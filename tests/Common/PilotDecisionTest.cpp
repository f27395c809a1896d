// --strategy auto's decision (Compare/AutoStrategy.h) on an engine whose candidates' noise and cost are known:
// every pixel channel of a sample is R + sigma N(0, 1), sigma set by the light sampler and selection, and each path
// costs the same device time, so a candidate's efficiency is 1 / sigma^2 up to a constant. No timing of the host
// decides anything (the device times are the fake's), so the pilots are deterministic for their seeds.
//
// Equal candidates: each pilot is a search over 12 candidates whose luckiest draws look better than the scene's own;
// a switch is a false alarm. The pilot switches where the lead is more than twice the standard error of the ratio:
// 0 of these 40 pilots switched (1 of 200 seeds in a longer run); the test allows 4 of 40. With one standard error
// 8 of the 40 switched, and the test failed (checked).
// A candidate twice as efficient (sigma / sqrt 2): every pilot must take it. (1.25x was taken by 38 of 40 pilots,
// 1.1x by 16: the pilot's noise at these sizes, about 5 % per candidate, hides a 10 % lead.)
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "Compare/AutoStrategy.h"
#include "Render/RenderEngine.h"
#include "Scenes/Catalogue.h"

namespace rt::compare
{
namespace
{
constexpr double kSecondsPerPath = 1e-7; // the fake device's time per camera path

class NoiseEngine final : public RenderEngine
{
public:
    explicit NoiseEngine(std::function<double(const RenderSettings&)> sigma) : m_sigma(std::move(sigma)) {}
    EngineKind kind() const override { return EngineKind::Single; }
    std::string deviceName() const override { return "noise"; }
    double setScene(const Scene& scene) override
    {
        m_scene = &scene;
        return 0.0;
    }
    const Scene* scene() const override { return m_scene; }
    double buildSeconds() const override { return 0.0; }
    std::uint64_t pathsPerBatch() const override { return std::uint64_t(1) << 40; }
    void beginFrame(const RenderSettings& settings) override
    {
        m_settings = settings;
        m_sums.assign(std::size_t(settings.width) * std::size_t(settings.height()) * 3, 0.0);
    }
    BatchResult traceSamples(std::uint32_t firstSample, std::uint32_t count, RenderControl& control) override
    {
        // The sum of `count` samples of R + sigma N(0, 1) is count R + sigma sqrt(count) N(0, 1).
        std::mt19937_64 rng(std::uint64_t(m_settings.seed) * 0x9E3779B97F4A7C15ull + firstSample);
        std::normal_distribution<double> normal;
        const double sigma = m_sigma(m_settings) * std::sqrt(double(count));
        for (std::size_t k = 0; k < m_sums.size(); ++k)
            m_sums[k] += double(count) * radiance(k) + sigma * normal(rng);
        const std::uint64_t paths = std::uint64_t(m_sums.size() / 3) * count;
        control.advance(paths);
        return {.complete = true, .deviceSeconds = double(paths) * kSecondsPerPath};
    }
    Image estimate(std::uint32_t samples) override
    {
        Image image(m_settings.width, m_settings.height());
        for (std::size_t k = 0; k < m_sums.size(); ++k)
            image.data()[k / 3][int(k % 3)] = float(m_sums[k] / samples);
        return image;
    }
    std::vector<double> radianceSums() override { return m_sums; }
    SampleTally tally() const override { return {}; }

private:
    static double radiance(std::size_t k) { return 0.2 + 0.1 * double(k % 7); }

    std::function<double(const RenderSettings&)> m_sigma;
    const Scene* m_scene = nullptr;
    RenderSettings m_settings;
    std::vector<double> m_sums;
};

/// Pilots of `trials` seeds over nee-mis x 4 light samplers x 3 selections, the scene's own projected with the BVH;
/// how many chose `wanted` (or, with none, anything but the scene's own).
int pilotsChoosing(const std::function<double(const RenderSettings&)>& sigma, int trials,
                   std::optional<Strategy> wanted = {})
{
    const Scene scene = makeScene("cornell-box-lights");
    NoiseEngine engine(sigma);
    engine.setScene(scene);
    RenderRequest request;
    request.scene.id = scene.id;
    request.settings.width = 400;
    request.settings.spp = 1024;
    request.settings.estimator = Estimator::NeeMis;
    request.settings.lightSampler = LightSampler::Projected;
    request.settings.lightSelection = LightSelection::Bvh;
    const StrategyLists lists = {{"--estimators", "nee-mis"},
                                 {"--light-samplers", "projected,solid-angle,area,projected-exact"},
                                 {"--light-selections", "bvh,power,uniform"}};
    const Strategy own = Strategy::of(request.settings);
    int count = 0;
    for (int trial = 0; trial < trials; ++trial)
    {
        request.settings.seed = std::uint32_t(100 + trial);
        // A 40 s render: a pilot of 2 s of the fake's device time, 1024 pixels at a few hundred spp per half.
        const AutoChoice choice = chooseStrategy(engine, request, lists, {.renderSeconds = 40.0});
        EXPECT_FALSE(choice.budgetSpent) << "the fake's pilot takes milliseconds of the host's 2 s";
        count += wanted ? choice.chosen == *wanted : !(choice.chosen == own);
    }
    return count;
}

TEST(PilotDecision, EqualCandidatesKeepTheScenesOwn)
{
    const int switched = pilotsChoosing([](const RenderSettings&) { return 1.0; }, 40);
    EXPECT_LE(switched, 4) << "of 40 pilots over 12 equally efficient candidates";
}

TEST(PilotDecision, ACandidateTwiceAsEfficientIsTaken)
{
    RenderSettings better;
    better.estimator = Estimator::NeeMis;
    better.lightSampler = LightSampler::SolidAngle;
    better.lightSelection = LightSelection::Power;
    const int taken = pilotsChoosing(
        [](const RenderSettings& s) {
            return s.lightSampler == LightSampler::SolidAngle && s.lightSelection == LightSelection::Power
                       ? 1.0 / std::sqrt(2.0)
                       : 1.0;
        },
        10, Strategy::of(better));
    EXPECT_EQ(taken, 10);
}

} // namespace
} // namespace rt::compare
