// Render/RenderSettings.h, Cli/CommonOptions.h and Render/RenderStats.h: what a render is asked to do,
// checked before anything runs, and what it reports. seed-findings CPU 1: stratified sampling takes
// floor(sqrt(spp))^2 samples and must say so.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "Cli/CommonOptions.h"
#include "Error.h"
#include "Render/RenderSettings.h"
#include "Render/RenderStats.h"
#include "Scenes/Catalogue.h"

namespace rt
{
namespace
{
/// validate() throws UsageError whose message mentions `word`.
void expectRejected(const RenderSettings& s, const std::string& word)
{
    try
    {
        s.validate();
        ADD_FAILURE() << "accepted; expected a complaint about " << word;
    }
    catch (const UsageError& e)
    {
        EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
}

TEST(RenderSettings, DefaultsAreValid) { EXPECT_NO_THROW(RenderSettings{}.validate()); }

TEST(RenderSettings, ValidateRejectsImpossibleValues)
{
    const auto with = [](auto change) {
        RenderSettings s;
        change(s);
        return s;
    };
    expectRejected(with([](RenderSettings& s) { s.spp = 0; }), "samples");
    expectRejected(with([](RenderSettings& s) { s.spp = -3; }), "samples");
    expectRejected(with([](RenderSettings& s) { s.depth = 0; }), "depth");
    expectRejected(with([](RenderSettings& s) { s.width = 0; }), "width");
    expectRejected(with([](RenderSettings& s) { s.width = -640; }), "width");
    expectRejected(with([](RenderSettings& s) { s.aspect = 0.0f; }), "aspect");
    expectRejected(with([](RenderSettings& s) { s.aspect = -1.5f; }), "aspect");
    expectRejected(with([](RenderSettings& s) { s.aspect = std::numeric_limits<float>::quiet_NaN(); }), "aspect");
    expectRejected(with([](RenderSettings& s) { s.aspect = std::numeric_limits<float>::infinity(); }), "aspect");
    // The smallest legal values pass.
    EXPECT_NO_THROW(with([](RenderSettings& s) { s.spp = 1, s.depth = 1, s.width = 1; }).validate());
}

TEST(RenderSettings, TrueSppIsTheStratifiedSquare)
{
    RenderSettings s;
    s.sampling = PixelSampling::Stratified;
    for (const auto& [spp, taken] : {std::pair{10, 9}, {16, 16}, {1, 1}, {99, 81}, {100, 100}, {3, 1}})
    {
        s.spp = spp;
        EXPECT_EQ(s.trueSpp(), taken) << "stratified spp " << spp;
    }
    for (PixelSampling sampling : {PixelSampling::Random, PixelSampling::Accumulate})
    {
        s.sampling = sampling;
        s.spp = 10;
        EXPECT_EQ(s.trueSpp(), 10) << toString(sampling);
    }
}

TEST(RenderSettings, HeightRoundsWidthOverAspect)
{
    const auto height = [](int width, float aspect) {
        RenderSettings s;
        s.width = width;
        s.aspect = aspect;
        return s.height();
    };
    EXPECT_EQ(height(600, 1.0f), 600);
    EXPECT_EQ(height(400, 16.0f / 9.0f), 225);
    EXPECT_EQ(height(1000, 3.0f), 333); // 333.3
    EXPECT_EQ(height(1000, 0.7f), 1429); // 1428.6: rounded, not truncated
    EXPECT_EQ(height(1001, 1.5f), 667); // 667.3
    EXPECT_EQ(height(1, 10.0f), 1); // never 0 rows
}

TEST(RenderSettings, NamesRoundTrip)
{
    for (PixelSampling p : {PixelSampling::Random, PixelSampling::Stratified, PixelSampling::Accumulate})
        EXPECT_EQ(parseName<PixelSampling>(toString(p)), p);
    for (EngineKind e : {EngineKind::Single, EngineKind::Multi, EngineKind::Gpu})
        EXPECT_EQ(parseName<EngineKind>(toString(e)), e);
    EXPECT_FALSE(parseName<PixelSampling>("Stratified").has_value()); // exact names only
    EXPECT_FALSE(parseName<EngineKind>("cpu").has_value());
}

TEST(ResolveRequest, FlagsOverrideTheScenesDefaults)
{
    const Scene scene = makeScene("rtow-final"); // 16:9, its own defaults
    CommonOptions options;
    options.scene = "rtow-final";
    RenderSettings s = resolveRequest(options, scene).settings;
    EXPECT_EQ(s.spp, scene.defaults.spp);
    EXPECT_EQ(s.depth, scene.defaults.depth);
    EXPECT_EQ(s.width, scene.defaults.width);
    EXPECT_EQ(s.aspect, scene.defaults.aspect);
    EXPECT_EQ(s.unidirectionalLight, scene.defaults.unidirectionalLight);

    options.settings["spp"] = "7";
    options.settings["depth"] = "3";
    options.settings["width"] = "320";
    options.settings["aspect"] = "2";
    options.settings["sampling"] = "stratified";
    options.pdf = "off";
    options.settings["unidirectional-light"] = scene.defaults.unidirectionalLight ? "off" : "on";
    options.settings["seed"] = "12";
    options.count = 5;
    options.mesh = "meshes/other.obj";
    const RenderRequest request = resolveRequest(options, scene);
    EXPECT_EQ(request.scene.id, "rtow-final");
    EXPECT_EQ(request.scene.options.count, 5);
    EXPECT_EQ(request.scene.options.meshPath, "meshes/other.obj");
    s = request.settings;
    EXPECT_EQ(s.spp, 7);
    EXPECT_EQ(s.depth, 3);
    EXPECT_EQ(s.width, 320);
    EXPECT_EQ(s.aspect, 2.0f);
    EXPECT_EQ(s.height(), 160);
    EXPECT_EQ(s.sampling, PixelSampling::Stratified);
    EXPECT_EQ(s.trueSpp(), 4);
    EXPECT_EQ(s.estimator, Estimator::BsdfOnly);
    EXPECT_NE(s.unidirectionalLight, scene.defaults.unidirectionalLight);
    EXPECT_EQ(s.seed, 12u);
}

TEST(ResolveRequest, EstimatorComesFromTheSceneUnlessNamed)
{
    // The project's scenes use NEE + MIS, the books' the mixture their images were made with.
    CommonOptions options;
    EXPECT_EQ(resolveRequest(options, makeScene("cornell-box-lights")).settings.estimator, Estimator::NeeMis);
    EXPECT_EQ(resolveRequest(options, makeScene("rtrol-cornell-box")).settings.estimator, Estimator::Mixture);
    EXPECT_EQ(resolveRequest(options, makeScene("rtrol-cornell-box")).settings.russianRoulette, RussianRoulette::Sqrt);
    options.settings["russian-roulette"] = "on";
    EXPECT_EQ(resolveRequest(options, makeScene("rtrol-cornell-box")).settings.russianRoulette,
              RussianRoulette::Throughput);
    options.settings["russian-roulette"] = "throughput"; // the alias of on
    EXPECT_EQ(resolveRequest(options, makeScene("rtrol-cornell-box")).settings.russianRoulette,
              RussianRoulette::Throughput);
    options.settings["estimator"] = "nee";
    options.settings["russian-roulette"] = "off";
    const RenderSettings s = resolveRequest(options, makeScene("rtrol-cornell-box")).settings;
    EXPECT_EQ(s.estimator, Estimator::Nee);
    EXPECT_EQ(s.russianRoulette, RussianRoulette::Off);
    options.settings["estimator"] = "mixture";
    options.pdf = "on"; // agrees: accepted
    EXPECT_EQ(resolveRequest(options, makeScene("cornell-box-lights")).settings.estimator, Estimator::Mixture);
}

TEST(ResolveRequest, SamplingComesFromTheSceneUnlessNamed)
{
    // The project's scenes draw Owen-scrambled Sobol samples, the books' the independent ones of their code.
    CommonOptions options;
    EXPECT_EQ(resolveRequest(options, makeScene("cornell-box-lights")).settings.sampling, PixelSampling::Sobol);
    EXPECT_EQ(resolveRequest(options, makeScene("many-lights")).settings.sampling, PixelSampling::Sobol);
    for (const char* book : {"rtow-final", "rtnw-final", "rtrol-cornell-glass"})
        EXPECT_EQ(resolveRequest(options, makeScene(book)).settings.sampling, PixelSampling::Random) << book;
    options.settings["sampling"] = "random";
    EXPECT_EQ(resolveRequest(options, makeScene("cornell-box-lights")).settings.sampling, PixelSampling::Random);
    options.settings["sampling"] = "sobol";
    EXPECT_EQ(resolveRequest(options, makeScene("rtrol-cornell-glass")).settings.sampling, PixelSampling::Sobol);
}

TEST(ResolveRequest, BadFlagsAreUsageErrors)
{
    const Scene scene = makeScene("rtow-camera-test");
    const auto rejects = [&](auto change) {
        CommonOptions o;
        change(o);
        EXPECT_THROW(resolveRequest(o, scene), UsageError);
    };
    rejects([](CommonOptions& o) { o.settings["spp"] = "0"; });
    rejects([](CommonOptions& o) { o.settings["width"] = "-1"; });
    rejects([](CommonOptions& o) { o.settings["aspect"] = "0"; });
    rejects([](CommonOptions& o) { o.settings["sampling"] = "jittered"; });
    rejects([](CommonOptions& o) { o.pdf = "maybe"; });
    rejects([](CommonOptions& o) { o.settings["estimator"] = "path"; });
    rejects([](CommonOptions& o) { o.settings["russian-roulette"] = "sometimes"; });
    rejects([](CommonOptions& o) {
        o.settings["estimator"] = "nee";
        o.pdf = "on";
    });
    rejects([](CommonOptions& o) { o.settings["unidirectional-light"] = "yes please"; });
}

TEST(RenderStats, JsonReportsWhatWasRendered)
{
    RenderStats stats;
    stats.request.scene = {.id = "white-spheres", .options = {.count = 300}};
    stats.engine = EngineKind::Multi;
    stats.request.settings.spp = 10;
    stats.request.settings.sampling = PixelSampling::Stratified;
    stats.width = 60;
    stats.height = 40;
    stats.trueSpp = stats.request.settings.trueSpp();
    stats.paths = 60ull * 40 * 9;
    stats.renderSeconds = 0.5;
    const nlohmann::json j = stats.toJson();
    EXPECT_EQ(j.at("scene"), "white-spheres");
    EXPECT_EQ(j.at("scene_options").at("count"), 300);
    EXPECT_EQ(j.at("engine"), "multi");
    EXPECT_EQ(j.at("settings").at("spp"), 10);
    EXPECT_EQ(j.at("settings").at("sampling"), "stratified");
    EXPECT_EQ(j.at("true_spp"), 9);
    EXPECT_EQ(j.at("paths"), 21600);
    EXPECT_DOUBLE_EQ(j.at("mpaths_per_second").get<double>(), 21600 / 0.5 * 1e-6);
    EXPECT_FALSE(j.contains("gpu_seconds")) << "not measured, so not reported";
    stats.gpuSeconds = 0.25;
    EXPECT_EQ(stats.toJson().at("gpu_seconds"), 0.25);
}

TEST(RenderStats, RaysByKindAndTheirRatesOnlyWhereCounted)
{
    RenderStats stats;
    stats.paths = 1000;
    stats.renderSeconds = 0.5;
    stats.rays = {1000, 2500, 3000};
    EXPECT_FALSE(stats.toJson().contains("rays")) << "the GPU engine without --count-rays counts none";
    EXPECT_FALSE(stats.toJson().contains("segments"));
    stats.raysCounted = true;
    const nlohmann::json j = stats.toJson();
    EXPECT_EQ(j.at("segments"), 6500);
    EXPECT_DOUBLE_EQ(j.at("segments_per_path").get<double>(), 6.5);
    const nlohmann::json& rays = j.at("rays");
    EXPECT_EQ(rays.at("camera"), 1000);
    EXPECT_EQ(rays.at("extension"), 2500);
    EXPECT_EQ(rays.at("shadow"), 3000);
    EXPECT_EQ(rays.at("total"), 6500);
    EXPECT_DOUBLE_EQ(rays.at("mrays_per_second").at("shadow").get<double>(), 3000 / 0.5 * 1e-6);
    EXPECT_DOUBLE_EQ(rays.at("mrays_per_second").at("total").get<double>(), 6500 / 0.5 * 1e-6);
    EXPECT_EQ(rayCountsFromJson(rays), stats.rays) << "an MPI rank's counts read back as they were sent";
}
} // namespace
} // namespace rt
