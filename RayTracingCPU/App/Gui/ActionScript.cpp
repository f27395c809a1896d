#include "App/Gui/ActionScript.h"

#include <optional>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "Cli/ActionGrammar.h"
#include "Error.h"
#include "Scenes/Catalogue.h"

namespace rt::gui
{
namespace
{
/// The window's actions: the shared ones (Cli/ActionGrammar.h), then this window's own.
const std::vector<ActionSpec>& specs()
{
    static const std::vector<ActionSpec> all = joinActionSpecs(
        sharedActionSpecs("samples per pixel of the render", 1),
        {
            {"count", ActionValue::Integer, "N", "white-spheres' sphere count (-1: the scene's)", -1},
            {"loop", ActionValue::OnOff, "on|off", "loop rendering: render again with the next seed and average"},
            {"heatmap", ActionValue::OnOff, "on|off",
             "show each pixel's cost (renders again, timing every pixel) instead of the image"},
            {"engine", ActionValue::Text, "single|multi|gpu",
             "rendering engine (gpu waits for the GPU engine to start; unavailable: a warning)", 0, 1e30,
             [](const std::string& v) { return parseName<EngineKind>(v).has_value(); }},
            {"render", ActionValue::None, "", "start a render with the panel's settings"},
            {"choose-strategy", ActionValue::None, "",
             "a pilot chooses estimator, light sampler and selection (--strategy auto), then a render with them"},
            {"cancel", ActionValue::None, "", "cancel the render"},
            {"defaults", ActionValue::None, "", "the scene's own spp, depth, width, aspect and light mode"},
            {"wait", ActionValue::None, "", "until no render runs (loop rendering: until one more finishes)"},
            {"running", ActionValue::None, "", "until a render is tracing, or none runs"},
        });
    return all;
}
} // namespace

ActionScript::ActionScript(const std::string& text) : m_actions(parseActionScript(text, specs())) {}

bool ActionScript::step(Session& session, GlWindow& window)
{
    if (done())
        return true;
    const Action& action = m_actions[m_next];
    if (!m_waiting)
        spdlog::info("action {}", action.text);
    if (run(action, session, window))
    {
        ++m_next;
        m_waiting = false;
    }
    else
        m_waiting = true;
    return done();
}

bool ActionScript::run(const Action& a, Session& session, GlWindow& window)
{
    const auto check = [&](bool accepted) {
        if (!accepted)
        {
            ++m_failures;
            spdlog::error("action {} refused: {}", a.text, session.message());
        }
        return true;
    };
    const std::string& v = a.value;
    if (a.name == "scene")
        return check(session.setScene(v));
    if (a.name == "fresnel")
    {
        std::optional<shader::FresnelModel> model;
        parseFresnelOption(v, model); // the grammar has checked the name
        session.setFresnel(model);
        return true;
    }
    if (a.name == "roughness-scale")
    {
        session.setRoughnessScale(a.real());
        return true;
    }
    if (a.name == "count")
        return check(session.setCount(int(a.integer())));
    if (a.name == "pdf")
    {
        session.setPdf(a.on());
        return true;
    }
    if (const Setting* setting = findSetting(a.name))
        return check(session.setSetting(*setting, v));
    if (a.name == "loop")
    {
        session.setLoop(a.on());
        return true;
    }
    if (a.name == "heatmap")
    {
        session.setHeatmap(a.on());
        return true;
    }
    if (a.name == "engine")
    {
        const EngineKind engine = *parseName<EngineKind>(v);
        // The GPU radio button says "starting..." until the engine is up; a script waits for the answer.
        if (engine == EngineKind::Gpu && session.gpu().state == GpuStartup::State::Starting)
            return false;
        if (!session.selectEngine(engine))
            spdlog::warn("action {}: {}", a.text, session.message());
        return true;
    }
    if (a.name == "render")
    {
        session.render();
        return true;
    }
    if (a.name == "choose-strategy")
    {
        session.chooseStrategy();
        return true;
    }
    if (a.name == "cancel")
    {
        session.cancel();
        return true;
    }
    if (a.name == "defaults")
    {
        // The defaults are known once the render thread has built the scene.
        if (session.applySceneDefaults())
            return true;
        return !session.progress().busy && check(false);
    }
    if (a.name == "wait")
    {
        if (!m_waiting)
            m_finishedBefore = session.finishedRenders();
        return !session.progress().busy || (session.loop() && session.finishedRenders() > m_finishedBefore);
    }
    if (a.name == "wait-reference")
        return !session.progress().busy && !session.referencesPending();
    if (a.name == "running")
        return !session.progress().busy ||
               (session.progress().phase == JobPhase::Rendering && session.progress().fraction > 0.0);
    if (a.name == "frames")
    {
        if (!m_waiting)
            m_framesLeft = int(a.integer());
        return m_framesLeft-- <= 0;
    }
    if (a.name == "sleep")
    {
        const auto now = std::chrono::steady_clock::now();
        if (!m_waiting)
            m_sleepUntil = now + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                     std::chrono::duration<double>(a.real()));
        return now >= m_sleepUntil;
    }
    if (a.name == "resize")
    {
        const auto [w, h] = a.size();
        window.resize(w, h);
        return true;
    }
    if (a.name == "fov")
        return check(session.setFov(float(a.real())));
    if (a.name == "camera")
        return check(session.applyCamera(*parseCameraAction(v))); // checked by the spec
    if (a.name == "save")
        return check(session.saveImage(v));
    if (a.name == "save-plot")
        return check(session.savePlot(v));
    if (a.name == "theme")
    {
        session.setDark(v == "dark");
        return true;
    }
    if (a.name == "font-size")
    {
        session.setFontSize(float(a.integer()));
        return true;
    }
    throw Error("the action '" + a.name + "' has no command"); // a spec added without its command
}

std::string actionHelp()
{
    return "UI actions separated by ';', one per frame, each calling what its widget calls (a change of the image's\n"
           "settings starts a new render):\n" +
           actionScriptHelp(specs()) +
           "e.g. \"engine=single;render;wait;engine=multi;render;wait;engine=gpu;render;wait\"";
}
} // namespace rt::gui
