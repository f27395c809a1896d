// Noticing a scene file's new versions (SceneFile/SceneFileWatch.h), the names the windows and file names use
// for scenes, and the Fresnel choice's names shared by --fresnel, the actions and --stats.
#include <chrono>
#include <filesystem>

#include <gtest/gtest.h>

#include "Cli/ActionGrammar.h"
#include "Error.h"
#include "SceneFile/SceneFile.h"
#include "SceneFile/SceneFileWatch.h"
#include "Scenes/Catalogue.h"
#include "Support/ScratchDir.h"

namespace rt
{
namespace
{
using namespace std::chrono_literals;
using Clock = SceneFileWatch::Clock;

TEST(SceneFileVersion, CatalogueIdsHaveNoneAndMissingFilesAreMinusOne)
{
    const test::ScratchDir dir;
    EXPECT_EQ(sceneFileVersion("cornell-box-lights"), 0);
    EXPECT_EQ(sceneFileVersion((dir / "absent.json").string()), -1);
    const std::string file = dir.write("a.json", "{}").string();
    EXPECT_GT(sceneFileVersion(file), 0);
    EXPECT_EQ(sceneFileVersion(file), sceneFileVersion(file)) << "a file that did not change";
}

TEST(SceneFileVersion, ChangesWithTheModificationTimeAndWithTheSize)
{
    const test::ScratchDir dir;
    const std::filesystem::path file = dir.write("a.json", "{}");
    const auto time = std::filesystem::last_write_time(file);
    const std::int64_t v0 = sceneFileVersion(file.string());
    std::filesystem::last_write_time(file, time + 1s);
    const std::int64_t v1 = sceneFileVersion(file.string());
    EXPECT_NE(v1, v0) << "same size, later time";
    dir.write("a.json", "{ }");
    std::filesystem::last_write_time(file, time + 1s);
    EXPECT_NE(sceneFileVersion(file.string()), v1) << "same time (a clock of coarse stamps), another size";
}

TEST(SceneFileWatch, ReportsEachNewVersionOnceAndNoMoreOftenThanItsInterval)
{
    const test::ScratchDir dir;
    const std::filesystem::path file = dir.write("a.json", "{}");
    SceneFileWatch watch(500ms);
    watch.watch(file.string(), sceneFileVersion(file.string()));
    const Clock::time_point t0 = Clock::now();
    EXPECT_FALSE(watch.poll(t0)) << "nothing changed";

    dir.write("a.json", "{\"changed\": 1}");
    EXPECT_FALSE(watch.poll(t0 + 100ms)) << "within the interval since the last poll";
    const std::optional<std::int64_t> v = watch.poll(t0 + 600ms);
    ASSERT_TRUE(v);
    EXPECT_EQ(*v, sceneFileVersion(file.string()));
    EXPECT_FALSE(watch.poll(t0 + 1200ms)) << "a version is reported once, also when it failed to load";

    std::filesystem::remove(file);
    const std::optional<std::int64_t> gone = watch.poll(t0 + 1800ms);
    ASSERT_TRUE(gone) << "a deleted file is a change: the window says it cannot read it";
    EXPECT_EQ(*gone, -1);
    EXPECT_FALSE(watch.poll(t0 + 2400ms));
}

TEST(SceneFileWatch, CatalogueScenesAreNotWatched)
{
    SceneFileWatch watch(0ms);
    watch.watch("cornell-box-lights", 0);
    EXPECT_TRUE(watch.path().empty());
    EXPECT_FALSE(watch.poll(Clock::now()));
}

TEST(SceneShortName, IsTheIdOrTheFilesStem)
{
    EXPECT_EQ(sceneShortName("cornell-box-lights"), "cornell-box-lights");
    EXPECT_EQ(sceneShortName("scenes/lamp.json"), "lamp");
    EXPECT_EQ(sceneShortName("/models/Box.Textured.glb"), "Box.Textured");
}

TEST(FresnelOption, NamesReadBackAndOthersAreRefused)
{
    for (const std::optional<shader::FresnelModel> model :
         {std::optional<shader::FresnelModel>{}, std::optional(shader::FresnelModel::Schlick),
          std::optional(shader::FresnelModel::Exact)})
    {
        std::optional<shader::FresnelModel> read = shader::FresnelModel::Exact;
        if (!model)
            read = shader::FresnelModel::Schlick; // "scene" must clear it
        ASSERT_TRUE(parseFresnelOption(fresnelOptionName(model), read));
        EXPECT_EQ(read, model) << fresnelOptionName(model);
    }
    std::optional<shader::FresnelModel> untouched = shader::FresnelModel::Exact;
    EXPECT_FALSE(parseFresnelOption("fast", untouched));
    EXPECT_FALSE(parseFresnelOption("Exact", untouched));
    EXPECT_EQ(untouched, shader::FresnelModel::Exact);
}

TEST(SharedActions, SceneTakesExistingSceneFilesAndFresnelItsThreeNames)
{
    const test::ScratchDir dir;
    const std::string file = dir.write("lamp.json", "{}").string();
    const std::vector<ActionSpec> specs = sharedActionSpecs("spp", 1);
    EXPECT_EQ(parseActionScript("scene=" + file + ";fresnel=exact;fresnel=scene;sleep=0.5", specs).size(), 4u);
    EXPECT_THROW(parseActionScript("scene=" + (dir / "absent.json").string(), specs), UsageError);
    EXPECT_THROW(parseActionScript("scene=" + dir.write("notes.txt", "").string(), specs), UsageError);
    EXPECT_THROW(parseActionScript("fresnel=fast", specs), UsageError);
    EXPECT_EQ(parseActionScript("roughness-scale=0.01;roughness-scale=100;roughness-scale=2.5", specs).size(), 3u);
    EXPECT_THROW(parseActionScript("roughness-scale=0.005", specs), UsageError);
    EXPECT_THROW(parseActionScript("roughness-scale=101", specs), UsageError);
    EXPECT_THROW(parseActionScript("roughness-scale=rough", specs), UsageError);
    EXPECT_THROW(parseActionScript("sleep=-1", specs), UsageError);
    EXPECT_THROW(parseActionScript("sleep=601", specs), UsageError);
}
} // namespace
} // namespace rt
