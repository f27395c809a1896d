#include "App/Gui/WindowApp.h"

#include <chrono>
#include <future>
#include <memory>

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "Scene/CameraMoves.h"
#include "App/Gui/CameraInput.h"
#include "App/Gui/Controls.h"
#include "App/Gui/DisplayPass.h"
#include "App/Gui/ImGuiLayer.h"
#include "App/Gui/Panel.h"
#include "App/Gui/Presenter.h"
#include "App/Gui/Throughput.h"
#include "App/Gui/VulkanWindow.h"
#include "App/Gui/RasterPreview.h"
#include "App/Gui/WindowLayout.h"
#include "Engine/ProgressiveFrame.h"
#include "Error.h"
#include "IO/AtomicFile.h"
#include "Image/ImageIO.h"
#include "SceneFile/SceneFileWatch.h"

namespace rt::gpu::gui
{
namespace
{
using Clock = std::chrono::steady_clock;

constexpr double kIdleFrameSeconds = 1.0 / 60.0;

GpuEngineOptions engineOptions(const WindowOptions& options, const VulkanWindow& window)
{
    GpuEngineOptions e;
    e.deviceIndex = options.deviceIndex;
    e.validation = options.validation;
    e.integrator = options.integrator;
    e.shaderDir = options.shaderDir;
    e.presentation = Presentation{VulkanWindow::requiredInstanceExtensions(),
                                  [&window](VkInstance instance) { return window.createSurface(instance); }};
    return e;
}

class WindowApp final
{
public:
    WindowApp(const WindowOptions& options, VulkanWindow& window, Scene scene)
        : m_options(options), m_window(window), m_engine(engineOptions(options, window)),
          m_scene(std::make_unique<Scene>(std::move(scene))),
          m_presenter(m_engine.context(), window.framebufferSize()),
          m_renderer(m_engine, kFramesInFlight),
          m_preview(m_engine.context().device(), m_engine.shaderDir(), m_presenter.renderPass()),
          m_display(m_engine.context().device(), m_engine.shaderDir(), m_presenter.renderPass()),
          m_imgui(m_engine.context(), window.handle(), m_presenter.renderPass(), kFramesInFlight),
          m_state(options.initial), m_controls(m_state)
    {
        m_panel.savePath = options.savePath;
        m_drawn.window = window.framebufferSize();
        m_state.costAvailable = m_renderer.costAvailable();
        m_state.fonts = m_imgui.fontNames();
        if (!options.screenshot.empty() && !m_presenter.canScreenshot())
            throw DeviceError("--screenshot: the window's swapchain cannot be copied from (no 8-bit format or no "
                              "VK_IMAGE_USAGE_TRANSFER_SRC_BIT)");
        m_state.image.heatmap = m_state.image.heatmap && m_state.costAvailable;
        if (options.initial.image.heatmap && !m_state.costAvailable)
            spdlog::warn("the device has no VK_KHR_shader_clock: no heatmap");
        showScene(*m_scene);
        m_watch.watch(m_state.image.request.scene.id, m_state.image.request.scene.fileVersion);
        spdlog::info("window on '{}': {} images, format {}, present mode {}, shader clock {}",
                     m_engine.deviceName(), m_presenter.imageCount(), static_cast<int>(m_presenter.format()),
                     static_cast<int>(m_presenter.presentMode()), m_state.costAvailable ? "yes" : "no");
    }

    ~WindowApp() { m_presenter.waitIdle(); }

    WindowApp(const WindowApp&) = delete;
    WindowApp& operator=(const WindowApp&) = delete;

    std::shared_ptr<const vk::ValidationLog> validationLog() const { return m_engine.validationLog(); }

    /// Runs until the window is closed or the automation is done; then writes --state-json.
    void run()
    {
        Clock::time_point last = Clock::now();
        while (!m_window.closeRequested() && !m_done)
        {
            // Nothing to trace: redraw on input, or at most at kIdleFrameSeconds (the preview, the panel).
            if (automated() || m_loading.valid() || tracing())
                m_window.pollEvents();
            else
                m_window.waitEvents(kIdleFrameSeconds);
            const Clock::time_point now = Clock::now();
            const float seconds = std::chrono::duration<float>(now - last).count();
            last = now;
            finishSceneBuild();
            runAutomation();
            pollSceneFile();
            startSceneBuild();
            applyRequests();
            if (m_window.framebufferSize().width == 0 || m_window.framebufferSize().height == 0)
            {
                // Minimised: nothing to draw into. Scripts keep running (their next action restores the window).
                m_window.waitEvents(automated() ? 0.01 : 0.0);
                continue;
            }
            drawFrame(seconds);
        }
        if (!m_options.stateJson.empty())
            writeStateJson();
    }

private:
    bool automated() const { return m_options.frames.has_value(); }

    /// The next frame traces samples: ray tracing is on and the image has not reached its stop.
    bool tracing() const
    {
        return m_state.image.rayTracing && (!m_state.display.stopAtSpp || !m_state.image.accumulate ||
                                            m_accumulatedSpp < std::uint32_t(m_state.image.request.settings.trueSpp()));
    }

    /// What a frame of `image` traces. Stratified samples only where the passes accumulate up to the settings'
    /// spp, the strata's count; otherwise random jitter per pass.
    FrameRequest requestOf(const ImageSettings& image) const
    {
        FrameRequest request;
        request.settings = image.request.settings;
        request.settings.sampling = progressiveSampling(request.settings.sampling,
                                                        m_state.display.stopAtSpp && image.accumulate);
        request.camera = image.camera;
        request.cost = image.heatmap;
        return request;
    }

    /// The samples in the accumulation image (traced with m_traced) are samples of the panel's image: the same
    /// settings but perhaps the spp, where tracing stops, as long as the spp does not change the integrator
    /// (whose images differ by noise).
    bool accumulationFits() const
    {
        ImageSettings now = m_state.image;
        // Stratified samples of another spp lie in other strata: another image.
        if (requestOf(now).settings.sampling != PixelSampling::Stratified)
            now.request.settings.spp = m_traced.request.settings.spp;
        return now == m_traced && requestOf(m_state.image).settings.sampling == requestOf(m_traced).settings.sampling &&
               m_renderer.integratorFor(requestOf(m_state.image)) == m_renderer.integratorFor(requestOf(m_traced));
    }

    /// Puts `scene` on the device, in the preview and behind the renderer's descriptor sets; the device is idle.
    void showScene(const Scene& scene)
    {
        m_engine.setScene(scene);
        m_preview.setScene(scene, m_engine.context().commandPool());
        prepareImages(m_state.image.extent());
        m_state.image.request.scene.id = scene.id;
        m_state.sceneCamera = scene.camera;
        m_state.sceneObjects = scene.primitiveCount() + scene.lights.size();
        m_state.image.camera = scene.camera;
        m_state.cameraSpeed = movementSpeed(scene.camera);
        glfwSetWindowTitle(m_window.handle(), ("ray-tracing-gpu: " + scene.id).c_str());
    }

    void prepareImages(Extent extent)
    {
        m_renderer.prepare({static_cast<std::uint32_t>(extent.width), static_cast<std::uint32_t>(extent.height)});
        m_display.setImages(m_renderer.accumulationView(), m_renderer.costView());
        m_needsClear = true;
    }

    void startSceneBuild()
    {
        if (!m_state.sceneRequest || m_loading.valid())
            return; // one build at a time; a newer request waits for it
        m_loadingId = *m_state.sceneRequest;
        m_state.sceneRequest.reset();
        // The version is read before the file: an edit saved while it is being read is noticed afterwards.
        const SceneRef ref{.id = m_loadingId,
                           .options = m_state.image.request.scene.options,
                           .fileVersion = sceneFileVersion(m_loadingId)};
        m_watch.watch(ref.id, ref.fileVersion);
        // The same version of the scene on screen, built again for its options (Fresnel, roughness): the view
        // the user moved to stays.
        m_loadingKeepsView = ref.id == m_state.image.request.scene.id &&
                             ref.fileVersion == m_state.image.request.scene.fileVersion;
        m_loadingVersion = ref.fileVersion;
        m_loading = std::async(std::launch::async, [ref] { return buildScene(ref); });
    }

    /// A new version of the scene file asked for last is built as if selected again; the scene on screen
    /// stays until it has been built, and stays for good when it fails.
    void pollSceneFile()
    {
        const std::optional<std::int64_t> version = m_watch.poll(Clock::now());
        if (!version || m_state.sceneRequest)
            return;
        spdlog::info("{} changed on disk: reloading it", m_watch.path());
        m_state.sceneRequest = m_watch.path();
    }

    void finishSceneBuild()
    {
        if (!m_loading.valid() || m_loading.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
            return;
        try
        {
            auto scene = std::make_unique<Scene>(m_loading.get());
            m_presenter.waitIdle();
            const CameraDesc view = m_state.image.camera;
            const float speed = m_state.cameraSpeed;
            try
            {
                showScene(*scene);
                if (m_loadingKeepsView)
                {
                    m_state.image.camera = view;
                    m_state.cameraSpeed = speed;
                }
            }
            catch (const Error&)
            {
                showScene(*m_scene); // the engine dropped the old scene before failing: put it back
                throw;
            }
            m_scene = std::move(scene);
            m_state.image.request.scene.fileVersion = m_loadingVersion;
            m_state.message.clear();
            m_sceneError.clear();
        }
        catch (const Error& e)
        {
            m_state.message = e.what();
            m_sceneError = e.what();
            if (automated())
                throw;
            spdlog::error("{}", e.what());
        }
    }

    void runAutomation()
    {
        if (!automated() || m_loading.valid() || m_state.sceneRequest)
            return; // a scene action waits until its scene is on screen
        if (m_waitFrames > 0)
        {
            --m_waitFrames;
            return;
        }
        if (Clock::now() < m_sleepUntil)
            return;
        if (m_nextAction < m_options.actions.size())
        {
            const Action& action = m_options.actions[m_nextAction++];
            spdlog::debug("action {}={}", action.name, action.value);
            if (!applyAction(action, m_controls))
            {
                m_waitFrames = waitFrames(action);
                m_sleepUntil = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                  std::chrono::duration<double>(waitSeconds(action)));
            }
        }
    }

    bool actionsDone() const
    {
        return m_nextAction >= m_options.actions.size() && m_waitFrames == 0 && Clock::now() >= m_sleepUntil &&
               !m_loading.valid() && !m_state.sceneRequest;
    }

    void applyRequests()
    {
        if (m_state.resizeRequest)
        {
            m_window.resize(*m_state.resizeRequest);
            m_state.resizeRequest.reset();
        }
        if (m_state.saveRequest)
        {
            const std::filesystem::path png = *m_state.saveRequest;
            m_state.saveRequest.reset();
            save(png);
        }
    }

    void save(const std::filesystem::path& png)
    {
        try
        {
            if (!m_state.image.rayTracing)
                throw UsageError("nothing to save: the window shows the rasterised preview; turn ray tracing on");
            // Before the first frame, or before the first frame of new settings (a save in the same frame as
            // the change): the accumulation image is empty or holds the old settings' samples.
            if (m_accumulatedSpp == 0 || !accumulationFits())
                throw UsageError("nothing to save yet: no frame rendered yet with the panel's settings (save after "
                                 "the first frame)");
            m_presenter.waitIdle();
            const Image image = m_renderer.readImage();
            const std::vector<std::filesystem::path> linear = writePngWithLinear(png, image);
            m_state.message = "saved " + png.string() + ", " + linear[0].string() + " and " + linear[1].string() + " (" +
                              std::to_string(m_accumulatedSpp) + " spp)";
            spdlog::info("{}", m_state.message);
        }
        catch (const Error& e)
        {
            m_state.message = e.what();
            if (automated())
                throw;
            spdlog::error("{}", e.what());
        }
    }

    PanelInfo panelInfo(Extent window) const
    {
        PanelInfo info;
        info.device = m_engine.deviceName();
        info.costAvailable = m_state.costAvailable;
        info.building = m_loading.valid() ? m_loadingId : std::string();
        info.sceneError = m_sceneError;
        info.microfacet = m_scene->hasMicrofacetMaterial();
        info.framesPerSecond = m_throughput.framesPerSecond();
        info.megaSamplesPerSecond = m_throughput.samplesPerSecond() * 1e-6;
        info.accumulatedSpp = static_cast<int>(m_accumulatedSpp);
        info.costMax = m_cost.max;
        info.costScale = costScale();
        info.window = window;
        info.image = m_state.image.extent();
        return info;
    }

    float costScale() const
    {
        return m_state.display.autoCostScale ? std::max(m_cost.high, 1.0f) : m_state.display.costScale;
    }

    /// The layout of a window of `framebuffer` pixels for the panel at the current font scale.
    WindowLayout layoutFor(Extent framebuffer) const
    {
        const float panelPixels = kPanelWidth * m_state.display.fontScale * framebufferScale();
        return layoutWindow(framebuffer, static_cast<int>(panelPixels), m_state.image.extent());
    }

    /// Framebuffer pixels per window coordinate (ImGui's coordinates): 1 on X11, 2 on a Retina display.
    static float framebufferScale() { return std::max(ImGui::GetIO().DisplayFramebufferScale.x, 1e-3f); }

    void drawFrame(float seconds)
    {
        const Extent size = m_window.framebufferSize();
        m_imgui.newFrame(m_state.display.darkStyle, m_state.display.font, m_state.display.fontScale);
        applyCameraInput(m_window.handle(), m_controls, m_state.cameraSpeed * seconds);
        WindowLayout layout = layoutFor(size);
        const PixelRect panelDrawn =
            drawPanel(m_controls, m_state, panelInfo(size), m_panel, layout.panel, framebufferScale());

        const std::optional<Frame> frame = m_presenter.beginFrame(size);
        if (!frame)
        {
            m_imgui.render(VK_NULL_HANDLE);
            return;
        }
        const Extent frameExtent{static_cast<int>(frame->extent.width), static_cast<int>(frame->extent.height)};
        if (!(frameExtent == size))
            layout.image = layoutFor(frameExtent).image; // the swapchain held to its surface's limits
        const VkExtent2D traced = m_renderer.extent();
        if (int(traced.width) != m_state.image.extent().width || int(traced.height) != m_state.image.extent().height)
        {
            m_presenter.waitIdle();
            prepareImages(m_state.image.extent());
        }
        m_drawn = {frameExtent, panelDrawn, layout.image};
        if (const CostSummary cost = m_renderer.takeCostSummary(frame->slot); cost.max > 0.0f)
            m_cost = cost;

        const VkCommandBuffer cmd = frame->commands;
        std::uint64_t samples = 0;
        if (m_state.image.rayTracing)
            samples = traceSamples(*frame);
        m_presenter.beginRenderPass(*frame);
        if (m_state.image.rayTracing)
        {
            shader::DisplayPushConstants push{};
            push.mode = m_state.image.heatmap ? shader::DisplayMode::Cost : shader::DisplayMode::Radiance;
            push.encodeSrgb = m_presenter.shaderEncodesSrgb() ? 1u : 0u;
            push.costScale = costScale();
            m_display.record(cmd, layout.image, m_state.image.extent(), push);
        }
        else
            m_preview.record(cmd, m_state.image.camera, layout.image, m_state.image.request.settings.aspect,
                             m_presenter.shaderEncodesSrgb());
        m_imgui.render(cmd);
        m_presenter.endRenderPass(*frame);

        const bool last = automated() && actionsDone() && m_framesAfterActions + 1 >= *m_options.frames;
        if (last && !m_options.screenshot.empty())
            m_presenter.recordScreenshot(*frame);
        m_presenter.endFrame(*frame, size);
        m_throughput.add(Throughput::Clock::now(), samples);
        if (automated() && actionsDone() && ++m_framesAfterActions >= *m_options.frames)
        {
            if (!m_options.screenshot.empty())
                saveScreenshot();
            m_done = true;
        }
    }

    /// Records this frame's samples; returns the camera samples (paths) traced.
    std::uint64_t traceSamples(const Frame& frame)
    {
        const VkCommandBuffer cmd = frame.commands;
        const bool restart = m_needsClear || !accumulationFits();
        if (restart || !m_state.image.accumulate)
        {
            m_renderer.recordClear(cmd);
            m_accumulatedSpp = 0;
            m_needsClear = false;
        }
        if (restart)
            m_nextSample = 0; // a new image: its samples are those of a headless render from index 0
        m_traced = m_state.image;

        auto count = static_cast<std::uint32_t>(m_state.display.samplesPerFrame);
        if (m_state.display.stopAtSpp && m_state.image.accumulate)
        {
            const auto target = static_cast<std::uint32_t>(m_state.image.request.settings.trueSpp());
            count = std::min(count, target > m_accumulatedSpp ? target - m_accumulatedSpp : 0u);
        }
        m_renderer.recordSamples(cmd, frame.slot, requestOf(m_state.image), m_nextSample, count);
        // Without accumulation the indices still advance, so each frame shows new noise, not the same frame.
        m_nextSample += count;
        m_accumulatedSpp += count;
        const Extent image = m_state.image.extent();
        return std::uint64_t(count) * std::uint64_t(image.width) * std::uint64_t(image.height);
    }

    /// --state-json: what the last frame drew where (framebuffer pixels, [x, y, width, height]), for the
    /// window tests to check the layout against the screenshot.
    void writeStateJson() const
    {
        const auto rect = [](const PixelRect& r) { return nlohmann::json::array({r.x, r.y, r.width, r.height}); };
        const Extent image = m_state.image.extent();
        const nlohmann::json state = {
            {"window", {m_drawn.window.width, m_drawn.window.height}},
            {"image_size", {image.width, image.height}},
            {"layout", {{"panel", rect(m_drawn.panel)}, {"image", rect(m_drawn.image)}}},
            {"ray_tracing", m_state.image.rayTracing},
            {"accumulated_spp", m_accumulatedSpp},
            {"samples_per_frame", m_state.display.samplesPerFrame},
            {"font_pixels", m_controls.fontPixels()},
            {"roughness_scale", m_state.image.request.scene.options.roughnessScale},
            {"message", m_state.message}};
        writeFileAtomically(m_options.stateJson, state.dump(2) + "\n");
    }

    void saveScreenshot()
    {
        int width = 0;
        int height = 0;
        const std::vector<unsigned char> rgba = m_presenter.screenshotPixels(width, height);
        writePng8(m_options.screenshot, width, height, rgba);
        spdlog::info("screenshot {} ({}x{}, {} spp)", m_options.screenshot.string(), width, height, m_accumulatedSpp);
    }

    const WindowOptions& m_options;
    VulkanWindow& m_window;
    GpuEngine m_engine;
    std::unique_ptr<Scene> m_scene; // what the engine renders (it keeps a pointer)
    Presenter m_presenter;
    ProgressiveFrame m_renderer;
    RasterPreview m_preview;
    DisplayPass m_display;
    ImGuiLayer m_imgui;
    WindowState m_state;
    Controls m_controls;
    PanelState m_panel;
    struct Drawn
    {
        Extent window;
        PixelRect panel; // as ImGui drew it
        PixelRect image;
    } m_drawn; // by the last frame, for --state-json

    std::future<Scene> m_loading;
    std::string m_loadingId;
    std::int64_t m_loadingVersion = 0;
    bool m_loadingKeepsView = false;
    SceneFileWatch m_watch; // the scene file asked for last
    std::string m_sceneError;
    ImageSettings m_traced; // the settings of the samples in the accumulation image
    bool m_needsClear = true; // new images, or a new scene behind them
    std::uint32_t m_nextSample = 0;
    std::uint32_t m_accumulatedSpp = 0;
    CostSummary m_cost; // of the last timed frame
    Throughput m_throughput;

    std::size_t m_nextAction = 0;
    int m_waitFrames = 0;
    Clock::time_point m_sleepUntil{};
    int m_framesAfterActions = 0;
    bool m_done = false;
};
} // namespace

int runWindow(const WindowOptions& options, Scene scene)
{
    std::shared_ptr<const vk::ValidationLog> log;
    {
        const bool defaultSize = !options.windowSize;
        const WindowSize size = defaultSize ? defaultWindowSize(options.initial.image.extent(), int(kPanelWidth))
                                            : *options.windowSize;
        VulkanWindow window("ray-tracing-gpu", size, defaultSize);
        WindowApp app(options, window, std::move(scene));
        log = app.validationLog();
        app.run();
    } // the device is destroyed here: leaked objects are reported into `log`
    if (log && log->total() > 0)
    {
        spdlog::error("Vulkan validation reported {} warnings or errors (see above)", log->total());
        return 1;
    }
    return 0;
}
} // namespace rt::gpu::gui
