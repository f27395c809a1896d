// The one --actions grammar of both windows (Cli/ActionGrammar.h): names, bare actions, typed values and
// their bounds, and the actions both windows share.
#include <gtest/gtest.h>

#include "Cli/ActionGrammar.h"
#include "Error.h"

namespace rt
{
namespace
{
std::vector<ActionSpec> specsWithRender()
{
    return joinActionSpecs(sharedActionSpecs("samples per pixel", 1),
                           {{"render", ActionValue::None, "", "start a render"},
                            {"zoom", ActionValue::Real, "Z", "a window's own real action", 0.5, 4.0}});
}

TEST(ActionGrammar, SplitsAtSemicolonsTrimsAndSkipsBlanks)
{
    const auto actions = parseActionScript(" scene=rtnw-quads ; ;render;resize=640x400;frames=3;", specsWithRender());
    ASSERT_EQ(actions.size(), 4u);
    EXPECT_EQ(actions[0].name, "scene");
    EXPECT_EQ(actions[0].value, "rtnw-quads");
    EXPECT_EQ(actions[1].name, "render");
    EXPECT_EQ(actions[1].value, "");
    EXPECT_EQ(actions[2].size(), (std::pair{640, 400}));
    EXPECT_EQ(actions[3].integer(), 3);
}

TEST(ActionGrammar, TypedValuesReadBack)
{
    const auto a = parseActionScript("pdf=off;unidirectional-light=on;zoom=1.5;font-size=20", specsWithRender());
    EXPECT_FALSE(a[0].on());
    EXPECT_TRUE(a[1].on());
    EXPECT_FLOAT_EQ(a[2].real(), 1.5f);
    EXPECT_EQ(a[3].integer(), 20);
}

TEST(ActionGrammar, BadNamesAndValuesAreUsageErrorsQuotingTheAction)
{
    for (const char* bad : {"bogus", "render=now", "spp=0", "spp=x", "depth=0", "pdf=yes", "resize=10",
                            "resize=-1x5", "resize=20000x10", "scene=", "scene=no-such-scene", "save=x.jpg",
                            "save=.png", "theme=pink", "font-size=4", "font-size=33", "font-size=1.5", "spp=3000000000", "zoom=5", "zoom=nan", "aspect=0", "width=0",
                            "frames"})
    {
        try
        {
            parseActionScript(bad, specsWithRender());
            ADD_FAILURE() << bad << " was accepted";
        }
        catch (const UsageError& e)
        {
            EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
        }
    }
}

TEST(ActionGrammar, SharedActionsAreTheSameForBothWindows)
{
    // Both windows build their tables from sharedActionSpecs: the names and value kinds cannot drift apart.
    const auto cpu = sharedActionSpecs("samples per pixel of the render", 1);
    const auto gpu = sharedActionSpecs("stop tracing at N samples per pixel (0: never)", 0);
    ASSERT_EQ(cpu.size(), gpu.size());
    for (std::size_t i = 0; i < cpu.size(); ++i)
    {
        EXPECT_EQ(cpu[i].name, gpu[i].name);
        EXPECT_EQ(cpu[i].value, gpu[i].value);
    }
    EXPECT_NO_THROW(parseActionScript("spp=0", joinActionSpecs(gpu, {})));
    EXPECT_THROW(parseActionScript("spp=0", joinActionSpecs(cpu, {})), UsageError);
}

TEST(ActionGrammar, IntegersEndAtTheirOwnMaximumOrIntMax)
{
    const std::vector<ActionSpec> specs = {{"seed", ActionValue::Integer, "N", "seed", 0, 4294967295.0},
                                           {"count", ActionValue::Integer, "N", "count", 0}};
    EXPECT_EQ(parseActionScript("seed=4294967295", specs).front().integer(), 4294967295ll);
    EXPECT_THROW(parseActionScript("seed=4294967296", specs), UsageError);
    EXPECT_EQ(parseActionScript("count=2147483647", specs).front().integer(), 2147483647ll);
    EXPECT_THROW(parseActionScript("count=2147483648", specs), UsageError);
}

TEST(ActionGrammar, HelpListsEveryAction)
{
    const std::string help = actionScriptHelp(specsWithRender());
    for (const ActionSpec& s : specsWithRender())
        EXPECT_NE(help.find(s.name), std::string::npos) << s.name;
    EXPECT_NE(help.find("resize=WxH"), std::string::npos);
}
} // namespace
} // namespace rt
