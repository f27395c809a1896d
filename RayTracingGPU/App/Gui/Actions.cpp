#include "App/Gui/Actions.h"

#include <cmath>
#include <functional>
#include <limits>

#include <spdlog/fmt/fmt.h>

#include "Cli/ValueParsing.h"
#include "Error.h"

namespace rt::gpu::gui
{
namespace
{
int toInt(const Action& a, const std::string& text, int minimum)
{
    const auto value = parseInteger(text);
    if (!value || *value < minimum || *value > std::numeric_limits<int>::max())
        throw UsageError(fmt::format("--actions: {}={}: expected an integer >= {}", a.name, text, minimum));
    return static_cast<int>(*value);
}

int toInt(const Action& a, int minimum) { return toInt(a, a.value, minimum); }

float toFloat(const Action& a, const std::string& text, float minimum)
{
    const auto value = parseReal(text);
    if (!value || !std::isfinite(*value) || *value < minimum)
        throw UsageError(fmt::format("--actions: {}={}: expected a number >= {}", a.name, a.value, minimum));
    return *value;
}

bool toOnOff(const Action& a)
{
    if (const auto on = parseOnOff(a.value))
        return *on;
    throw UsageError(fmt::format("--actions: {}={}: expected on or off", a.name, a.value));
}

Extent toExtent(const Action& a)
{
    const std::size_t x = a.value.find('x');
    if (x == std::string::npos)
        throw UsageError(fmt::format("--actions: {}={}: expected WIDTHxHEIGHT", a.name, a.value));
    return {toInt(a, a.value.substr(0, x), 0), toInt(a, a.value.substr(x + 1), 0)};
}

/// camera=forward|back|left|right|up|down:<units>, yaw|pitch:<degrees>, reset.
void applyCamera(const Action& a, Controls* controls)
{
    if (a.value == "reset")
    {
        if (controls)
            controls->resetCamera();
        return;
    }
    const std::size_t colon = a.value.find(':');
    const std::string what = a.value.substr(0, colon);
    const float amount = colon == std::string::npos ? NAN : toFloat(a, a.value.substr(colon + 1), -1e30f);
    const struct
    {
        const char* name;
        vec3 direction; // view axes: right, up, forward
    } moves[] = {{"forward", {0, 0, 1}}, {"back", {0, 0, -1}}, {"left", {-1, 0, 0}},
                 {"right", {1, 0, 0}},   {"up", {0, 1, 0}},    {"down", {0, -1, 0}}};
    if (std::isnan(amount))
        throw UsageError(fmt::format("--actions: camera={}: expected reset or <move>:<amount>", a.value));
    for (const auto& m : moves)
        if (what == m.name)
        {
            if (controls)
                controls->moveCamera(amount * m.direction);
            return;
        }
    if (what == "yaw" || what == "pitch")
    {
        if (controls)
            controls->turnCamera(what == "yaw" ? amount : 0.0f, what == "pitch" ? amount : 0.0f);
        return;
    }
    throw UsageError(fmt::format("--actions: camera={}: expected forward, back, left, right, up, down, yaw, pitch "
                                 "or reset",
                                 a.value));
}

struct ActionKind
{
    const char* name;
    const char* value;
    const char* meaning;
    /// Checks the value and, with controls, applies it.
    std::function<void(const Action&, Controls*)> apply;
};

const std::vector<ActionKind>& actionKinds()
{
    static const std::vector<ActionKind> kinds = {
        {"scene", "ID", "switch scene (the next action waits until it is built)",
         [](const Action& a, Controls* c) {
             if (a.value.empty())
                 throw UsageError("--actions: scene=: expected a scene id");
             if (c)
                 c->selectScene(a.value);
         }},
        {"raytracing", "on|off", "ray tracing, or the rasterised preview",
         [](const Action& a, Controls* c) { const bool v = toOnOff(a); if (c) c->setRayTracing(v); }},
        {"accumulate", "on|off", "accumulate samples between frames",
         [](const Action& a, Controls* c) { const bool v = toOnOff(a); if (c) c->setAccumulate(v); }},
        {"heatmap", "on|off", "per-pixel cost (needs VK_KHR_shader_clock)",
         [](const Action& a, Controls* c) { const bool v = toOnOff(a); if (c) c->setHeatmap(v); }},
        {"heatmap-scale", "auto|TICKS", "top of the heatmap's palette, in clock ticks per sample",
         [](const Action& a, Controls* c) {
             if (a.value == "auto")
             {
                 if (c)
                     c->setAutoCostScale(true);
                 return;
             }
             const float v = toFloat(a, a.value, 1.0f);
             if (c)
             {
                 c->setAutoCostScale(false);
                 c->setCostScale(v);
             }
         }},
        {"samples", "N", "samples per pixel per frame",
         [](const Action& a, Controls* c) { const int v = toInt(a, 1); if (c) c->setSamplesPerFrame(v); }},
        {"spp", "N", "stop tracing at N samples per pixel (0: never)",
         [](const Action& a, Controls* c) { const int v = toInt(a, 0); if (c) c->setTargetSpp(v); }},
        {"depth", "N", "path segments at most",
         [](const Action& a, Controls* c) { const int v = toInt(a, 1); if (c) c->setDepth(v); }},
        {"pdf", "on|off", "mixture estimator, or BSDF sampling only",
         [](const Action& a, Controls* c) { const bool v = toOnOff(a); if (c) c->setPdf(v); }},
        {"unidirectional-light", "on|off", "emitters emit from their front face only",
         [](const Action& a, Controls* c) { const bool v = toOnOff(a); if (c) c->setUnidirectionalLight(v); }},
        {"fov", "DEGREES", "vertical field of view",
         [](const Action& a, Controls* c) { const float v = toFloat(a, a.value, 0.0f); if (c) c->setFov(v); }},
        {"aperture", "UNITS", "lens diameter (0: pinhole)",
         [](const Action& a, Controls* c) { const float v = toFloat(a, a.value, 0.0f); if (c) c->setAperture(v); }},
        {"focus", "UNITS", "focus distance",
         [](const Action& a, Controls* c) { const float v = toFloat(a, a.value, 1e-4f); if (c) c->setFocusDistance(v); }},
        {"camera", "MOVE:AMOUNT|reset",
         "move forward/back/left/right/up/down by AMOUNT world units, or turn yaw/pitch by AMOUNT degrees",
         applyCamera},
        {"resize", "WxH", "resize the window (0x0: as a minimised window reports)",
         [](const Action& a, Controls* c) { const Extent v = toExtent(a); if (c) c->resize(v); }},
        {"save", "FILE.png", "save the accumulated image: FILE.png and FILE.pfm",
         [](const Action& a, Controls* c) {
             if (a.value.empty())
                 throw UsageError("--actions: save=: expected a file name");
             if (c)
                 c->save(a.value);
         }},
        {"wait", "N", "let N frames pass", [](const Action& a, Controls*) { toInt(a, 0); }},
        {"style", "dark|light", "colour style of the panel",
         [](const Action& a, Controls* c) {
             if (a.value != "dark" && a.value != "light")
                 throw UsageError(fmt::format("--actions: style={}: expected dark or light", a.value));
             if (c)
                 c->setDarkStyle(a.value == "dark");
         }},
        {"font", "NAME", "font of the panel, as the panel lists it",
         [](const Action& a, Controls* c) {
             if (a.value.empty())
                 throw UsageError("--actions: font=: expected a font name");
             if (c)
                 c->setFont(a.value);
         }},
        {"font-size", "SCALE", "font scale of the panel (0.5 to 3)",
         [](const Action& a, Controls* c) { const float v = toFloat(a, a.value, 0.5f); if (c) c->setFontScale(v); }},
    };
    return kinds;
}

const ActionKind& kindOf(const Action& action)
{
    for (const ActionKind& k : actionKinds())
        if (action.name == k.name)
            return k;
    throw UsageError(fmt::format("--actions: unknown action '{}' (see --help)", action.name));
}
} // namespace

std::vector<Action> parseActions(const std::string& script)
{
    std::vector<Action> actions;
    std::size_t start = 0;
    while (start <= script.size())
    {
        const std::size_t end = std::min(script.find(';', start), script.size());
        const std::string item = script.substr(start, end - start);
        start = end + 1;
        if (item.find_first_not_of(" \t") == std::string::npos)
            continue;
        const std::size_t equals = item.find('=');
        if (equals == std::string::npos)
            throw UsageError(fmt::format("--actions: '{}' is not NAME=VALUE", item));
        Action action{item.substr(0, equals), item.substr(equals + 1)};
        kindOf(action).apply(action, nullptr); // checks the value
        actions.push_back(std::move(action));
    }
    return actions;
}

bool applyAction(const Action& action, Controls& controls)
{
    if (action.name == "wait")
        return false;
    kindOf(action).apply(action, &controls);
    return true;
}

int waitFrames(const Action& action) { return action.name == "wait" ? std::stoi(action.value) : 0; }

std::string actionHelp()
{
    std::string help;
    for (const ActionKind& k : actionKinds())
        help += fmt::format("  {:<30} {}\n", fmt::format("{}={}", k.name, k.value), k.meaning);
    return help;
}
} // namespace rt::gpu::gui
