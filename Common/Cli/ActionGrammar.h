// The grammar of both windows' --actions: "name=value;name;..." (blanks around items ignored), run one per
// frame through the panel's own functions. Each window lists its actions in one table of ActionSpecs; the
// actions both windows have are declared once (sharedActionSpecs) with the same names, values and meaning,
// so that a script line means the same thing in either window. Parsing checks every name and value against
// the table, so a typo stops the app before its window opens.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "Math/Math.h"

namespace rt
{
struct Setting;

enum class ActionValue
{
    None, // a bare name: "render"
    Integer, // at least ActionSpec::minimum, at most ActionSpec::maximum (INT_MAX when it has none)
    Real, // finite, in [minimum, maximum]
    OnOff, // "on" or "off"
    Size, // "WxH", each in [0, 16384]
    Text // anything ActionSpec::accepts
};

struct ActionSpec
{
    std::string name;
    ActionValue value = ActionValue::None;
    std::string placeholder; // what --help shows after '=' ("N", "on|off", "ID"); empty for ActionValue::None
    std::string meaning;
    double minimum = 0.0;
    double maximum = 1e30;
    std::function<bool(const std::string&)> accepts = {}; // a further check of the value (Text: required)
};

/// One parsed action. The typed accessors read a value its spec has checked.
struct ScriptedAction
{
    std::string name;
    std::string value; // empty for ActionValue::None
    std::string text; // as written, for messages

    long long integer() const;
    float real() const;
    bool on() const;
    std::pair<int, int> size() const;
};

/// Parses `script` against `specs`. Throws UsageError naming the first unknown action or bad value.
std::vector<ScriptedAction> parseActionScript(std::string_view script, const std::vector<ActionSpec>& specs);

/// One line per spec, "  name=PLACEHOLDER   meaning", for --help.
std::string actionScriptHelp(const std::vector<ActionSpec>& specs);

/// The actions both windows have: scene=ID|FILE (a catalogue id or an existing scene file), fresnel=NAME,
/// roughness-scale=X, spp=N, width=N, aspect=X, seed=N, depth=N, sampling=NAME, estimator=NAME, pdf=on|off, russian-roulette=on|off|sqrt, unidirectional-light=on|off,
/// fov=DEGREES, camera=MOVE:AMOUNT|reset, resize=WxH, save=FILE.png, frames=N (let N frames pass), sleep=SECONDS (let that much time pass),
/// theme=dark|light, font-size=PIXELS. `sppMeaning` says what spp means in the window (the render's samples per pixel, or
/// where accumulation stops).
std::vector<ActionSpec> sharedActionSpecs(const std::string& sppMeaning, long long sppMinimum);

/// The panel's font height in both windows, in pixels (font-size=, the panels' sliders): below 10 the
/// panel's text is unreadable, above 32 the panel no longer fits beside the image.
inline constexpr int kMinFontPixels = 10;
inline constexpr int kMaxFontPixels = 32;

/// What the windows' camera=VALUE does: forward|back|left|right|up|down:UNITS moves by that many world units
/// along the view's axes, yaw|pitch:DEGREES turns (Scene/CameraMoves.h), reset returns to the scene's camera.
struct CameraAction
{
    bool reset = false;
    vec3 move{0.0f}; // view axes: right, up, forward
    float yawDegrees = 0.0f;
    float pitchDegrees = 0.0f;
};
/// Parses camera=VALUE; nullopt when it is none of the above or its amount is not a finite number.
std::optional<CameraAction> parseCameraAction(const std::string& value);

/// Why the windows' Save cannot write `path`, or empty when it can: they write PNG (sRGB) with the linear PFM
/// beside it, so the name must end in .png.
std::string saveImagePathProblem(const std::string& path);

/// The action that sets `setting` (Render/SettingsTable.h): its name, its words or range as the table parses them,
/// its tooltip as the meaning. A window applies it with Setting::assign.
ActionSpec settingActionSpec(const Setting& setting);

/// `shared` followed by `own`.
std::vector<ActionSpec> joinActionSpecs(std::vector<ActionSpec> shared, const std::vector<ActionSpec>& own);
} // namespace rt
