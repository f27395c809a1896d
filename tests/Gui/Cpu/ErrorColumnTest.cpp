// The CPU window's error beside time, without a window (issue 38): the timings table asks once per row for the
// reference --compare would render (ReferenceTask.h), on the row's fastest engine, and measures every render of the
// row against it once it arrives; the convergence plot groups points into lines by engine x strategy of a work
// and measures each against its own reference.
#include <gtest/gtest.h>

#include "Gui/ConvergencePlot.h"
#include "Gui/ReferenceMemory.h"
#include "Gui/TimingsTable.h"
#include "Image/Metrics.h"

namespace rt::gui
{
namespace
{
std::shared_ptr<const Image> flat(float value, int size = 8)
{
    auto image = std::make_shared<Image>(size, size);
    for (vec3& p : image->pixels())
        p = vec3(value);
    return image;
}

RenderRequest request(int spp, Estimator estimator = Estimator::NeeMis, std::uint32_t seed = 5)
{
    RenderRequest r;
    r.scene.id = "cornell-box-lights";
    r.settings.width = 8;
    r.settings.spp = spp;
    r.settings.seed = seed;
    r.settings.estimator = estimator;
    return r;
}

RenderStats stats(const RenderRequest& r, EngineKind engine, double seconds, std::uint64_t paths)
{
    RenderStats s;
    s.request = r;
    s.engine = engine;
    s.trueSpp = r.settings.trueSpp();
    s.renderSeconds = seconds;
    s.paths = paths;
    return s;
}

FinishedReference ready(const ReferenceTask& task, std::shared_ptr<const Image> image, double own = 0.01)
{
    return {.task = task, .image = std::move(image), .ownRelMse = own};
}

TEST(TimingsTable, AsksOnceForCompareReferenceOfTheRowOnItsFastestEngine)
{
    TimingsTable table;
    table.record(stats(request(16), EngineKind::Single, 2.0, 1000), {}, flat(0.5f));
    const std::optional<ReferenceTask> task = table.referenceWanted();
    ASSERT_TRUE(task);
    EXPECT_EQ(task->engine, EngineKind::Multi) << "multi does single core's work faster";
    EXPECT_EQ(task->spp, 64) << "--compare's default: 4x the spp";
    EXPECT_EQ(task->base, request(16)) << "the render's request, seed included (the halves are at + 1000, + 2000)";
    EXPECT_FALSE(table.referenceWanted()) << "asked once per row";

    table.record(stats(request(16), EngineKind::Gpu, 0.1, 1000), {}, flat(0.5f));
    EXPECT_FALSE(table.referenceWanted()) << "the row has its reference already";
    table.record(stats(request(4), EngineKind::Single, 0.5, 1000), {}, flat(0.5f));
    table.record(stats(request(4), EngineKind::Gpu, 0.05, 1000), {}, flat(0.5f));
    const std::optional<ReferenceTask> faster = table.referenceWanted();
    ASSERT_TRUE(faster);
    EXPECT_EQ(faster->engine, EngineKind::Gpu) << "the most Mpaths/s of the row's renders when asked";
}

TEST(TimingsTable, MeasuresTheRowsRendersOnceTheirReferenceArrives)
{
    TimingsTable table;
    table.record(stats(request(16), EngineKind::Multi, 0.25, 1000), {}, flat(0.5f));
    const ReferenceTask task = *table.referenceWanted();
    const EngineTiming& cell = *table.rows()[0].engines[std::size_t(EngineKind::Multi)];
    EXPECT_FALSE(cell.relMse) << "no reference yet";

    ReferenceTask other = task;
    other.spp = 128;
    table.attach(ready(other, flat(0.4f)));
    EXPECT_FALSE(cell.relMse) << "another work's reference";

    table.attach(ready(task, flat(0.4f)));
    ASSERT_TRUE(cell.relMse);
    const double expected = 0.1 * 0.1 / (0.4 * 0.4 + kRelMseEpsilon); // (I - R)^2 / (R^2 + epsilon), every pixel
    EXPECT_NEAR(*cell.relMse, expected, 1e-6);
    EXPECT_NEAR(cell.efficiency(), 1.0 / (expected * 0.25), 1e-3);
    EXPECT_EQ(table.rows()[0].reference->state, RowReference::State::Ready);

    // A later render of the row is measured at once against the reference it has.
    table.record(stats(request(16), EngineKind::Single, 1.0, 1000), {}, flat(0.3f));
    const EngineTiming& single = *table.rows()[0].engines[std::size_t(EngineKind::Single)];
    ASSERT_TRUE(single.relMse);
    EXPECT_NEAR(*single.relMse, expected, 1e-6) << "|0.3 - 0.4| = |0.5 - 0.4|";
}

TEST(TimingsTable, AFailedReferenceLeavesTheRowUnmeasuredAndSaysWhy)
{
    TimingsTable table;
    table.record(stats(request(16), EngineKind::Multi, 0.25, 1000), {}, flat(0.5f));
    const ReferenceTask task = *table.referenceWanted();
    table.attach({.task = task, .error = "out of memory"});
    EXPECT_EQ(table.rows()[0].reference->state, RowReference::State::Failed);
    EXPECT_FALSE(table.rows()[0].engines[std::size_t(EngineKind::Multi)]->relMse);
    const nlohmann::json json = table.toJson();
    EXPECT_EQ(json[0]["reference"]["state"], "failed");
    EXPECT_EQ(json[0]["reference"]["error"], "out of memory");
    EXPECT_TRUE(json[0]["rel_mse"].is_null());
}

TEST(TimingsTable, TakesAnEngineForItsReferenceWhenTheWindowNamesOne)
{
    // The GPU window renders every reference on its device, whatever the row's fastest engine.
    TimingsTable table;
    table.record(stats(request(4), EngineKind::Multi, 0.5, 256), {}, flat(1.0f));
    const std::optional<ReferenceTask> task = table.referenceWanted(EngineKind::Gpu);
    ASSERT_TRUE(task);
    EXPECT_EQ(task->engine, EngineKind::Gpu);
    EXPECT_EQ(task->spp, 16);
}

TEST(ReferenceMemory, FindsAFinishedReferenceOfTheSameTaskOnlyAndKeepsTheNewest)
{
    ReferenceMemory memory;
    const ReferenceTask task{.base = request(4), .engine = EngineKind::Gpu, .spp = 16};
    EXPECT_FALSE(memory.find(task));
    memory.remember({.task = task, .error = "failed"});
    EXPECT_FALSE(memory.find(task)) << "a failed reference is asked for again";
    memory.remember({.task = task, .image = flat(2.0f), .ownRelMse = 0.25, .seconds = 3.0});
    const std::optional<FinishedReference> found = memory.find(task);
    ASSERT_TRUE(found);
    EXPECT_EQ(found->image->pixels()[0], vec3(2.0f));
    EXPECT_EQ(found->ownRelMse, 0.25);
    EXPECT_TRUE(found->fromCache) << "not rendered for the render that asks";
    EXPECT_EQ(found->seconds, 0.0);
    ReferenceTask otherSeed = task;
    otherSeed.base.settings.seed += 1;
    EXPECT_FALSE(memory.find(otherSeed)) << "another seed is another reference";
    ReferenceTask otherEngine = task;
    otherEngine.engine = EngineKind::Multi;
    EXPECT_FALSE(memory.find(otherEngine));
    // Past kKept, the oldest goes first.
    for (std::size_t i = 0; i < ReferenceMemory::kKept; ++i)
    {
        ReferenceTask t = task;
        t.spp = 100 + int(i);
        memory.remember({.task = t, .image = flat(1.0f)});
    }
    EXPECT_FALSE(memory.find(task));
    ReferenceTask newest = task;
    newest.spp = 100 + int(ReferenceMemory::kKept) - 1;
    EXPECT_TRUE(memory.find(newest));
}

TEST(ConvergencePlot, ALinePerEngineAndStrategyOfAWorkEachPointAgainstItsOwnReference)
{
    ConvergencePlot plot;
    const auto a = plot.add(request(4), EngineKind::Multi, "cpu", 0.1, 4, flat(0.5f), EngineKind::Multi, false);
    const auto b = plot.add(request(16), EngineKind::Multi, "cpu", 0.4, 16, flat(0.45f), EngineKind::Multi, false);
    plot.add(request(4, Estimator::Mixture), EngineKind::Multi, "cpu", 0.1, 4, flat(0.6f), EngineKind::Multi, false);
    plot.add(request(4), EngineKind::Gpu, "gpu", 0.01, 4, flat(0.5f), EngineKind::Gpu, false);
    RenderRequest wider = request(4);
    wider.settings.width = 16;
    plot.add(wider, EngineKind::Multi, "cpu", 0.1, 4, flat(0.5f, 16), EngineKind::Multi, false);
    ASSERT_TRUE(a && b);
    EXPECT_EQ(a->spp, 16);
    EXPECT_EQ(b->spp, 64);
    EXPECT_EQ(plot.lines().size(), 4u);

    const std::vector<const PlotLine*> lines = plot.linesOf(request(1, Estimator::BsdfOnly, 99));
    ASSERT_EQ(lines.size(), 3u) << "the work's lines, whatever the strategy, spp and seed asked; not the wider image";
    EXPECT_EQ(lines[0]->points.size(), 2u);
    EXPECT_EQ(shortLabels(lines), (std::vector<std::string>{"multi nee-mis", "multi mixture", "gpu nee-mis"}));
    EXPECT_EQ(shortLabels({lines[0]}), std::vector<std::string>{"multi"});

    plot.attach(ready(*b, flat(0.4f), 0.002));
    EXPECT_FALSE(lines[0]->points[0].error) << "its reference is another";
    ASSERT_TRUE(lines[0]->points[1].error);
    EXPECT_NEAR(lines[0]->points[1].error->relMse, 0.05 * 0.05 / (0.16 + kRelMseEpsilon), 1e-6);
    const std::vector<compare::ConvergenceRow> rows = ConvergencePlot::csvRows(lines);
    ASSERT_EQ(rows.size(), 1u) << "measured points only";
    EXPECT_EQ(rows[0].spp, 16);
    EXPECT_EQ(rows[0].engine, "multi");
    EXPECT_EQ(rows[0].label, "nee-mis");
    EXPECT_DOUBLE_EQ(rows[0].referenceRelMse, 0.002);
    EXPECT_DOUBLE_EQ(rows[0].wallMs, 400.0);
}

TEST(ConvergencePlot, LeavesOutAPointWhoseReferenceWouldPassTwoRendersOfTheLargestSpp)
{
    ConvergencePlot plot;
    EXPECT_FALSE(plot.add(request(kMaxSpp), EngineKind::Multi, "cpu", 1.0, kMaxSpp, flat(0.5f), EngineKind::Multi, true));
    EXPECT_TRUE(plot.add(request(kMaxSpp / 2), EngineKind::Multi, "cpu", 1.0, kMaxSpp / 2, flat(0.5f), EngineKind::Multi,
                         true));
}
} // namespace
} // namespace rt::gui
