#include "Cli/ActionGrammar.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include <spdlog/fmt/fmt.h>

#include "Cli/ValueParsing.h"
#include "Cli/WindowSize.h"
#include "Error.h"
#include "Render/SettingsTable.h"
#include "Scene/CameraMoves.h"
#include "SceneFile/SceneFile.h"
#include "Scenes/Catalogue.h"

namespace rt
{
namespace
{
constexpr long long kMaxSize = kMaxWindowSide; // resize: 0x0 (minimised) up to --window-size's largest

std::string trimmed(std::string_view text)
{
    const auto first = text.find_first_not_of(" \t\n");
    if (first == std::string_view::npos)
        return {};
    const auto last = text.find_last_not_of(" \t\n");
    return std::string(text.substr(first, last - first + 1));
}

/// Integers without a maximum of their own end where the windows' int settings do.
double integerMaximum(const ActionSpec& spec)
{
    return spec.maximum >= 1e30 ? double(std::numeric_limits<int>::max()) : spec.maximum;
}

/// What the value must be, for the error message.
std::string expected(const ActionSpec& spec)
{
    switch (spec.value)
    {
    case ActionValue::None: return "no value";
    case ActionValue::Integer: return fmt::format("an integer in [{}, {}]", spec.minimum, integerMaximum(spec));
    case ActionValue::Real:
        return spec.maximum < 1e30 ? fmt::format("a number in [{}, {}]", spec.minimum, spec.maximum)
                                   : fmt::format("a number >= {}", spec.minimum);
    case ActionValue::OnOff: return "on or off";
    case ActionValue::Size: return fmt::format("WIDTHxHEIGHT, each in [0, {}]", kMaxSize);
    case ActionValue::Text: return spec.placeholder;
    }
    return "?";
}

bool valueFits(const ActionSpec& spec, const std::string& value, bool hasValue)
{
    bool ok = false;
    switch (spec.value)
    {
    case ActionValue::None: return !hasValue;
    case ActionValue::Integer:
    {
        const auto v = parseInteger(value);
        ok = v && double(*v) >= spec.minimum && double(*v) <= integerMaximum(spec);
        break;
    }
    case ActionValue::Real:
    {
        const auto v = parseReal(value);
        ok = v && std::isfinite(*v) && *v >= spec.minimum && *v <= spec.maximum;
        break;
    }
    case ActionValue::OnOff: ok = parseOnOff(value).has_value(); break;
    case ActionValue::Size:
    {
        const auto s = parseSize(value);
        ok = s && s->first >= 0 && s->second >= 0 && s->first <= kMaxSize && s->second <= kMaxSize;
        break;
    }
    case ActionValue::Text: ok = hasValue; break;
    }
    return ok && (!spec.accepts || spec.accepts(value));
}
} // namespace

long long ScriptedAction::integer() const { return parseInteger(value).value_or(0); }

float ScriptedAction::real() const { return parseReal(value).value_or(0.0f); }

bool ScriptedAction::on() const { return parseOnOff(value).value_or(false); }

std::pair<int, int> ScriptedAction::size() const
{
    const auto s = parseSize(value).value_or(std::pair{0ll, 0ll});
    return {int(s.first), int(s.second)};
}

std::vector<ScriptedAction> parseActionScript(std::string_view script, const std::vector<ActionSpec>& specs)
{
    std::vector<ScriptedAction> actions;
    std::size_t start = 0;
    while (start <= script.size())
    {
        const std::size_t end = std::min(script.find(';', start), script.size());
        const std::string item = trimmed(script.substr(start, end - start));
        start = end + 1;
        if (item.empty())
            continue;
        const std::size_t eq = item.find('=');
        ScriptedAction a{item.substr(0, eq), eq == std::string::npos ? "" : item.substr(eq + 1), item};
        const auto spec = std::find_if(specs.begin(), specs.end(), [&](const ActionSpec& s) { return s.name == a.name; });
        if (spec == specs.end())
            throw UsageError(fmt::format("--actions: unknown action '{}' (see --help)", a.text));
        if (!valueFits(*spec, a.value, eq != std::string::npos))
            throw UsageError(fmt::format("--actions: '{}': expected {} (see --help)", a.text,
                                         spec->value == ActionValue::None ? "no value"
                                                                          : a.name + "=" + expected(*spec)));
        actions.push_back(std::move(a));
    }
    return actions;
}

std::string actionScriptHelp(const std::vector<ActionSpec>& specs)
{
    std::string help;
    for (const ActionSpec& s : specs)
        help += fmt::format("  {:<30} {}\n", s.placeholder.empty() ? s.name : s.name + "=" + s.placeholder, s.meaning);
    return help;
}

ActionSpec settingActionSpec(const Setting& setting)
{
    ActionSpec spec{.name = std::string(setting.name),
                    .placeholder = setting.placeholder(),
                    .meaning = std::string(setting.tooltip)};
    switch (setting.type)
    {
    case SettingType::Integer: spec.value = ActionValue::Integer; break;
    case SettingType::Real: spec.value = ActionValue::Real; break;
    case SettingType::OnOff: spec.value = ActionValue::OnOff; break;
    case SettingType::Choice: spec.value = ActionValue::Text; break;
    }
    // The table's parse is the last check (a Real's minimum is exclusive there).
    spec.minimum = setting.minimum;
    spec.maximum = setting.number ? setting.maximum : 1e30;
    spec.accepts = [&setting](const std::string& value) { return setting.accepts(value); };
    return spec;
}

std::vector<ActionSpec> sharedActionSpecs(const std::string& sppMeaning, long long sppMinimum)
{
    ActionSpec sppSpec = settingActionSpec(setting("spp"));
    sppSpec.meaning = sppMeaning;
    // The GPU window's spp is where accumulation stops, 0 for never: its own minimum.
    sppSpec.minimum = double(sppMinimum);
    sppSpec.accepts = {};
    return {
        {"scene", ActionValue::Text, "ID|FILE",
         "switch to a catalogue scene (--list-scenes) or a scene file (.json, .gltf, .glb; reloaded when it changes)",
         0, 1e30,
         [](const std::string& id) { return sceneProblem(id).empty(); }},
        {"fresnel", ActionValue::Text, "scene|schlick|exact", "every dielectric's reflectance (--fresnel)", 0, 1e30,
         [](const std::string& v) {
             std::optional<shader::FresnelModel> model;
             return parseFresnelOption(v, model);
         }},
        {"roughness-scale", ActionValue::Real, "X",
         "every microfacet material's GGX alpha times X, alpha at most 1 (--roughness-scale)", kMinRoughnessScale,
         kMaxRoughnessScale},
        sppSpec,
        settingActionSpec(setting("width")),
        settingActionSpec(setting("aspect")),
        settingActionSpec(setting("seed")),
        settingActionSpec(setting("depth")),
        settingActionSpec(setting("sampling")),
        settingActionSpec(setting("estimator")),
        settingActionSpec(setting("light-sampler")),
        settingActionSpec(setting("light-selection")),
        {"pdf", ActionValue::OnOff, "on|off", "the books' name: estimator=mixture, or estimator=bsdf"},
        settingActionSpec(setting("russian-roulette")),
        settingActionSpec(setting("unidirectional-light")),
        {"fov", ActionValue::Real, "DEGREES",
         fmt::format("the camera's vertical field of view, {:g} to {:g} (the panel's range)", kMinFov, kMaxFov),
         kMinFov, kMaxFov},
        {"camera", ActionValue::Text, "MOVE:AMOUNT|reset",
         "move forward/back/left/right/up/down by AMOUNT world units, or turn yaw/pitch by AMOUNT degrees; reset: the "
         "scene's camera",
         0, 1e30, [](const std::string& v) { return parseCameraAction(v).has_value(); }},
        {"resize", ActionValue::Size, "WxH", "resize the window (0x0: as a minimised window reports)"},
        {"save", ActionValue::Text, "FILE.png", "save the image shown: FILE.png and the linear FILE.pfm", 0, 1e30,
         [](const std::string& path) { return saveImagePathProblem(path).empty(); }},
        {"save-plot", ActionValue::Text, "FILE.png",
         "save the convergence plot of the panel's work: FILE.png (plot_convergence.py) and its points FILE.csv", 0,
         1e30, [](const std::string& path) { return saveImagePathProblem(path).empty(); }},
        {"wait-reference", ActionValue::None, "",
         "until no render runs and the timings' references of the current scene are done (relMSE measured)"},
        {"frames", ActionValue::Integer, "N", "let N frames pass", 0},
        {"sleep", ActionValue::Real, "SECONDS", "let SECONDS of wall-clock time pass, drawing frames", 0, 600},
        {"theme", ActionValue::Text, "dark|light", "colour theme of the panel", 0, 1e30,
         [](const std::string& v) { return v == "dark" || v == "light"; }},
        {"font-size", ActionValue::Integer, "PIXELS", "height of the panel's font", kMinFontPixels, kMaxFontPixels},
    };
}

std::string saveImagePathProblem(const std::string& path)
{
    const std::filesystem::path p(path);
    if (p.extension() == ".png" && !p.stem().empty())
        return {};
    return fmt::format("'{}' is not saved: the window writes PNG (sRGB) with the linear PFM beside it, so the "
                       "name must end in .png{}",
                       path, p.extension().empty() || p.extension() == ".png" ? "" : " (not " + p.extension().string() + ")");
}

std::optional<CameraAction> parseCameraAction(const std::string& value)
{
    if (value == "reset")
        return CameraAction{.reset = true};
    const std::size_t colon = value.find(':');
    if (colon == std::string::npos)
        return std::nullopt;
    const std::string what = value.substr(0, colon);
    const auto amount = parseReal(value.substr(colon + 1));
    if (!amount || !std::isfinite(*amount))
        return std::nullopt;
    const struct
    {
        const char* name;
        vec3 direction;
    } moves[] = {{"forward", {0, 0, 1}}, {"back", {0, 0, -1}}, {"left", {-1, 0, 0}},
                 {"right", {1, 0, 0}},   {"up", {0, 1, 0}},    {"down", {0, -1, 0}}};
    for (const auto& m : moves)
        if (what == m.name)
            return CameraAction{.move = float(*amount) * m.direction};
    if (what == "yaw")
        return CameraAction{.yawDegrees = float(*amount)};
    if (what == "pitch")
        return CameraAction{.pitchDegrees = float(*amount)};
    return std::nullopt;
}

std::vector<ActionSpec> joinActionSpecs(std::vector<ActionSpec> shared, const std::vector<ActionSpec>& own)
{
    shared.insert(shared.end(), own.begin(), own.end());
    return shared;
}
} // namespace rt
