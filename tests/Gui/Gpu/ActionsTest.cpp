// The window's scripted actions and the settings they change, without a window: every action goes through
// Controls, the functions the panel's widgets call, and every image setting restarts accumulation.
#include <gtest/gtest.h>

#include "App/Gui/Actions.h"
#include "Scene/CameraMoves.h"
#include "Cli/ActionGrammar.h"
#include "Error.h"
#include "Scenes/Catalogue.h"

namespace rt::gpu::gui
{
namespace
{
WindowState cornellState()
{
    WindowState state;
    state.costAvailable = true;
    state.fonts = {"ImGui default", "Mono"};
    state.sceneCamera = makeScene("cornell-box-lights").camera;
    state.image.camera = state.sceneCamera;
    return state;
}

void apply(WindowState& state, const std::string& script)
{
    Controls controls(state);
    for (const Action& action : parseActions(script))
        applyAction(action, controls);
}

TEST(WindowActions, ParseSplitsAtSemicolonsAndSkipsBlanks)
{
    const std::vector<Action> actions = parseActions("scene=rtnw-quads; ;depth=7;resize=0x0;camera=forward:10;");
    ASSERT_EQ(actions.size(), 4u);
    EXPECT_EQ(actions[0].name, "scene");
    EXPECT_EQ(actions[0].value, "rtnw-quads");
    EXPECT_EQ(actions[3].value, "forward:10");
}

TEST(WindowActions, BadNamesAndValuesAreUsageErrorsNamingThem)
{
    for (const char* bad : {"depth=0", "depth=x", "bogus=1", "heatmap=yes", "resize=10", "resize=-1x5",
                            "camera=sideways:1", "camera=forward", "fov=abc", "fov=0", "fov=170", "theme=pink", "nothing", "scene=", "scene=no-such-scene",
                            "samples=1000", "font-size=1.5", "save=x.jpg"})
    {
        try
        {
            parseActions(bad);
            ADD_FAILURE() << bad << " was accepted";
        }
        catch (const UsageError& e)
        {
            const std::string name = std::string(bad).substr(0, std::string(bad).find('='));
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        }
    }
}

TEST(WindowActions, ValuesOutOfRangeAreRefusedNamingTheLimit)
{
    // Issue 13 item 7: samples=1000 was capped to 256 and a font size out of range taken without a word.
    const auto error = [](const std::string& script) {
        try
        {
            parseActions(script);
        }
        catch (const UsageError& e)
        {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(error("samples=1000").find("[0, 256]"), std::string::npos) << error("samples=1000");
    EXPECT_NE(error("samples=257").find("[0, 256]"), std::string::npos);
    EXPECT_NE(error("font-size=9").find("[10, 32]"), std::string::npos) << error("font-size=9");
    EXPECT_NE(error("font-size=33").find("[10, 32]"), std::string::npos);
    for (const char* name : {"save=x.jpg", "save=x.PNG", "save=x", "save=.png", "save=x.pfm"})
        EXPECT_NE(error(name).find("FILE.png"), std::string::npos) << name << ": " << error(name);
    EXPECT_EQ(error("samples=256;font-size=10;font-size=32;save=x.png"), "accepted");
}

TEST(WindowControls, ValuesHeldToTheirLimitsSaySoNamingTheLimit)
{
    // The panel's sliders take any number typed into them (Ctrl+click): Controls holds it and says so.
    WindowState state = cornellState();
    Controls controls(state);
    controls.setSamplesPerFrame(1000);
    EXPECT_EQ(state.display.samplesPerFrame, kMaxSamplesPerFrame);
    EXPECT_NE(state.message.find("samples per frame 1000"), std::string::npos) << state.message;
    EXPECT_NE(state.message.find("largest allowed, 256"), std::string::npos) << state.message;
    state.message.clear();
    controls.setSamplesPerFrame(64);
    EXPECT_EQ(state.display.samplesPerFrame, 64);
    EXPECT_TRUE(state.message.empty()) << "a value in range says nothing";
    controls.setFontPixels(4);
    EXPECT_EQ(controls.fontPixels(), kMinFontPixels);
    EXPECT_NE(state.message.find("smallest allowed, 10 px"), std::string::npos) << state.message;
    controls.setFontPixels(100);
    EXPECT_EQ(controls.fontPixels(), kMaxFontPixels);
    EXPECT_NE(state.message.find("largest allowed, 32 px"), std::string::npos) << state.message;
    controls.setDepth(0);
    EXPECT_EQ(state.image.request.settings.depth, 1);
    EXPECT_NE(state.message.find("depth 0"), std::string::npos) << state.message;
}

TEST(WindowControls, SaveRefusesNamesItWouldNotWriteAsNamed)
{
    // Issue 13 item 7: the panel's file box took x.jpg and wrote PNG bytes under that name.
    WindowState state = cornellState();
    Controls controls(state);
    EXPECT_FALSE(controls.save("x.jpg"));
    EXPECT_FALSE(state.saveRequest);
    EXPECT_NE(state.message.find("'x.jpg' is not saved"), std::string::npos) << state.message;
    EXPECT_NE(state.message.find("must end in .png (not .jpg)"), std::string::npos) << state.message;
    EXPECT_FALSE(controls.save("noextension"));
    EXPECT_TRUE(controls.save("dir/x.png"));
    EXPECT_EQ(state.saveRequest, std::filesystem::path("dir/x.png"));
}

TEST(WindowActions, EachActionChangesItsSetting)
{
    WindowState state = cornellState();
    apply(state, "depth=7;samples=4;spp=64;pdf=off;russian-roulette=off;unidirectional-light=off;accumulate=off;raytracing=off;"
                 "heatmap=on;heatmap-scale=5000;theme=light;font=Mono;font-size=30;fov=55;focus=20;aperture=2");
    EXPECT_EQ(state.image.request.settings.depth, 7);
    EXPECT_EQ(state.display.samplesPerFrame, 4);
    EXPECT_TRUE(state.display.stopAtSpp);
    EXPECT_EQ(state.image.request.settings.spp, 64) << "one spp: the render's is where the window stops";
    EXPECT_EQ(state.image.request.settings.estimator, Estimator::BsdfOnly);
    EXPECT_EQ(state.image.request.settings.russianRoulette, RussianRoulette::Off);
    EXPECT_FALSE(state.image.request.settings.unidirectionalLight);
    apply(state, "estimator=nee;light-sampler=area;light-selection=uniform;sobol=on");
    EXPECT_EQ(state.image.request.settings.sampling, PixelSampling::Sobol);
    EXPECT_EQ(state.image.request.settings.estimator, Estimator::Nee);
    EXPECT_EQ(state.image.request.settings.lightSampler, LightSampler::Area);
    EXPECT_EQ(state.image.request.settings.lightSelection, LightSelection::Uniform);
    EXPECT_FALSE(state.image.accumulate);
    EXPECT_FALSE(state.image.rayTracing);
    EXPECT_TRUE(state.image.heatmap);
    EXPECT_FALSE(state.display.autoCostScale);
    EXPECT_FLOAT_EQ(state.display.costScale, 5000.0f);
    EXPECT_FALSE(state.display.darkStyle);
    EXPECT_EQ(state.display.font, 1);
    EXPECT_FLOAT_EQ(state.display.fontScale, 30.0f / kPanelFontPixels);
    EXPECT_FLOAT_EQ(state.image.camera.vfovDegrees, 55.0f);
    EXPECT_FLOAT_EQ(state.image.camera.focusDistance, 20.0f);
    EXPECT_NEAR(apertureOf(state.image.camera), 2.0f, 1e-4f);
}

TEST(WindowActions, RequestsAreLeftForTheFrameLoop)
{
    WindowState state = cornellState();
    EXPECT_FALSE(state.pilotRequest);
    apply(state, "scene=rtnw-quads;resize=0x0;save=out.png;choose-strategy");
    EXPECT_EQ(state.sceneRequest, "rtnw-quads");
    EXPECT_TRUE(state.pilotRequest) << "the frame loop runs the strategy pilot";
    EXPECT_EQ(state.resizeRequest, (Extent{0, 0}));
    EXPECT_EQ(state.saveRequest, std::filesystem::path("out.png"));
    EXPECT_THROW(apply(state, "font=Comic Sans"), UsageError);
}

TEST(WindowActions, CameraMovesInViewAxesAndResets)
{
    WindowState state = cornellState();
    const CameraDesc start = state.image.camera;
    apply(state, "camera=forward:10");
    const vec3 forward = glm::normalize(start.lookAt - start.lookFrom);
    EXPECT_NEAR(glm::length(state.image.camera.lookFrom - (start.lookFrom + 10.0f * forward)), 0.0f, 1e-3f);
    apply(state, "camera=yaw:30;camera=pitch:-10;camera=up:5");
    EXPECT_NE(state.image.camera, start);
    apply(state, "camera=reset");
    EXPECT_EQ(state.image.camera, start);
}

TEST(WindowActions, HeatmapStaysOffWithoutTheShaderClock)
{
    WindowState state = cornellState();
    state.costAvailable = false;
    apply(state, "heatmap=on");
    EXPECT_FALSE(state.image.heatmap);
}

TEST(WindowActions, FramesIsTheFrameLoops)
{
    WindowState state = cornellState();
    Controls controls(state);
    const Action wait = parseActions("frames=3").front();
    EXPECT_FALSE(applyAction(wait, controls));
    EXPECT_EQ(waitFrames(wait), 3);
}

TEST(WindowSettings, EveryImageSettingRestartsAccumulationDisplaySettingsDoNot)
{
    const WindowState base = cornellState();
    const auto changed = [&](const std::string& script) {
        WindowState state = base;
        apply(state, script);
        return !(state.image == base.image);
    };
    for (const char* imageChange : {"depth=7", "pdf=off", "estimator=nee", "russian-roulette=off", "light-sampler=area", "light-selection=uniform",
                                    "sobol=on", "unidirectional-light=off", "accumulate=off",
                                    "raytracing=off", "heatmap=on", "fov=30", "aperture=1", "focus=3",
                                    "camera=forward:1", "camera=yaw:1"})
        EXPECT_TRUE(changed(imageChange)) << imageChange;
    for (const char* displayChange : {"samples=8", "heatmap-scale=100", "theme=light", "font=Mono", "font-size=20"})
        EXPECT_FALSE(changed(displayChange)) << displayChange;
    // The spp is the image's (it decides the integrator), but where tracing stops is all it changes: the window
    // keeps the samples while the integrator stays (WindowApp's accumulationFits).
    WindowState stopped = base;
    apply(stopped, "spp=100");
    EXPECT_TRUE(stopped.display.stopAtSpp);
    stopped.image.request.settings.spp = base.image.request.settings.spp;
    EXPECT_EQ(stopped.image, base.image);
    apply(stopped, "spp=0");
    EXPECT_FALSE(stopped.display.stopAtSpp) << "0: never stop";
    EXPECT_EQ(stopped.image.request.settings.spp, base.image.request.settings.spp) << "the spp is kept";
}
} // namespace
} // namespace rt::gpu::gui
