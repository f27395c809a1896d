// A distributed --compare's renders as tasks (Compare/RowJob.h, Compare/Ladder.h): the ladder's jobs in one
// process's order, and measurements and references that cross between ranks unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <tuple>

#include "Compare/Ladder.h"
#include "Compare/RowJob.h"
#include "Error.h"

namespace rt::compare
{
namespace
{
Image rampImage(int width, int height)
{
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.at(x, y) = vec3(float(x) * 0.25f, float(y) + 1e-7f, -float(x + y) * 3.5e9f);
    return image;
}

bool sameBits(const Image& a, const Image& b)
{
    return a.width() == b.width() && a.height() == b.height() &&
           std::memcmp(a.data(), b.data(), a.pixelCount() * sizeof(vec3)) == 0;
}

TEST(RowJobMessages, AMeasurementComesBackExactlyWithItsImage)
{
    Measurement m;
    m.spp = 64;
    m.wallMs = 12.345678901234;
    m.gpuMs = 3.25;
    m.mpathsPerSecond = 1e3 / 7.0;
    m.error.mse = 1.0 / 3.0;
    m.error.rmse = std::sqrt(1.0 / 3.0);
    m.error.relMse = 2e-300;
    m.error.trimmedRelMse = 0.5;
    m.error.mape = 0.1;
    m.error.psnr = std::numeric_limits<double>::infinity(); // identical images: JSON could not carry it
    m.error.flip = -1.0;
    m.image = rampImage(5, 3);
    std::string device;
    const Measurement back = unpackMeasurement(packMeasurement(m, true, "NVIDIA H100 80GB HBM3"), device);
    EXPECT_EQ(device, "NVIDIA H100 80GB HBM3");
    EXPECT_EQ(back.spp, 64);
    EXPECT_EQ(back.wallMs, m.wallMs);
    EXPECT_EQ(back.gpuMs, m.gpuMs);
    EXPECT_EQ(back.mpathsPerSecond, m.mpathsPerSecond);
    EXPECT_EQ(back.error.mse, m.error.mse);
    EXPECT_EQ(back.error.rmse, m.error.rmse);
    EXPECT_EQ(back.error.relMse, m.error.relMse);
    EXPECT_EQ(back.error.trimmedRelMse, m.error.trimmedRelMse);
    EXPECT_EQ(back.error.mape, m.error.mape);
    EXPECT_EQ(back.error.psnr, m.error.psnr);
    EXPECT_EQ(back.error.flip, m.error.flip);
    EXPECT_TRUE(sameBits(back.image, m.image));
    EXPECT_FALSE(back.cancelled);
}

TEST(RowJobMessages, WithoutItsImageAMeasurementIsSmall)
{
    Measurement m;
    m.spp = 4;
    m.image = rampImage(400, 300);
    std::string device;
    const std::string bytes = packMeasurement(m, false, "cpu");
    EXPECT_LT(bytes.size(), 400u);
    const Measurement back = unpackMeasurement(bytes, device);
    EXPECT_EQ(back.image.pixelCount(), 0u);
    EXPECT_EQ(back.spp, 4);
}

TEST(RowJobMessages, TruncatedOrHeaderlessBytesAreAnError)
{
    Measurement m;
    m.image = rampImage(2, 2);
    const std::string bytes = packMeasurement(m, true, "x");
    std::string device;
    EXPECT_THROW(unpackMeasurement(bytes.substr(0, bytes.size() - 1), device), Error);
    EXPECT_THROW(unpackMeasurement(bytes + "x", device), Error);
    EXPECT_THROW(unpackMeasurement("no header line", device), Error);
    EXPECT_THROW(unpackReference(bytes.substr(0, bytes.size() - 4)), Error);
}

TEST(RowJobMessages, AReferenceComesBackWithOrWithoutItsOwnRelMse)
{
    Reference r{rampImage(7, 2), 3.4e-4, "4096 spp", 4096};
    Reference back = unpackReference(packReference(r));
    EXPECT_TRUE(sameBits(back.image, r.image));
    ASSERT_TRUE(back.ownRelMse.has_value());
    EXPECT_EQ(*back.ownRelMse, 3.4e-4);
    EXPECT_EQ(back.description, "4096 spp");
    EXPECT_EQ(back.spp, 4096);
    r.ownRelMse.reset(); // a file's
    r.description = "/data/ref \"quoted\".pfm";
    back = unpackReference(packReference(r));
    EXPECT_FALSE(back.ownRelMse.has_value());
    EXPECT_EQ(back.description, r.description);
}

TEST(RowJobMessages, AJobSurvivesItsJson)
{
    const RowJob j{.engine = 2, .strategy = 3, .spp = 1, .seed = 7, .round = 4, .keepImage = true, .half = -1};
    const RowJob back = nlohmann::json::parse(nlohmann::json(j).dump()).get<RowJob>();
    EXPECT_EQ(std::tie(back.engine, back.strategy, back.spp, back.seed, back.round, back.keepImage, back.half),
              std::tie(j.engine, j.strategy, j.spp, j.seed, j.round, j.keepImage, j.half));
    EXPECT_EQ(nlohmann::json::parse(R"({"half": 1})").get<RowJob>().half, 1) << "a half names nothing else";
}

TEST(LadderJobs, OneProcesssOrderEveryRenderOnceTheGpuFirst)
{
    CompareOptions options;
    options.spps = {4, 16, 64};
    options.strategies.resize(2);
    options.seeds = 3;
    options.rounds = 2;
    std::vector<EngineUnderTest> engines;
    engines.push_back({EngineKind::Multi, nullptr});
    engines.push_back({EngineKind::Gpu, nullptr});
    for (const bool everyImage : {false, true})
    {
        const std::vector<RowJob> jobs = ladderJobs(options, engines, everyImage);
        ASSERT_EQ(jobs.size(), 2u * 2u * 2u * 3u * 3u);
        std::set<std::tuple<std::size_t, std::size_t, std::size_t, int, int>> seen;
        for (std::size_t i = 0; i < jobs.size(); ++i)
        {
            const RowJob& j = jobs[i];
            EXPECT_TRUE(seen.insert({j.engine, j.strategy, j.spp, j.seed, j.round}).second) << "job " << i << " twice";
            EXPECT_EQ(j.engine, i < jobs.size() / 2 ? 1u : 0u) << "the GPU's renders first, each engine's together";
            EXPECT_EQ(j.keepImage, j.round == 0 && (j.seed == 0 || everyImage)) << "job " << i;
            EXPECT_EQ(j.half, -1);
            if (i > 0 && jobs[i - 1].engine == j.engine)
            {
                EXPECT_LE(jobs[i - 1].round, j.round) << "rounds interleave the rows: every row, then again";
            }
        }
    }
    options.autoCandidates["estimators"] = "nee";
    EXPECT_EQ(ladderJobs(options, engines, false).size(), 2u * 2u * 3u * 3u * 3u) << "the auto row is a third";
}
} // namespace
} // namespace rt::compare
