#include "Engine/GpuEngine.h"

#include <chrono>

#include "Assets/AssetPaths.h"
#include "Engine/DispatchPlan.h"
#include "Engine/GpuContext.h"
#include "Engine/GpuScene.h"
#include "Engine/PathTracingPipeline.h"
#include "Engine/RenderLimits.h"
#include "Engine/RenderTarget.h"
#include "Engine/Uniforms.h"
#include "Error.h"
#include "Vulkan/Barriers.h"
#include "Vulkan/CommandBuffer.h"
#include "Vulkan/DescriptorPool.h"
#include "Vulkan/QueryPool.h"

namespace rt::gpu
{
namespace
{
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

TargetLimits targetLimits(const vk::Device& device)
{
    const vk::DeviceProperties& p = device.properties();
    return {p.name, p.limits.maxImageDimension2D, p.deviceLocalHeapSize, p.maxMemoryAllocationSize,
            p.rayTracing.maxRayDispatchInvocationCount};
}
} // namespace

struct GpuEngine::Impl
{
    GpuContext context;
    std::filesystem::path shaderDir;
    PathTracingPipeline pipeline;
    vk::QueryPool timestamps;
    std::uint64_t pathsPerDispatch;
    const Scene* sceneDesc = nullptr;
    std::unique_ptr<GpuScene> scene;
    double buildSeconds = 0.0;
    std::unique_ptr<RenderTarget> target;
    vk::DescriptorPool descriptorPool;
    VkDescriptorSet descriptorSet = VK_NULL_HANDLE;

    explicit Impl(const GpuEngineOptions& options)
        : context({options.deviceIndex, options.validation, options.presentation}),
          shaderDir(options.shaderDir.empty() ? executableDir() / "shaders" : options.shaderDir),
          pipeline(context.device(), shaderDir),
          timestamps(context.device(), 2),
          pathsPerDispatch(options.pathsPerDispatch > 0 ? options.pathsPerDispatch
                           : context.device().properties().type == vk::DeviceType::Cpu ? kPathsPerDispatchCpu
                                                                                       : kPathsPerDispatchGpu)
    {
    }

    const vk::Device& device() const { return context.device(); }

    /// A target of the settings' size (kept while the size stays, across scenes) and a descriptor set for it
    /// and the scene (setScene drops the set).
    void prepareTarget(std::uint32_t width, std::uint32_t height)
    {
        const bool resized = !target || target->width() != width || target->height() != height;
        if (!resized && descriptorSet != VK_NULL_HANDLE)
            return;
        descriptorPool = vk::DescriptorPool(); // its set names the old target or the old scene
        descriptorSet = VK_NULL_HANDLE;
        if (resized)
        {
            target.reset();
            target = std::make_unique<RenderTarget>(device(), width, height);
        }
        const auto imageCount = static_cast<std::uint32_t>(scene->imageViews().size());
        descriptorPool = vk::DescriptorPool(device(), pipeline.bindings(), imageCount);
        descriptorSet = descriptorPool.allocate(pipeline.setLayout(), imageCount);
        pipeline.writeDescriptors(device(), descriptorSet, *scene, target->bindings());
    }

    /// Records and runs one dispatch: `samples` samples per pixel from `firstSample` on.
    /// Returns the GPU seconds of the launches (negative when the queue has no timestamps).
    double dispatch(std::uint32_t firstSample, std::uint32_t samples, bool readback)
    {
        const bool timed = device().properties().timestampValidBits > 0;
        vk::submitAndWait(device(), context.commandPool(), [&](VkCommandBuffer cmd) {
            if (timed)
            {
                vkCmdResetQueryPool(cmd, timestamps.Handle(), 0, 2);
                vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, timestamps.Handle(), 0);
            }
            pipeline.recordLaunch(cmd, {&descriptorSet, 1}, firstSample, samples, {target->width(), target->height()},
                                  scene->samplesPerLaunch());
            if (timed)
                vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps.Handle(), 1);
            if (readback)
                target->recordReadback(cmd);
            vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_SHADER_WRITE_BIT,
                              VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT); // the NaN/Inf counters
        });
        return timed ? timestamps.secondsBetween(0, device().properties().limits.timestampPeriod) : -1.0;
    }

    void clear()
    {
        vk::submitAndWait(device(), context.commandPool(), [&](VkCommandBuffer cmd) { target->recordClear(cmd); });
    }

    void readback()
    {
        vk::submitAndWait(device(), context.commandPool(), [&](VkCommandBuffer cmd) { target->recordReadback(cmd); });
    }
};

GpuEngine::GpuEngine(const GpuEngineOptions& options) : m_impl(std::make_unique<Impl>(options)) {}

GpuEngine::~GpuEngine() = default;

std::string GpuEngine::deviceName() const { return m_impl->device().properties().name; }

const GpuContext& GpuEngine::context() const { return m_impl->context; }

bool GpuEngine::validationEnabled() const { return m_impl->context.validationEnabled(); }

std::uint64_t GpuEngine::validationMessages() const { return m_impl->context.validationMessages(); }

std::shared_ptr<const vk::ValidationLog> GpuEngine::validationLog() const
{
    return m_impl->context.instance().validationLog();
}

const PathTracingPipeline& GpuEngine::pipeline() const { return m_impl->pipeline; }

const std::filesystem::path& GpuEngine::shaderDir() const { return m_impl->shaderDir; }

const GpuScene& GpuEngine::gpuScene() const
{
    if (!m_impl->scene)
        throw UsageError("GpuEngine::gpuScene called before setScene");
    return *m_impl->scene;
}

const Scene& GpuEngine::scene() const
{
    if (!m_impl->sceneDesc)
        throw UsageError("GpuEngine::scene called before setScene");
    return *m_impl->sceneDesc;
}

double GpuEngine::setScene(const Scene& scene)
{
    Impl& e = *m_impl;
    scene.validate();
    e.descriptorPool = vk::DescriptorPool();
    e.descriptorSet = VK_NULL_HANDLE;
    e.scene.reset();
    e.sceneDesc = nullptr;
    e.scene = std::make_unique<GpuScene>(e.device(), e.context.commandPool(), scene, e.pipeline.maxImages());
    e.sceneDesc = &scene;
    e.buildSeconds = e.scene->buildSeconds();
    return e.buildSeconds;
}

RenderResult GpuEngine::render(const RenderSettings& settings, RenderControl& control, const PreviewCallback& preview)
{
    const Clock::time_point wallStart = Clock::now();
    Impl& e = *m_impl;
    settings.validate();
    if (!e.scene)
        throw UsageError("GpuEngine::render called before setScene");
    const auto width = static_cast<std::uint32_t>(settings.width);
    const auto height = static_cast<std::uint32_t>(settings.height());
    if (const auto problem = checkTargetLimits(width, height, targetLimits(e.device())))
        throw DeviceError(*problem);

    e.prepareTarget(width, height);
    e.target->reset(makeUniforms(*e.sceneDesc, e.sceneDesc->camera, settings, width, height, e.scene->lightCount()));
    const auto totalSamples = static_cast<std::uint32_t>(settings.trueSpp());
    const DispatchPlan plan = planDispatches(totalSamples, std::uint64_t(width) * height, e.pathsPerDispatch,
                                             settings.sampling == PixelSampling::Accumulate);

    RenderResult result;
    RenderStats& stats = result.stats;
    e.clear();
    control.begin(plan.dispatchCount);
    std::uint32_t samplesDone = 0;
    double gpuSeconds = 0.0;
    bool timed = true;
    const Clock::time_point renderStart = Clock::now();
    bool readBack = false; // the last dispatch copied the image to the host (for a preview)
    for (std::uint32_t d = 0; d < plan.dispatchCount; ++d)
    {
        if (control.cancelRequested())
        {
            stats.cancelled = true;
            break;
        }
        const std::uint32_t samples = plan.samplesIn(d, totalSamples);
        readBack = preview && control.previewDue();
        const double seconds = e.dispatch(samplesDone, samples, readBack);
        timed = timed && seconds >= 0.0;
        gpuSeconds += seconds;
        samplesDone += samples;
        control.advance();
        if (readBack)
            preview(e.target->readEstimate(samplesDone), static_cast<int>(samplesDone));
    }
    stats.renderSeconds = secondsSince(renderStart);
    if (!readBack)
        e.readback();
    result.image = e.target->readEstimate(samplesDone);

    const shader::SampleCounters counters = e.target->readCounters();
    stats.scene = e.sceneDesc->id;
    stats.engine = EngineKind::Gpu;
    stats.device = deviceName();
    stats.settings = settings;
    stats.width = static_cast<int>(width);
    stats.height = static_cast<int>(height);
    stats.trueSpp = static_cast<int>(samplesDone);
    stats.buildSeconds = e.buildSeconds;
    stats.gpuSeconds = timed ? gpuSeconds : -1.0;
    stats.paths = std::uint64_t(width) * height * samplesDone;
    stats.nanSamples = counters.nanSamples;
    stats.infSamples = counters.infSamples;
    stats.threadsUsed = 1;
    stats.wallSeconds = secondsSince(wallStart) + e.buildSeconds; // as the CPU engine: build included
    return result;
}
} // namespace rt::gpu
