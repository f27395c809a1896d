// The engine registry (Render/EngineRegistry.h): a program offers the engines whose registration objects it links,
// and a kind it lacks is a usage error naming it. rt_common_tests links no engine, so the registry starts empty
// here; the GPU suite (which links both engines) checks the real registrations.
#include <gtest/gtest.h>

#include "Error.h"
#include "Render/EngineRegistry.h"

namespace rt
{
namespace
{
/// An engine that renders nothing: enough to tell which factory made it and with what options.
class FakeEngine final : public RenderEngine
{
public:
    FakeEngine(EngineKind kind, const EngineOptions& options) : m_kind(kind), m_options(options) {}
    EngineKind kind() const override { return m_kind; }
    std::string deviceName() const override { return "fake"; }
    double setScene(const Scene&) override { return 0.0; }
    const Scene* scene() const override { return nullptr; }
    double buildSeconds() const override { return 0.0; }
    std::uint64_t pathsPerBatch() const override { return 1; }
    void beginFrame(const RenderSettings&) override {}
    BatchResult traceSamples(std::uint32_t, std::uint32_t, RenderControl&) override { return {}; }
    Image estimate(std::uint32_t) override { return Image(1, 1); }
    std::vector<double> radianceSums() override { return {0.0, 0.0, 0.0}; }
    SampleTally tally() const override { return {}; }
    const EngineOptions& options() const { return m_options; }

private:
    EngineKind m_kind;
    EngineOptions m_options;
};

std::unique_ptr<RenderEngine> makeFake(EngineKind kind, const EngineOptions& options)
{
    return std::make_unique<FakeEngine>(kind, options);
}

std::unique_ptr<RenderEngine> makeOtherFake(EngineKind, const EngineOptions&)
{
    return nullptr;
}

TEST(EngineRegistry, AKindNotLinkedIsAUsageErrorNamingIt)
{
    ASSERT_FALSE(engines::has(EngineKind::Gpu)) << "rt_common_tests must link no engine";
    try
    {
        engines::make(EngineKind::Gpu);
        FAIL() << "made an engine the program does not have";
    }
    catch (const UsageError& e)
    {
        EXPECT_STREQ(e.what(), "this build has no gpu engine");
    }
}

TEST(EngineRegistry, MakesTheRegisteredKindsWithTheirOptionsAndKeepsTheFirstFactory)
{
    ASSERT_TRUE(engines::add({EngineKind::Multi, EngineKind::Single}, &makeFake));
    ASSERT_TRUE(engines::add({EngineKind::Single}, &makeOtherFake)); // a second registration is ignored
    EXPECT_TRUE(engines::has(EngineKind::Single));
    EXPECT_TRUE(engines::has(EngineKind::Multi));
    EXPECT_FALSE(engines::has(EngineKind::Gpu));
    EXPECT_EQ(engines::available(), (std::vector<EngineKind>{EngineKind::Single, EngineKind::Multi}));
    const std::unique_ptr<RenderEngine> engine =
        engines::make(EngineKind::Single, EngineOptions{.specialize = Specialize::Off, .wavePaths = 7});
    ASSERT_NE(engine, nullptr) << "the second factory replaced the first";
    EXPECT_EQ(engine->kind(), EngineKind::Single);
    const auto& fake = static_cast<const FakeEngine&>(*engine);
    EXPECT_EQ(fake.options().specialize, Specialize::Off);
    EXPECT_EQ(fake.options().wavePaths, 7u);
    EXPECT_EQ(engine->validationMessages(), 0u) << "an engine without validation reports none";
}

TEST(EngineOptions, NamesRoundTrip)
{
    for (const Specialize s : {Specialize::Off, Specialize::Strategy, Specialize::Full})
        EXPECT_EQ(parseName<Specialize>(toString(s)), s);
    EXPECT_EQ(parseName<Specialize>("on"), Specialize::Full);
    EXPECT_FALSE(parseName<Specialize>("full"));
    for (const GpuIntegrator i : {GpuIntegrator::Auto, GpuIntegrator::Megakernel, GpuIntegrator::Wavefront})
        EXPECT_EQ(parseName<GpuIntegrator>(toString(i)), i);
    EXPECT_FALSE(parseName<GpuIntegrator>("wave"));
}
} // namespace
} // namespace rt
