// The settings table (Render/SettingsTable.h) is what every interface reads: each entry must read back what it
// writes, be told apart from the others, and reach the shaders when the shaders read it.
#include <cstring>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "Cli/ActionGrammar.h"
#include "Error.h"
#include "Render/RenderUniforms.h"
#include "Render/SettingsTable.h"
#include "Scenes/Catalogue.h"

namespace rt
{
namespace
{
/// A value of `s` other than the default's: the last word of a choice, the other switch, a number in range.
std::string otherValue(const Setting& s)
{
    const RenderSettings defaults;
    switch (s.type)
    {
    case SettingType::Choice:
        for (auto it = s.choices.rbegin(); it != s.choices.rend(); ++it)
            if (std::string(*it) != s.text(defaults))
                return std::string(*it);
        break;
    case SettingType::OnOff: return s.text(defaults) == "on" ? "off" : "on";
    case SettingType::Integer: return s.text(defaults) == "7" ? "8" : "7";
    case SettingType::Real: return "1.5";
    }
    return {};
}

TEST(SettingsTable, NamesAndJsonKeysAreUniqueAndEveryFieldIsInTheJson)
{
    std::set<std::string> names;
    std::set<std::string> keys;
    for (const Setting& s : settingsTable())
    {
        EXPECT_TRUE(names.insert(std::string(s.name)).second) << s.name;
        EXPECT_TRUE(keys.insert(std::string(s.jsonKey)).second) << s.jsonKey;
        EXPECT_FALSE(s.help.empty()) << s.name;
        EXPECT_FALSE(s.tooltip.empty()) << s.name;
    }
    EXPECT_EQ(toJson(RenderSettings{}).size(), keys.size());
}

TEST(SettingsTable, EverySettingReadsBackWhatItWritesAndOnlyItsOwnField)
{
    for (const Setting& s : settingsTable())
    {
        const std::string value = otherValue(s);
        RenderSettings changed;
        ASSERT_TRUE(s.assign(s, changed, value)) << s.name << " refused " << value;
        EXPECT_EQ(s.text(changed), value) << s.name;
        EXPECT_NE(changed, RenderSettings{}) << s.name << "=" << value << " changed nothing";
        // Copying the field alone onto the defaults gives the same settings: the entry names one field.
        RenderSettings copied;
        s.copy(copied, changed);
        EXPECT_EQ(copied, changed) << s.name;
        EXPECT_EQ(toJson(changed)[std::string(s.jsonKey)], s.json(changed)) << s.name;
    }
}

TEST(SettingsTable, ValuesOutsideTheRangeOrWordsAreRefusedNamingWhatIsExpected)
{
    const Setting& spp = setting("spp");
    RenderSettings s;
    EXPECT_FALSE(spp.assign(spp, s, "0"));
    EXPECT_FALSE(spp.assign(spp, s, "16777217"));
    EXPECT_FALSE(spp.assign(spp, s, "12x"));
    EXPECT_EQ(s.spp, RenderSettings{}.spp) << "a refused value leaves the field alone";
    EXPECT_THROW(spp.set(s, "0", "--spp"), UsageError);
    const Setting& sampler = setting("light-sampler");
    EXPECT_FALSE(sampler.assign(sampler, s, "cosine"));
    EXPECT_EQ(sampler.refusal("cosine"),
              "light sampler must be area, solid-angle, projected or projected-exact (got 'cosine')");
    const Setting& aspect = setting("aspect");
    EXPECT_FALSE(aspect.assign(aspect, s, "0"));
    EXPECT_FALSE(aspect.assign(aspect, s, "1e308")); // finite as a double, not as a float
    EXPECT_TRUE(aspect.assign(aspect, s, "1.7778"));
    EXPECT_FLOAT_EQ(s.aspect, 1.7778f);
    const Setting& sampling = setting("sampling");
    EXPECT_TRUE(sampling.assign(sampling, s, "accumulation")) << "the thesis' name is an alias";
    EXPECT_EQ(s.sampling, PixelSampling::Accumulate);
    EXPECT_EQ(sampling.text(s), "accumulate") << "and never printed";
}

TEST(SettingsTable, EverySettingTheShadersReadReachesTheUniforms)
{
    const Scene scene = makeScene("cornell-box-lights");
    const auto bytes = [&](const RenderSettings& s) { return makeUniforms(scene, scene.camera, s, 16, 16); };
    const shader::RenderUniforms base = bytes(RenderSettings{});
    int written = 0;
    for (const Setting& s : settingsTable())
    {
        RenderSettings changed;
        ASSERT_TRUE(s.assign(s, changed, otherValue(s)));
        const shader::RenderUniforms u = bytes(changed);
        const bool differs = std::memcmp(&u, &base, sizeof(u)) != 0;
        if (s.toUniforms != nullptr)
        {
            EXPECT_TRUE(differs) << s.name << " has a uniform but changing it changed none";
            ++written;
        }
    }
    EXPECT_GE(written, 8); // depth, estimator, light sampler and selection, sampling, roulette, sidedness, seed
}

TEST(SettingsTable, EveryWindowActionOfASettingParsesAsTheCommandLine)
{
    for (const Setting& s : settingsTable())
    {
        const std::vector<ActionSpec> specs{settingActionSpec(s)};
        EXPECT_NO_THROW(parseActionScript(std::string(s.name) + "=" + otherValue(s), specs)) << s.name;
        if (s.type == SettingType::Choice || s.type == SettingType::OnOff)
        {
            EXPECT_THROW(parseActionScript(std::string(s.name) + "=nonsense", specs), UsageError) << s.name;
        }
    }
}
} // namespace
} // namespace rt
