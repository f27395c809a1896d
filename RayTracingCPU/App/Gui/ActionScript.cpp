#include "App/Gui/ActionScript.h"

#include <map>
#include <optional>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "Cli/ValueParsing.h"
#include "Error.h"
#include "Scenes/Catalogue.h"

namespace rt::gui
{
namespace
{
enum class Value
{
    None,
    Integer,
    Real,
    OnOff,
    Text
};

// name -> what its value must be. The names are the panel's, shortened.
const std::map<std::string, Value>& grammar()
{
    static const std::map<std::string, Value> g = {
        {"scene", Value::Text},   {"spp", Value::Integer},      {"depth", Value::Integer},
        {"width", Value::Integer}, {"aspect", Value::Real},     {"seed", Value::Integer},
        {"count", Value::Integer}, {"sampling", Value::Text},   {"pdf", Value::OnOff},
        {"unidirectional", Value::OnOff}, {"loop", Value::OnOff}, {"engine", Value::Text},
        {"render", Value::None},  {"cancel", Value::None},      {"defaults", Value::None},
        {"wait", Value::None},    {"running", Value::None},     {"frames", Value::Integer},
        {"resize", Value::Text},  {"save", Value::Text},        {"theme", Value::Text},
        {"font-size", Value::Integer}};
    return g;
}

std::optional<PixelSampling> sampling(const std::string& text)
{
    if (text == "normal" || text == "random")
        return PixelSampling::Random;
    if (text == "accumulation" || text == "accumulate")
        return PixelSampling::Accumulate;
    if (text == "stratified")
        return PixelSampling::Stratified;
    return std::nullopt;
}

std::optional<std::pair<int, int>> size(const std::string& text)
{
    const auto s = parseSize(text);
    if (!s || s->first < 0 || s->second < 0 || s->first > 16384 || s->second > 16384)
        return std::nullopt;
    return std::pair{int(s->first), int(s->second)};
}

/// Checks what the grammar cannot: known scene ids and engines, sampling names, sizes, themes.
bool valueIsValid(const std::string& name, const std::string& value)
{
    if (name == "scene")
        return findScene(value) != nullptr;
    if (name == "sampling")
        return sampling(value).has_value();
    if (name == "engine")
        return parseEngine(value).has_value();
    if (name == "resize")
        return size(value).has_value();
    if (name == "theme")
        return value == "dark" || value == "light";
    if (name == "save")
        return !value.empty();
    return true;
}
} // namespace

ActionScript::ActionScript(const std::string& text)
{
    std::size_t start = 0;
    while (start <= text.size())
    {
        const std::size_t end = std::min(text.find(';', start), text.size());
        std::string item = text.substr(start, end - start);
        start = end + 1;
        item.erase(0, item.find_first_not_of(" \t\n"));
        item.erase(item.find_last_not_of(" \t\n") + 1);
        if (item.empty())
            continue;
        const std::size_t eq = item.find('=');
        Action a{item.substr(0, eq), eq == std::string::npos ? "" : item.substr(eq + 1), item};
        const auto rule = grammar().find(a.name);
        if (rule == grammar().end())
            throw UsageError(fmt::format("--actions: unknown action '{}' (see --help)", a.text));
        const bool ok = [&] {
            switch (rule->second)
            {
            case Value::None: return eq == std::string::npos;
            case Value::Integer: return parseInteger(a.value).has_value();
            case Value::Real: return parseReal(a.value).has_value();
            case Value::OnOff: return parseOnOff(a.value).has_value();
            case Value::Text: return valueIsValid(a.name, a.value);
            }
            return false;
        }();
        if (!ok)
            throw UsageError(fmt::format("--actions: bad value in '{}' (see --help)", a.text));
        m_actions.push_back(std::move(a));
    }
}

bool ActionScript::step(Session& session, Window& window)
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

bool ActionScript::run(const Action& a, Session& session, Window& window)
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
    if (a.name == "spp")
        return check(session.setSpp(int(*parseInteger(v))));
    if (a.name == "depth")
        return check(session.setDepth(int(*parseInteger(v))));
    if (a.name == "width")
        return check(session.setWidth(int(*parseInteger(v))));
    if (a.name == "aspect")
        return check(session.setAspect(*parseReal(v)));
    if (a.name == "seed")
        return check(session.setSeed(*parseInteger(v)));
    if (a.name == "count")
        return check(session.setCount(int(*parseInteger(v))));
    if (a.name == "sampling")
    {
        session.setSampling(*sampling(v));
        return true;
    }
    if (a.name == "pdf")
    {
        session.setPdf(v == "on");
        return true;
    }
    if (a.name == "unidirectional")
    {
        session.setUnidirectionalLight(v == "on");
        return true;
    }
    if (a.name == "loop")
    {
        session.setLoop(v == "on");
        return true;
    }
    if (a.name == "engine")
    {
        const EngineKind engine = *parseEngine(v);
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
    if (a.name == "running")
        return !session.progress().busy ||
               (session.progress().phase == JobPhase::Rendering && session.progress().fraction > 0.0);
    if (a.name == "frames")
    {
        if (!m_waiting)
            m_framesLeft = int(*parseInteger(v));
        return m_framesLeft-- <= 0;
    }
    if (a.name == "resize")
    {
        const auto [w, h] = *size(v);
        window.resize(w, h);
        return true;
    }
    if (a.name == "save")
        return check(session.saveImage(v));
    if (a.name == "theme")
    {
        session.setDark(v == "dark");
        return true;
    }
    if (a.name == "font-size")
    {
        session.setFontSize(float(*parseInteger(v)));
        return true;
    }
    return true;
}

std::string actionHelp()
{
    return "UI actions separated by ';', one per frame, each calling what its widget calls:\n"
           "  scene=ID spp=N depth=N width=N aspect=A seed=N count=N sampling=normal|accumulation|stratified\n"
           "  pdf=on|off unidirectional=on|off loop=on|off   (image settings: a change starts a new render)\n"
           "  engine=single|multi|gpu (gpu waits for the GPU engine to start; unavailable: a warning)\n"
           "  render  cancel  defaults (the scene's own settings)  save=FILE.png (and FILE.pfm)\n"
           "  wait (until no render runs; loop rendering: until one more finishes)\n"
           "  running (until a render is tracing, or none runs)  frames=N (let N frames pass)\n"
           "  resize=WxH (0x0 too)  theme=dark|light  font-size=N\n"
           "e.g. \"engine=single;render;wait;engine=multi;render;wait;engine=gpu;render;wait\"";
}
} // namespace rt::gui
