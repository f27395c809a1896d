// ray-tracing-gpu end to end, as a user runs it: flags, exit codes, one-line errors and the files it writes.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#ifndef _WIN32 // the app runs through a POSIX shell (Support/AppProcess.h)

#include "GpuTestEnvironment.h"
#include "Support/AppProcess.h"
#include "Support/ScratchDir.h"

namespace rt::gpu::test
{
namespace
{
using ::rt::test::AppRun;

AppRun runApp(const std::string& arguments, const std::string& environment = "")
{
    return ::rt::test::runApp(RT_GPU_APP, arguments, environment);
}


TEST(GpuApp, HelpExplainsEveryFlag)
{
    const AppRun r = runApp("--help");
    EXPECT_EQ(r.status, 0) << r.output;
    for (const char* flag : {"--headless", "--list-scenes", "--scene", "--spp", "--depth", "--width", "--aspect",
                             "--sampling", "--pdf", "--unidirectional-light", "--seed", "--output", "--hdr", "--stats",
                             "--count", "--mesh", "--quiet", "--device", "--validation", "--version"})
        EXPECT_NE(r.output.find(flag), std::string::npos) << flag;
}

TEST(GpuApp, VersionPrintsTheProjectsVersionAndExits)
{
    const AppRun r = runApp("--version");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find(RT_PROJECT_VERSION), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("rendering"), std::string::npos) << "it renders nothing";
}

TEST(GpuApp, ListsScenes)
{
    const AppRun r = runApp("--list-scenes");
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(r.output.find("rtrol-cornell-glass"), std::string::npos);
}

TEST(GpuApp, UnknownSceneIsSceneError)
{
    const AppRun r = runApp("--headless --scene no-such-scene");
    EXPECT_EQ(r.status, 3) << r.output;
    EXPECT_NE(r.output.find("unknown scene 'no-such-scene'"), std::string::npos) << r.output;
}

TEST(GpuApp, WithoutDisplayTheWindowSaysUseHeadless)
{
    // Without --headless the app opens its window (tests/Gui/Gpu); with no display, or in a build without the
    // window, it says so, naming --headless.
    const AppRun r = runApp("--scene rtnw-quads", "env -u DISPLAY -u WAYLAND_DISPLAY");
#ifdef RT_GPU_WINDOW
    EXPECT_EQ(r.status, 5) << r.output;
#else
    EXPECT_EQ(r.status, 2) << r.output;
#endif
    EXPECT_NE(r.output.find("--headless"), std::string::npos) << r.output;
}

#ifdef RT_GPU_WINDOW
TEST(GpuApp, BadActionIsUsageErrorBeforeAnyWindow)
{
    const AppRun r = runApp("--scene rtnw-quads --actions 'depth=0'", "env -u DISPLAY -u WAYLAND_DISPLAY");
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("depth=0"), std::string::npos) << r.output;
}
#endif

TEST(GpuApp, NoVulkanDriverIsOneLineDeviceError)
{
    // The loader finds no ICD: a clear line and exit code 5, not a crash.
    const AppRun r = runApp("--headless --scene rtnw-quads --width 8 --spp 1 --quiet",
                         "VK_ICD_FILENAMES=/nonexistent/icd.json VK_DRIVER_FILES=/nonexistent/icd.json");
    EXPECT_EQ(r.status, 5) << r.output;
    EXPECT_NE(r.output.find("error: "), std::string::npos) << r.output;
}

#ifdef RT_NO_VULKAN_DIR
TEST(GpuApp, NoVulkanLoaderIsOneLineDeviceError)
{
    // dlopen("libvulkan.so.1") finds a library without the loader's symbols first: as good as no Vulkan.
    // Prepended, so the app still finds its other libraries where they come from LD_LIBRARY_PATH.
    const char* inherited = std::getenv("LD_LIBRARY_PATH");
    const AppRun r = runApp("--headless --scene rtnw-quads --width 8 --spp 1 --quiet",
                            "LD_LIBRARY_PATH='" RT_NO_VULKAN_DIR + std::string(inherited ? ":" : "") +
                                (inherited ? inherited : "") + "'");
    EXPECT_EQ(r.status, 5) << r.output;
    EXPECT_NE(r.output.find("error: no Vulkan loader"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << "one line: " << r.output;
}
#endif

#ifdef RT_HIDE_RAY_TRACING_LAYER_DIR
TEST(GpuApp, NoRayTracingDeviceListsWhatEachLacks)
{
    RT_REQUIRE_GPU(); // a device exists; the layer takes its ray tracing away
    const ::rt::test::ScratchDir dir;
    const AppRun r = runApp("--headless --scene rtnw-quads --width 8 --spp 1 --quiet --output '" +
                                (dir / "out.png").string() + "'",
                            "VK_LAYER_PATH='" RT_HIDE_RAY_TRACING_LAYER_DIR "' VK_INSTANCE_LAYERS=VK_LAYER_RT_hide_ray_tracing");
    EXPECT_EQ(r.status, 5) << r.output;
    EXPECT_NE(r.output.find("error: "), std::string::npos) << r.output;
    // Every device is listed with what it lacks, by name.
    EXPECT_NE(r.output.find("device 0 '"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("): lacks extension "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("extension " VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("extension " VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}
#endif

TEST(GpuApp, AbsurdSizeNamesTheLimitAndWritesNothing)
{
    RT_REQUIRE_GPU();
    const ::rt::test::ScratchDir dir;
    // 40000 x 1000: 2.6 GB of host memory, which a test machine has, but wider than maxImageDimension2D of
    // lavapipe (16384) and of an H100 (32768): the device's limit, named.
    const AppRun wide = runApp("--headless --scene rtnw-quads --width 40000 --aspect 40 --spp 1 --quiet --output '" +
                               (dir / "wide.png").string() + "'");
    EXPECT_EQ(wide.status, 5) << wide.output;
    EXPECT_NE(wide.output.find("image 40000x1000"), std::string::npos) << wide.output;
    EXPECT_NE(wide.output.find("maxImageDimension2D"), std::string::npos) << wide.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "wide.png"));
    // 60000 x 60000: 230 GB, more than the host has (Render/MemoryBudget.h), refused before the device is
    // asked; either way the line gives the figures.
    const AppRun r = runApp("--headless --scene rtnw-quads --width 60000 --aspect 1 --spp 1 --quiet --output '" +
                         (dir / "huge.png").string() + "'");
    EXPECT_TRUE(r.status == 2 || r.status == 5) << r.output;
    EXPECT_NE(r.output.find("60000x60000"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(" GB"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "huge.png"));
}

TEST(GpuApp, HeadlessRenderWritesImageHdrAndStats)
{
    RT_REQUIRE_GPU();
    const ::rt::test::ScratchDir dir;
    const AppRun r = runApp("--headless --scene rtnw-cornell-box --width 24 --spp 2 --depth 6 --validation --quiet "
                         "--output '" + (dir / "out.png").string() + "' --hdr '" + (dir / "out.pfm").string() +
                         "' --stats '" + (dir / "stats.json").string() + "'");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_GT(std::filesystem::file_size(dir / "out.png"), 0u);
    EXPECT_GT(std::filesystem::file_size(dir / "out.pfm"), 24u * 24u * 12u);
    std::ifstream stats(dir / "stats.json");
    const std::string json((std::istreambuf_iterator<char>(stats)), std::istreambuf_iterator<char>());
    for (const char* key : {"\"gpu_seconds\"", "\"build_seconds\"", "\"wall_seconds\"", "\"mpaths_per_second\"",
                            "\"engine\": \"gpu\""})
        EXPECT_NE(json.find(key), std::string::npos) << key << " in " << json;
}

TEST(GpuApp, ShaderDirLoadsTheShadersFromThere)
{
    // A copy of the shaders renders the image of the app's own; a folder without them is a one-line asset
    // error naming the missing shader; a folder that does not exist is refused as a usage error.
    RT_REQUIRE_GPU();
    const ::rt::test::ScratchDir dir;
    const std::filesystem::path shaders = std::filesystem::path(RT_GPU_APP).parent_path() / "shaders";
    std::filesystem::copy(shaders, dir / "copy", std::filesystem::copy_options::recursive);
    const auto render = [&](const std::string& hdr, const std::string& shaderDir) {
        return runApp("--headless --scene rtnw-cornell-box --width 16 --spp 2 --depth 4 --quiet --hdr '" +
                      (dir / hdr).string() + "'" +
                      (shaderDir.empty() ? "" : " --shader-dir '" + (dir / shaderDir).string() + "'"));
    };
    const auto bytes = [](const std::filesystem::path& p) {
        std::ifstream in(p, std::ios::binary);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    ASSERT_EQ(render("own.pfm", "").status, 0);
    const AppRun copied = render("copy.pfm", "copy");
    ASSERT_EQ(copied.status, 0) << copied.output;
    ASSERT_GT(std::filesystem::file_size(dir / "own.pfm"), 16u * 16u * 12u);
    EXPECT_EQ(bytes(dir / "own.pfm"), bytes(dir / "copy.pfm"));
    std::filesystem::create_directory(dir / "empty");
    const AppRun empty = render("none.pfm", "empty");
    EXPECT_EQ(empty.status, 4) << empty.output;
    EXPECT_NE(empty.output.find("RayGen.rgen.spv' not found"), std::string::npos) << empty.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "none.pfm"));
    const AppRun missing = render("x.pfm", "nope");
    EXPECT_EQ(missing.status, 2) << missing.output;
    EXPECT_NE(missing.output.find("--shader-dir"), std::string::npos) << missing.output;
}

TEST(GpuApp, BadDeviceIndexIsUsageError)
{
    RT_REQUIRE_GPU();
    const AppRun r = runApp("--headless --scene rtnw-quads --device 99 --quiet");
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("--device 99 does not exist"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("--list-devices describes them)\n"), std::string::npos) << "one line: " << r.output;
}
} // namespace
} // namespace rt::gpu::test
#endif
