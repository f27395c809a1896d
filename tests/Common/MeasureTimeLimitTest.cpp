// Compare/Measurement.h's time limit on an engine that cannot stop a batch (as a GPU cannot): a render traced in
// one batch that runs past the limit finishes, and is reported as timed out with its whole image, so that
// --strategy auto's pilot still stops measuring a candidate far slower than its share.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "Compare/Measurement.h"
#include "Render/RenderEngine.h"
#include "Scenes/Catalogue.h"
#include "Support/SceneHoldingEngine.h"

namespace rt::compare
{
namespace
{
/// Every batch takes `batch` on the host's clock and ignores cancellation; each pixel's sample is 1.
class UnstoppableEngine final : public SceneHoldingEngine
{
public:
    explicit UnstoppableEngine(std::chrono::milliseconds batch) : SceneHoldingEngine("unstoppable"), m_batch(batch) {}
    void beginFrame(const RenderSettings& settings) override
    {
        m_settings = settings;
        m_samples = 0;
    }
    BatchResult traceSamples(std::uint32_t, std::uint32_t count, RenderControl& control) override
    {
        std::this_thread::sleep_for(m_batch);
        m_samples += count;
        ++batches;
        control.advance(std::uint64_t(m_settings.width) * std::uint64_t(m_settings.height()) * count);
        return {};
    }
    Image estimate(std::uint32_t samples) override
    {
        Image image(m_settings.width, m_settings.height());
        for (vec3& p : image.pixels())
            p = vec3(float(m_samples) / float(samples));
        return image;
    }
    std::vector<double> radianceSums() override { return {}; }

    int batches = 0;

private:
    std::chrono::milliseconds m_batch;
    RenderSettings m_settings;
    std::uint32_t m_samples = 0;
};

/// An 8-pixel-wide render of `scene` at `spp`.
RenderRequest smallRequest(const Scene& scene, int spp)
{
    RenderRequest request;
    request.scene.id = scene.id;
    request.settings.width = 8;
    request.settings.spp = spp;
    return request;
}

TEST(MeasureTimeLimit, ARenderInOneBatchPastItsLimitIsTimedOutWithItsImage)
{
    const Scene scene = makeScene("cornell-box-lights");
    UnstoppableEngine engine(std::chrono::milliseconds(40));
    engine.setScene(scene);
    const RenderRequest request = smallRequest(scene, 16);
    const Measurement m = measure(engine, request, nullptr, std::chrono::milliseconds(5), true);
    EXPECT_EQ(engine.batches, 1);
    EXPECT_FALSE(m.cancelled);
    EXPECT_TRUE(m.timedOut) << "a 40 ms batch against a 5 ms limit";
    EXPECT_EQ(m.spp, 16);
    EXPECT_FLOAT_EQ(m.image.at(3, 3).x, 1.0f) << "the whole image, every sample in";
}

TEST(MeasureTimeLimit, WithinItsLimitOrWithoutOneARenderIsNotTimedOut)
{
    const Scene scene = makeScene("cornell-box-lights");
    UnstoppableEngine engine(std::chrono::milliseconds(1));
    engine.setScene(scene);
    const RenderRequest request = smallRequest(scene, 4);
    EXPECT_FALSE(measure(engine, request, nullptr, std::chrono::seconds(5), true).timedOut);
    EXPECT_FALSE(measure(engine, request, nullptr, {}, true).timedOut);
    EXPECT_EQ(engine.batches, 2) << "each render one batch";
}
} // namespace
} // namespace rt::compare
