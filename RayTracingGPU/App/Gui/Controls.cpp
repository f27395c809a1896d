#include "App/Gui/Controls.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "Scene/CameraMoves.h"
#include "Cli/ActionGrammar.h"
#include "Error.h"
#include "Render/MemoryBudget.h"
#include "SceneFile/SceneFile.h"
#include "Scenes/Catalogue.h"

namespace rt::gpu::gui
{
namespace
{
/// `value` held to [low, high]; one outside says so, naming the limit.
int held(WindowState& state, const char* what, int value, int low, int high, const char* unit)
{
    const int kept = std::clamp(value, low, high);
    if (kept != value)
    {
        state.message = fmt::format("{} {}{}: {} than the {} allowed, {}{}; using {}{}", what, value, unit,
                                    value > high ? "more" : "less", value > high ? "largest" : "smallest", kept,
                                    unit, kept, unit);
        spdlog::warn("{}", state.message);
    }
    return kept;
}

float basePixels(const WindowState& state) { return state.display.font == 0 ? kImGuiFontPixels : kPanelFontPixels; }
} // namespace

void Controls::selectScene(const std::string& idOrPath)
{
    if (const std::string problem = sceneProblem(idOrPath); !problem.empty())
        throw SceneError(problem);
    m_state->sceneRequest = idOrPath;
}

void Controls::setFresnel(std::optional<shader::FresnelModel> fresnel)
{
    SceneOptions& options = m_state->image.request.scene.options;
    if (options.fresnel == fresnel)
        return;
    options.fresnel = fresnel;
    if (!m_state->sceneRequest)
        m_state->sceneRequest = m_state->image.request.scene.id; // the materials are the scene's: build it again
}

void Controls::setRoughnessScale(float scale)
{
    SceneOptions& options = m_state->image.request.scene.options;
    scale = std::clamp(scale, kMinRoughnessScale, kMaxRoughnessScale);
    if (options.roughnessScale == scale)
        return;
    options.roughnessScale = scale;
    if (!m_state->sceneRequest)
        m_state->sceneRequest = m_state->image.request.scene.id; // the materials are the scene's: build it again
}

void Controls::setRayTracing(bool on) { m_state->image.rayTracing = on; }
void Controls::setEngine(EngineKind engine) { m_state->engine = engine; }
void Controls::chooseStrategy() { m_state->pilotRequest = true; }
void Controls::setAccumulate(bool on) { m_state->image.accumulate = on; }
void Controls::setHeatmap(bool on) { m_state->image.heatmap = on && m_state->costAvailable; }
void Controls::setAutoCostScale(bool on) { m_state->display.autoCostScale = on; }
void Controls::setCostScale(float ticksPerSample) { m_state->display.costScale = std::max(ticksPerSample, 1.0f); }
void Controls::setSamplesPerFrame(int samples)
{
    m_state->display.samplesPerFrame = held(*m_state, "samples per frame", samples, 0, kMaxSamplesPerFrame, "");
}
void Controls::setStopSpp(int spp)
{
    const int kept = held(*m_state, "stop at spp", spp, 0, std::numeric_limits<int>::max(), "");
    m_state->display.stopAtSpp = kept > 0;
    if (kept > 0)
        m_state->image.request.settings.spp = kept;
}
void Controls::setDepth(int depth)
{
    m_state->image.request.settings.depth = held(*m_state, "depth", depth, 1, std::numeric_limits<int>::max(), "");
}
bool Controls::setSetting(const Setting& setting, std::string_view value)
{
    RenderSettings changed = m_state->image.request.settings;
    if (!setting.assign(setting, changed, value))
    {
        m_state->message = setting.refusal(value);
        spdlog::warn("{}", m_state->message);
        return false;
    }
    try // the command line's memory check: a size (or restir-di's frame) that would not fit is refused
    {
        checkMemory(renderBytes(changed, m_state->sceneObjects),
                    fmt::format("a {}x{} render of {}", changed.width, changed.height(), m_state->image.request.scene.id),
                    availableMemoryBytesReplacing(renderBytes(m_state->image.request.settings, m_state->sceneObjects)));
    }
    catch (const Error& e)
    {
        m_state->message = e.what();
        spdlog::warn("{}", m_state->message);
        return false;
    }
    m_state->image.request.settings = changed;
    return true;
}
void Controls::setPdf(bool on)
{
    m_state->image.request.settings.estimator = on ? Estimator::Mixture : Estimator::BsdfOnly;
}
void Controls::setSobol(bool on)
{
    m_state->image.request.settings.sampling = on ? PixelSampling::Sobol : PixelSampling::Accumulate;
}
void Controls::setFov(float degrees) { m_state->image.camera = withFov(m_state->image.camera, degrees); }
void Controls::setAperture(float diameter) { m_state->image.camera = withAperture(m_state->image.camera, diameter); }

void Controls::setFocusDistance(float distance)
{
    m_state->image.camera = withFocusDistance(m_state->image.camera, distance);
}

void Controls::moveCamera(const vec3& offset) { m_state->image.camera = rt::moveCamera(m_state->image.camera, offset); }

void Controls::turnCamera(float yawDegrees, float pitchDegrees)
{
    m_state->image.camera = rt::turnCamera(m_state->image.camera, yawDegrees, pitchDegrees);
}

void Controls::resetCamera() { m_state->image.camera = m_state->sceneCamera; }
void Controls::setDarkStyle(bool dark) { m_state->display.darkStyle = dark; }
void Controls::setFont(const std::string& name)
{
    const std::vector<std::string>& fonts = m_state->fonts;
    const auto found = std::find(fonts.begin(), fonts.end(), name);
    if (found == fonts.end())
    {
        std::string known;
        for (const std::string& f : fonts)
            known += (known.empty() ? "'" : ", '") + f + "'";
        throw UsageError(fmt::format("no font '{}' (installed: {})", name, known));
    }
    m_state->display.font = static_cast<int>(found - fonts.begin());
}

void Controls::setFontPixels(int pixels)
{
    const int kept = held(*m_state, "font size", pixels, kMinFontPixels, kMaxFontPixels, " px");
    m_state->display.fontScale = float(kept) / basePixels(*m_state);
}

int Controls::fontPixels() const { return int(std::lround(m_state->display.fontScale * basePixels(*m_state))); }

bool Controls::requestPng(const std::filesystem::path& png, std::optional<std::filesystem::path>& request)
{
    if (const std::string problem = saveImagePathProblem(png.string()); !problem.empty())
    {
        m_state->message = problem;
        spdlog::error("{}", problem);
        return false;
    }
    request = png;
    return true;
}

bool Controls::save(const std::filesystem::path& png) { return requestPng(png, m_state->saveRequest); }

bool Controls::savePlot(const std::filesystem::path& png) { return requestPng(png, m_state->savePlotRequest); }
void Controls::resize(Extent size) { m_state->resizeRequest = Extent{std::max(size.width, 0), std::max(size.height, 0)}; }
} // namespace rt::gpu::gui
