#include "App/Gui/Actions.h"

#include <cmath>

#include <spdlog/fmt/fmt.h>

#include "Cli/ValueParsing.h"
#include "Error.h"
#include "Scenes/Catalogue.h"

namespace rt::gpu::gui
{
namespace
{
/// The window's actions: the shared ones (Cli/ActionGrammar.h), then this window's own.
const std::vector<ActionSpec>& specs()
{
    static const std::vector<ActionSpec> all = joinActionSpecs(
        sharedActionSpecs("stop tracing at N samples per pixel (0: never)", 0),
        {
            {"raytracing", ActionValue::OnOff, "on|off", "ray tracing, or the rasterised preview"},
            {"wait", ActionValue::None, "",
             "until the image has reached its stop (a CPU engine: until its render ended); references may still run"},
            {"engine", ActionValue::Text, "gpu|single|multi",
             "what renders the image: the GPU in the frames, or a CPU engine a whole render at a time", 0, 1e30,
             [](const std::string& v) { return parseName<EngineKind>(v).has_value(); }},
            {"choose-strategy", ActionValue::None, "",
             "a pilot on the GPU chooses estimator, light sampler and selection (--strategy auto) for the image"},
            {"accumulate", ActionValue::OnOff, "on|off", "accumulate samples between frames"},
            {"sobol", ActionValue::OnOff, "on|off", "Owen-scrambled Sobol pixel samples (off: random)"},
            {"heatmap", ActionValue::OnOff, "on|off", "per-pixel cost (needs VK_KHR_shader_clock)"},
            {"heatmap-scale", ActionValue::Text, "auto|TICKS", "top of the heatmap's palette, in clock ticks per sample",
             0, 1e30,
             [](const std::string& v) {
                 const auto ticks = parseReal(v);
                 return v == "auto" || (ticks && std::isfinite(*ticks) && *ticks >= 1.0f);
             }},
            {"samples", ActionValue::Integer, "N", "samples per pixel per frame (0: by the device's time, about 50 ms a frame)",
             0, double(kMaxSamplesPerFrame)},
            {"aperture", ActionValue::Real, "UNITS", "lens diameter (0: pinhole)", 0},
            {"focus", ActionValue::Real, "UNITS", "focus distance", 1e-4},
            {"font", ActionValue::Text, "NAME", "font of the panel, as the panel lists it", 0, 1e30,
             [](const std::string& v) { return !v.empty(); }},
        });
    return all;
}
} // namespace

std::vector<Action> parseActions(const std::string& script) { return parseActionScript(script, specs()); }

bool applyAction(const Action& a, Controls& c)
{
    const std::string& n = a.name;
    if (n == "frames" || n == "sleep" || n == "wait" || n == "wait-reference")
        return false;
    if (n == "scene")
        c.selectScene(a.value);
    else if (n == "fresnel")
    {
        std::optional<shader::FresnelModel> model;
        parseFresnelOption(a.value, model); // the grammar has checked the name
        c.setFresnel(model);
    }
    else if (n == "roughness-scale")
        c.setRoughnessScale(a.real());
    else if (n == "spp")
        c.setStopSpp(int(a.integer()));
    else if (n == "depth")
        c.setDepth(int(a.integer()));
    else if (n == "pdf")
        c.setPdf(a.on());
    else if (n == "sobol")
        c.setSobol(a.on());
    else if (const Setting* setting = findSetting(n))
        c.setSetting(*setting, a.value);
    else if (n == "resize")
        c.resize({a.size().first, a.size().second});
    else if (n == "save")
        c.save(a.value);
    else if (n == "save-plot")
        c.savePlot(a.value);
    else if (n == "theme")
        c.setDarkStyle(a.value == "dark");
    else if (n == "font-size")
        c.setFontPixels(int(a.integer()));
    else if (n == "raytracing")
        c.setRayTracing(a.on());
    else if (n == "engine")
        c.setEngine(*parseName<EngineKind>(a.value)); // checked by the spec
    else if (n == "choose-strategy")
        c.chooseStrategy();
    else if (n == "accumulate")
        c.setAccumulate(a.on());
    else if (n == "heatmap")
        c.setHeatmap(a.on());
    else if (n == "heatmap-scale")
    {
        c.setAutoCostScale(a.value == "auto");
        if (a.value != "auto")
            c.setCostScale(a.real());
    }
    else if (n == "samples")
        c.setSamplesPerFrame(int(a.integer()));
    else if (n == "fov")
        c.setFov(a.real());
    else if (n == "aperture")
        c.setAperture(a.real());
    else if (n == "focus")
        c.setFocusDistance(a.real());
    else if (n == "camera")
    {
        const CameraAction move = *parseCameraAction(a.value); // checked by the spec
        if (move.reset)
            c.resetCamera();
        else if (move.move != vec3(0.0f))
            c.moveCamera(move.move);
        else
            c.turnCamera(move.yawDegrees, move.pitchDegrees);
    }
    else if (n == "font")
        c.setFont(a.value);
    else
        throw UsageError(fmt::format("--actions: '{}' has no effect in this window", a.text));
    return true;
}

int waitFrames(const Action& action) { return action.name == "frames" ? int(action.integer()) : 0; }

double waitSeconds(const Action& action) { return action.name == "sleep" ? double(action.real()) : 0.0; }

std::string actionHelp() { return actionScriptHelp(specs()); }
} // namespace rt::gpu::gui
