#include "Engine/GpuEngine.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <map>
#include <thread>
#include <utility>
#include <tuple>

#include <spdlog/fmt/fmt.h>

#include "Assets/AssetPaths.h"
#include "Engine/BandPlan.h"
#include "Engine/CostTarget.h"
#include "Engine/GpuContext.h"
#include "Engine/GpuScene.h"
#include "Engine/RenderLimits.h"
#include "Engine/RenderTarget.h"
#include "Engine/RestirBuffers.h"
#include "Engine/RestirPipeline.h"
#include "Engine/SceneTracer.h"
#include "Engine/WaveStageTimer.h"
#include "Engine/WavefrontPipeline.h"
#include "Error.h"
#include "Shared/BandOrder.h"
#include "Vulkan/Barriers.h"
#include "Vulkan/CommandBuffer.h"
#include "Vulkan/QueryPool.h"

namespace rt::gpu
{
namespace
{
/// Segments of a wave the wavefront first records, before it knows how many its paths need (then as many as
/// the last wave of the same kind of path needed), and the segments of each further submission while paths
/// remain: the launches of a segment whose queue is empty cost the H100 about 25 us each.
constexpr std::uint32_t kFirstWaveSegments = 8;
constexpr std::uint32_t kWaveSegmentChunk = 8;
/// The most pixels (times seed blocks) of a target GpuEngine keeps aside after a resize: 2^20, 64 MiB at most
/// (RenderTarget: 32 B a pixel on the device, 32 B in the read-back buffer) beside a render of another size; a
/// pilot's targets hold a third of it or less (416 x 416 px, two seed blocks).
constexpr std::uint64_t kSparePixels = std::uint64_t(1) << 20;
/// Timestamp queries: 0-1 around a dispatch, 2-3 around a clear or readback, from 4 on around restir-di's passes.
constexpr std::uint32_t kRestirQueries = 4;

/// Adds the host seconds of its life to `stage`: a stage of stageSeconds on the host's clock.
class HostStageTimer
{
public:
    explicit HostStageTimer(double& stage) : m_stage(stage) {}
    ~HostStageTimer()
    {
        m_stage += std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    }
    HostStageTimer(const HostStageTimer&) = delete;
    HostStageTimer& operator=(const HostStageTimer&) = delete;

private:
    double& m_stage;
    std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

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
    SceneTracer tracer;
    vk::QueryPool timestamps;
    std::uint64_t pathsPerBatch;
    BandPlan bands{1}; // the frame's (beginFrame)
    std::uint32_t fixedBandRows = 0; // setBandRows: rows per submit; 0: by time
    std::unique_ptr<RenderTarget> target;
    /// The target before the last resize and its descriptor set (none after setScene or setIntegrator, nor where
    /// it named restir-di's buffers), kept while it holds at most kSparePixels: a pilot's frames switch between
    /// its measurements' size (two seed blocks) and its timing frames' (the image's width), and each new target
    /// cost an H200's host 7 ms, 12 of them 0.08 s of cornell-box-lights' 1.2 s search (notebook §69).
    std::unique_ptr<RenderTarget> spareTarget;
    TracingDescriptors spareDescriptors;
    std::unique_ptr<RestirBuffers> restir; // restir-di's, of the target's size, while a frame runs it
    // Whether restir's final reservoirs and surfaces hold a whole iteration of the frame, which the next one's
    // temporal reuse reads (false at the frame's start and after a cancelled iteration).
    bool restirHistory = false;
    TracingDescriptors descriptors; // the scene and the target; empty after setScene
    shader::RenderUniforms uniforms{}; // the frame's, as in the target's uniform buffer
    std::uint32_t frameBlocks = 1; // the frame's seed blocks (RenderEngine::setSeedBlock; the target may hold more)
    GpuIntegrator integrator = GpuIntegrator::Megakernel; // the frame's (SceneTracer::integratorFor)
    std::map<std::string, double> frameStages; // stageSeconds() of the frame
    std::unique_ptr<WaveStageTimer> waveTimer; // made at the first wavefront launch on a device with timestamps
    /// The wavefront's first submission per wave, its segments: what the last wave of the scene's same kind of path
    /// (WaveKind) needed, kFirstWaveSegments before any. Begun anew at each frame, the first wave of every frame (a
    /// pilot has 54, of 2-13 ms each on an H200) waited on up to six more submissions of eight segments, the host
    /// reading the queue's count before each. Lowering it by one only where a wave needed fewer cut an H200's waves
    /// that took a second submission from 63-72 % to 20 %, but the empty segments recorded instead cost its
    /// cornell-box-lights renders 0.2-1.2 % on the GPU's clock and saved nothing on the host's: not kept (notebook
    /// §69).
    using WaveKind = std::tuple<int, Estimator, RussianRoulette>; // depth, estimator, roulette: the paths' length
    std::map<WaveKind, std::uint32_t> learnedWaveSegments;
    WaveKind waveKind{};
    bool countRays = false; // GpuEngineOptions::countRays
    bool recordCost = false; // setCostRecording
    std::unique_ptr<CostTarget> cost; // the frame's, with cost recording; kept while the size stays
    std::uint64_t costSamples = 0; // samples per pixel of the frame's completed batches, while recording

    explicit Impl(const GpuEngineOptions& options)
        : context({options.deviceIndex, options.deviceShare, options.validation, options.presentation}),
          tracer(context.device(), context.commandPool(),
                 options.shaderDir.empty() ? executableDir() / "shaders" : options.shaderDir, options.specialize,
                 options.integrator, options.wavePaths),
          timestamps(context.device(), kRestirQueries + std::size(kRestirPasses) + 1),
          pathsPerBatch(options.pathsPerBatch > 0 ? options.pathsPerBatch
                        : context.device().properties().type == vk::DeviceType::Cpu ? kPathsPerBatchCpu
                                                                                    : kPathsPerBatchGpu),
          countRays(options.countRays)
    {
    }

    const vk::Device& device() const { return context.device(); }

    /// A target of the settings' size (kept while the size stays, across scenes; the spare where it fits),
    /// restir-di's buffers when `restirDi` (dropped when not), and a descriptor set for them and the scene
    /// (setScene drops the set).
    void prepareTarget(std::uint32_t width, std::uint32_t height, std::uint32_t blocks, bool restirDi)
    {
        // Blocks kept when fewer are asked for: a pilot's candidates are prepared on one, measured on two and timed
        // on one again, and each new target costs the host an allocation and the descriptors.
        const bool resized =
            !target || target->width() != width || target->height() != height || target->blocks() < blocks;
        const bool restirChanged = restirDi != bool(restir) || (restir && resized);
        if (!resized && !restirChanged && descriptors.set != VK_NULL_HANDLE)
            return;
        if (resized)
        {
            const bool spareFits = spareTarget && spareTarget->width() == width && spareTarget->height() == height &&
                                   spareTarget->blocks() >= blocks;
            if (restir)
                descriptors = {}; // it names the restir buffers, remade below
            std::swap(target, spareTarget);
            std::swap(descriptors, spareDescriptors);
            // A large old target goes before the new one is made: both may not fit at once.
            if (spareTarget && std::uint64_t(spareTarget->width()) * spareTarget->height() * spareTarget->blocks() >
                                   kSparePixels)
            {
                spareDescriptors = {};
                spareTarget.reset();
            }
            if (!spareFits)
            {
                descriptors = {};
                target.reset();
                target = std::make_unique<RenderTarget>(device(), width, height, blocks);
            }
        }
        if (restirChanged)
        {
            descriptors = {}; // it names the old restir buffers, or lacks the new ones
            restir.reset();
            if (restirDi)
                restir = std::make_unique<RestirBuffers>(device(), std::uint64_t(width) * height);
        }
        if (descriptors.set != VK_NULL_HANDLE)
            return; // the spare's
        TargetBindings bindings = target->bindings();
        bindings.restir = restir.get();
        descriptors = tracer.makeDescriptors(bindings);
    }

    /// Records and runs one dispatch: `samples` samples per pixel from `firstSample` on, over `rows` rows from
    /// position `firstRow` on in the row order of `interleave` (Shared/BandOrder.h); `snapshot` first copies the
    /// accumulation image to the readback buffer.
    /// Returns the GPU seconds of the launches (negative when the queue has no timestamps).
    double dispatch(std::uint32_t firstSample, std::uint32_t samples, std::uint32_t firstRow, std::uint32_t rows,
                    std::uint32_t interleave, bool snapshot)
    {
        if (integrator == GpuIntegrator::Wavefront)
            return dispatchWaves(firstSample, samples, firstRow, rows, interleave, snapshot);
        const bool timed = device().properties().timestampValidBits > 0;
        vk::submitAndWait(device(), context.commandPool(), [&](VkCommandBuffer cmd) {
            if (snapshot)
                target->recordReadback(cmd);
            if (timed)
            {
                vkCmdResetQueryPool(cmd, timestamps.Handle(), 0, 2);
                vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, timestamps.Handle(), 0);
            }
            if (cost)
            {
                const VkDescriptorSet sets[] = {descriptors.set, cost->set()};
                tracer.recordLaunch(cmd, sets, uniforms, GpuIntegrator::Megakernel, firstSample, samples,
                                    {target->width(), rows}, &cost->pipeline(), firstRow, interleave);
            }
            else
                tracer.recordLaunch(cmd, {&descriptors.set, 1}, uniforms, integrator, firstSample, samples,
                                    {target->width(), rows}, nullptr, firstRow, interleave);
            if (timed)
                vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps.Handle(), 1);
            vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_SHADER_WRITE_BIT,
                              VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT); // the NaN/Inf counters
        });
        return timed ? timestamps.secondsBetween(0, device().properties().limits.timestampPeriod) : -1.0;
    }

    /// dispatch() on the wavefront integrator: a submission per wave (its sums recorded in the next one), with
    /// the segments its paths are expected to need, then more while its queue is not empty: no launches over
    /// the empty queues of the segments after its longest path. The image is the one recordLaunch gives.
    double dispatchWaves(std::uint32_t firstSample, std::uint32_t samples, std::uint32_t firstRow, std::uint32_t rows,
                         std::uint32_t interleave, bool snapshot)
    {
        const bool timed = device().properties().timestampValidBits > 0;
        if (timed && !waveTimer)
            waveTimer = std::make_unique<WaveStageTimer>(device());
        const WaveBuffers& buffers = tracer.waves();
        const PipelineScene& scene = tracer.gpuScene().pipelineScene();
        double seconds = 0.0;
        bool first = true;
        const auto submit = [&](const std::function<void(WavefrontPipeline::Recorder&)>& record) {
            vk::submitAndWait(device(), context.commandPool(), [&](VkCommandBuffer cmd) {
                if (first && snapshot)
                    target->recordReadback(cmd);
                first = false;
                if (timed)
                {
                    vkCmdResetQueryPool(cmd, timestamps.Handle(), 0, 2);
                    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, timestamps.Handle(), 0);
                    waveTimer->begin(cmd);
                }
                WavefrontPipeline::Recorder recorder(*tracer.wavefront(), cmd, {&descriptors.set, 1}, uniforms, scene,
                                                     firstRow, interleave, buffers, waveTimer.get());
                record(recorder);
                buffers.recordCountersReadback(cmd);
                if (timed)
                    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps.Handle(), 1);
            });
            if (timed)
            {
                waveTimer->addTo(frameStages);
                seconds += timestamps.secondsBetween(0, device().properties().limits.timestampPeriod);
            }
        };
        const std::uint32_t depth = uniforms.depth;
        const std::vector<Wave> waves = planWaves(firstSample, samples, {target->width(), rows}, firstRow,
                                                  buffers.capacity());
        const Wave* unfinished = nullptr; // the wave whose sums the next submission records first
        std::uint32_t& learned = learnedWaveSegments.try_emplace(waveKind, kFirstWaveSegments).first->second;
        for (const Wave& wave : waves)
        {
            std::uint32_t last = std::min(depth, learned);
            submit([&](WavefrontPipeline::Recorder& r) {
                if (unfinished)
                    r.finish(*unfinished);
                r.start(wave);
                r.segments(wave, 0, last);
            });
            unfinished = &wave;
            while (last < depth && buffers.readCounters().extendRays.x > 0)
            {
                const std::uint32_t next = std::min(depth, last + kWaveSegmentChunk);
                submit([&](WavefrontPipeline::Recorder& r) { r.segments(wave, last, next); });
                last = next;
            }
            learned = std::max(buffers.readCounters().segments, 1u);
        }
        if (unfinished)
            submit([&](WavefrontPipeline::Recorder& r) { r.finish(*unfinished); });
        return timed ? seconds : -1.0;
    }

    /// Records `record` between timestamps 2 and 3, runs it and adds its device seconds to frameStages[stage].
    void timedSubmit(const char* stage, const std::function<void(VkCommandBuffer)>& record)
    {
        const bool timed = device().properties().timestampValidBits > 0;
        vk::submitAndWait(device(), context.commandPool(), [&](VkCommandBuffer cmd) {
            if (timed)
            {
                vkCmdResetQueryPool(cmd, timestamps.Handle(), 2, 2);
                vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, timestamps.Handle(), 2);
            }
            record(cmd);
            if (timed)
                vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps.Handle(), 3);
        });
        if (timed)
            frameStages[stage] += timestamps.secondsBetween(2, device().properties().limits.timestampPeriod);
    }

    /// Records `passes` of restir-di's sample `sampleIndex` over `rows` rows from position `row` on (row order
    /// `interleave`) in one submission, waited for; `snapshot` first copies the accumulation image to the readback
    /// buffer. Adds each pass's device seconds to frameStages (timestamps 4 .. 4 + passes) and returns the device
    /// seconds (negative without timestamps) and the host seconds.
    std::pair<double, double> submitRestir(std::span<const RestirPass> passes, std::uint32_t sampleIndex,
                                           std::uint32_t row, std::uint32_t rows, std::uint32_t interleave,
                                           bool snapshot)
    {
        const RestirPipeline& pipeline = tracer.restir();
        const PipelineScene& scene = tracer.gpuScene().pipelineScene();
        const bool timed = device().properties().timestampValidBits > 0;
        const auto count = static_cast<std::uint32_t>(passes.size());
        const auto start = std::chrono::steady_clock::now();
        vk::submitAndWait(device(), context.commandPool(), [&](VkCommandBuffer cmd) {
            if (snapshot)
                target->recordReadback(cmd);
            if (timed)
            {
                vkCmdResetQueryPool(cmd, timestamps.Handle(), kRestirQueries, count + 1);
                vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, timestamps.Handle(), kRestirQueries);
            }
            for (std::uint32_t k = 0; k < count; ++k)
            {
                pipeline.recordPass(cmd, {&descriptors.set, 1}, uniforms, scene, passes[k], sampleIndex,
                                    {target->width(), rows}, row, interleave, restirHistory);
                if (timed)
                    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps.Handle(),
                                        kRestirQueries + k + 1);
            }
            vk::memoryBarrier(cmd, VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR, VK_ACCESS_SHADER_WRITE_BIT,
                              VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT); // the NaN/Inf counters
        });
        const double hostSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!timed)
            return {-1.0, hostSeconds};
        const double secondsPerTick = double(device().properties().limits.timestampPeriod) * 1e-9;
        const std::vector<std::uint64_t> ticks = timestamps.ticks(kRestirQueries, count + 1);
        const auto between = [&](std::uint32_t a, std::uint32_t b) {
            return ticks[b] >= ticks[a] ? double(ticks[b] - ticks[a]) * secondsPerTick : 0.0;
        };
        for (std::uint32_t k = 0; k < count; ++k)
            frameStages[passes[k] == RestirPass::Candidates ? "restir_candidates_gpu"
                        : passes[k] == RestirPass::Spatial  ? "restir_spatial_gpu"
                                                            : "restir_shade_gpu"] += between(k, k + 1);
        const double seconds = between(0, count);
        frameStages["trace_gpu"] += seconds;
        return {seconds, hostSeconds};
    }

    /// restir-di's batch: per sample, an iteration of three passes over the image (RestirPipeline). Where a band
    /// would cover the whole image the three are one submission; else each pass runs in bands of rows, with
    /// cancellation polled between them. A batch cancelled after its first shading band is put back from the
    /// snapshot that band took, counters too; a cancelled iteration leaves no history (the next one starts without
    /// temporal reuse, as the CPU's does).
    BatchResult traceRestir(std::uint32_t firstSample, std::uint32_t count, RenderControl& control)
    {
        const std::uint32_t height = target->height();
        const std::uint32_t width = target->width();
        const shader::SampleCounters countersBefore = target->readCounters();
        double deviceSeconds = 0.0;
        bool deviceTimed = true;
        bool touched = false; // the accumulation image has changed since the batch began
        const auto cancelled = [&] {
            if (!control.cancelRequested())
                return false;
            restirHistory = false;
            if (touched)
            {
                restore();
                target->writeCounters(countersBefore);
            }
            return true;
        };
        const auto add = [&](std::pair<double, double> seconds) {
            deviceTimed = deviceTimed && seconds.first >= 0.0;
            deviceSeconds += seconds.first;
            return seconds.second;
        };
        for (std::uint32_t s = 0; s < count; ++s)
        {
            const std::uint32_t sampleIndex = firstSample + s;
            const std::uint32_t wholeRows =
                fixedBandRows > 0 ? std::min(fixedBandRows, height) : bands.nextRows(1, height);
            if (wholeRows >= height)
            {
                if (cancelled())
                    return {.complete = false};
                const bool snapshot = !touched && s + 1 < count;
                const double host = add(submitRestir(kRestirPasses, sampleIndex, 0, height, 1, snapshot));
                touched = true;
                control.advance(std::uint64_t(width) * height);
                bands.record(height, 1, host);
                restirHistory = true;
                continue;
            }
            for (const RestirPass pass : kRestirPasses)
            {
                std::uint32_t interleave = 1;
                for (std::uint32_t row = 0; row < height;)
                {
                    if (cancelled())
                        return {.complete = false};
                    const std::uint32_t rows = fixedBandRows > 0 ? std::min(fixedBandRows, height - row)
                                                                 : bands.nextRows(1, height - row);
                    if (row == 0)
                        interleave = BandPlan::interleaveFor(rows, height);
                    // Only a batch that may still be cancelled once this band has run needs the image as it was.
                    const bool snapshot =
                        !touched && pass == RestirPass::Shade && row == 0 && (rows < height || s + 1 < count);
                    const double host = add(submitRestir({&pass, 1}, sampleIndex, row, rows, interleave, snapshot));
                    if (pass == RestirPass::Shade)
                    {
                        touched = true;
                        control.advance(std::uint64_t(width) * rows);
                    }
                    row += rows;
                    bands.record(rows, 1, host);
                }
            }
            restirHistory = true;
        }
        return {.complete = true, .deviceSeconds = deviceTimed ? deviceSeconds : -1.0};
    }

    void clear()
    {
        timedSubmit("clear_gpu", [&](VkCommandBuffer cmd) {
            target->recordClear(cmd);
            if (cost)
                cost->recordClear(cmd);
        });
        costSamples = 0;
    }

    void readback()
    {
        const HostStageTimer hostTime(frameStages["readback_host"]);
        timedSubmit("readback_gpu", [&](VkCommandBuffer cmd) { target->recordReadback(cmd); });
    }

    void restore()
    {
        vk::submitAndWait(device(), context.commandPool(), [&](VkCommandBuffer cmd) { target->recordRestore(cmd); });
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

const SceneTracer& GpuEngine::tracer() const { return m_impl->tracer; }

const std::filesystem::path& GpuEngine::shaderDir() const { return m_impl->tracer.shaderDir(); }

void GpuEngine::setBandRows(std::uint32_t rows) { m_impl->fixedBandRows = rows; }

void GpuEngine::setSpecialize(Specialize specialize) { m_impl->tracer.setSpecialize(specialize); }

void GpuEngine::setCountRays(bool countRays) { m_impl->countRays = countRays; }

void GpuEngine::setIntegrator(GpuIntegrator integrator, std::uint32_t waveCapacity)
{
    m_impl->descriptors = {}; // they name the old wave buffers
    m_impl->spareDescriptors = {};
    m_impl->learnedWaveSegments.clear(); // what a wave of another size needed
    m_impl->tracer.setIntegrator(integrator, waveCapacity);
}

const AccelerationStructureBuilds& GpuEngine::accelerationStructureBuilds() const
{
    return m_impl->tracer.accelerationStructureBuilds();
}

const Scene* GpuEngine::scene() const { return m_impl->tracer.scene(); }

double GpuEngine::buildSeconds() const { return m_impl->tracer.buildSeconds(); }

std::uint64_t GpuEngine::pathsPerBatch() const { return m_impl->pathsPerBatch; }

std::uint64_t GpuEngine::concurrentPaths() const
{
    return m_impl->device().properties().type == vk::DeviceType::Cpu ? std::uint64_t(4096) : std::uint64_t(1) << 18;
}

std::uint64_t GpuEngine::busyPixels(const RenderSettings& settings) const
{
    const Impl& e = *m_impl;
    if (!e.tracer.scene() || settings.estimator == Estimator::RestirDi || e.recordCost)
        return concurrentPaths();
    const auto width = static_cast<std::uint32_t>(settings.width);
    const auto height = static_cast<std::uint32_t>(settings.height());
    const std::uint64_t spp = static_cast<std::uint64_t>(std::max(settings.trueSpp(), 1));
    const shader::RenderUniforms uniforms =
        e.tracer.uniforms(frameCamera(*e.tracer.scene()), settings, {width, height});
    if (e.tracer.integratorFor(uniforms, representedPaths(std::uint64_t(width) * height * spp)) !=
        GpuIntegrator::Wavefront)
        return concurrentPaths();
    return (concurrentPaths() + spp - 1) / spp;
}

double GpuEngine::setScene(const Scene& scene)
{
    m_impl->descriptors = {};
    m_impl->spareDescriptors = {};
    m_impl->learnedWaveSegments.clear();
    return m_impl->tracer.setScene(scene);
}

struct GpuEngine::FrameSetup
{
    shader::RenderUniforms uniforms;
    GpuIntegrator integrator;
};

GpuEngine::FrameSetup GpuEngine::frameOf(const RenderSettings& settings, std::uint32_t blocks) const
{
    const Impl& e = *m_impl;
    const auto width = static_cast<std::uint32_t>(settings.width);
    const auto height = static_cast<std::uint32_t>(settings.height());
    shader::RenderUniforms u = e.tracer.uniforms(frameCamera(*e.tracer.scene()), settings, {width, height});
    u.countRays = e.countRays ? 1u : 0u;
    u.seedBlock = blocks > 1 ? seedBlock() : 0u; // one block: the plain frame, whatever is traced
    // restir-di runs its own passes (RestirPipeline), whatever the integrator setting; the timed ray generation
    // is a megakernel's.
    const GpuIntegrator integrator =
        settings.estimator == Estimator::RestirDi || e.recordCost
            ? GpuIntegrator::Megakernel
            : e.tracer.integratorFor(u, representedPaths(std::uint64_t(width) * height * settings.trueSpp() / blocks));
    return {u, integrator};
}

std::size_t GpuEngine::concurrentCompiles() const
{
    if (m_impl->device().properties().type == vk::DeviceType::Cpu)
        return 1; // the pilot's bound on the preparation then checks before each candidate's costly first launch
    return std::max(std::thread::hardware_concurrency(), 1u);
}

void GpuEngine::compileAhead(std::span<const RenderSettings> frames)
{
    const Impl& e = *m_impl;
    if (!e.tracer.scene())
        throw UsageError("GpuEngine::compileAhead called before setScene");
    if (e.recordCost) // the cost pipeline is compiled by its frame
        return;
    std::vector<std::pair<shader::RenderUniforms, GpuIntegrator>> renders;
    for (const RenderSettings& settings : frames)
    {
        const FrameSetup frame = frameOf(settings, seedBlocksOf(settings, false));
        renders.emplace_back(frame.uniforms, frame.integrator);
    }
    e.tracer.compileTogether(renders);
}

void GpuEngine::beginFrame(const RenderSettings& settings)
{
    const auto frameStart = std::chrono::steady_clock::now();
    Impl& e = *m_impl;
    if (!e.tracer.scene())
        throw UsageError("GpuEngine::beginFrame called before setScene");
    const auto width = static_cast<std::uint32_t>(settings.width);
    const auto height = static_cast<std::uint32_t>(settings.height());
    const std::uint32_t blocks = seedBlocksOf(settings, e.recordCost);
    if (const auto problem = checkTargetLimits(width, height * blocks, targetLimits(e.device())))
        throw DeviceError(*problem);
    const bool restirDi = settings.estimator == Estimator::RestirDi;
    if (restirDi)
        if (const auto problem = RestirBuffers::tooLargeFor(e.device(), std::uint64_t(width) * height))
            throw DeviceError(*problem);
    if (e.recordCost)
        if (const std::string why = costUnavailable(settings); !why.empty())
            throw UsageError(why);
    e.prepareTarget(width, height, blocks, restirDi);
    e.restirHistory = false;
    const FrameSetup frame = frameOf(settings, blocks);
    e.uniforms = frame.uniforms;
    e.frameBlocks = blocks;
    e.frameStages.clear();
    const auto compileStart = std::chrono::steady_clock::now();
    if (!e.recordCost)
        e.cost.reset();
    else if (!e.cost || e.cost->width() != width || e.cost->height() != height)
    {
        e.cost.reset();
        e.cost = std::make_unique<CostTarget>(e.device(), e.tracer.shaderDir(), e.tracer.pipeline().specializes(),
                                              width, height);
    }
    e.integrator = frame.integrator;
    // Out of the render's time.
    const bool compiled = e.cost ? e.cost->pipeline().prepare(e.uniforms, e.tracer.gpuScene().pipelineScene())
                                 : e.tracer.prepare(e.uniforms, e.integrator);
    e.target->reset(e.uniforms);
    e.clear();
    e.waveKind = {settings.depth, settings.estimator, settings.russianRoulette};
    if (compiled)
    {
        // The render plans its first wave as with a cached pipeline, not by the warm-up row's paths.
        const auto learnedBefore = e.learnedWaveSegments;
        // A driver may finish a new pipeline's compilation at its first launch (lavapipe: a 16-px render took
        // 1.6 s at first use against 0.009 s cached; restir-di's three passes 7.6 s at 96 px in the CPU window):
        // one row of one sample keeps that in the compilation's time too. Its sums, counters and reservoirs are
        // cleared or forgotten below; its stage times are dropped.
        if (restirDi)
            e.submitRestir(kRestirPasses, 0, 0, 1, 1, false);
        else
            e.dispatch(0, 1, 0, 1, 1, false);
        e.frameStages.clear();
        e.target->reset(e.uniforms);
        e.clear();
        e.restirHistory = false;
        e.learnedWaveSegments = learnedBefore;
    }
    if (compiled) // a frame whose pipelines were all compiled before has no compilation to tell
        e.frameStages["pipeline_host"] =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - compileStart).count();
    // The first band: a sixteenth of the engine's paths per batch (a CPU device's 64 K are a fraction of a second;
    // a GPU's 268 M, 16 M paths, are 75 ms of an H200's cornell-box-lights). Before a frame of a few samples could
    // reach it, a frame at one sample of 16 M pixels did: the unmeasured first submission's bound is the same.
    const std::uint64_t firstBandWork = e.pathsPerBatch / (std::uint64_t(shader::kBandInterleave) * width);
    e.bands = BandPlan(height, std::max<std::uint64_t>(firstBandWork, 1));
    e.frameStages["setup_host"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - frameStart).count();
}

BatchResult GpuEngine::traceSamples(std::uint32_t firstSample, std::uint32_t count, RenderControl& control)
{
    Impl& e = *m_impl;
    if (!e.target || e.descriptors.set == VK_NULL_HANDLE)
        throw UsageError("GpuEngine::traceSamples called before beginFrame");
    const HostStageTimer hostTime(e.frameStages["trace_host"]);
    if (e.restir)
        return e.traceRestir(firstSample, count, control);
    // One submit per band of rows, each about kBatchTargetSeconds: the render driver sizes batches by time
    // but no smaller than one sample per pixel, which on lavapipe is seconds for a 200x200 image of a heavy
    // scene. Cancellation is polled between bands; a batch cancelled part way is put back from the snapshot
    // its first band took (the readback buffer), counters too, as the RenderEngine contract asks.
    const std::uint32_t height = e.target->height();
    const std::uint32_t width = e.target->width();
    const shader::SampleCounters countersBefore = e.target->readCounters();
    double deviceSeconds = 0.0;
    bool deviceTimed = true;
    std::uint32_t interleave = 1; // the batch's row order, chosen at its first band
    for (std::uint32_t row = 0; row < height;)
    {
        if (control.cancelRequested())
        {
            if (row > 0)
            {
                e.restore();
                e.target->writeCounters(countersBefore);
            }
            return {.complete = false};
        }
        const std::uint32_t rows = e.fixedBandRows > 0 ? std::min(e.fixedBandRows, height - row)
                                                       : e.bands.nextRows(count, height - row);
        if (row == 0)
            interleave = BandPlan::interleaveFor(rows, height);
        const bool snapshot = row == 0 && rows < height; // only a batch of several bands can be cut
        const auto start = std::chrono::steady_clock::now();
        const double seconds = e.dispatch(firstSample, count, row, rows, interleave, snapshot);
        const double hostSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        deviceTimed = deviceTimed && seconds >= 0.0;
        deviceSeconds += seconds;
        if (seconds >= 0.0)
            e.frameStages["trace_gpu"] += seconds;
        control.advance(std::uint64_t(width) * rows * count);
        row += rows;
        e.bands.record(rows, count, hostSeconds);
    }
    e.costSamples += count;
    return {.complete = true, .deviceSeconds = deviceTimed ? deviceSeconds : -1.0};
}

Image GpuEngine::estimate(std::uint32_t samples)
{
    if (!m_impl->target || m_impl->descriptors.set == VK_NULL_HANDLE)
        throw UsageError("GpuEngine::estimate called before beginFrame");
    m_impl->readback();
    const HostStageTimer hostTime(m_impl->frameStages["resolve_host"]);
    return m_impl->target->readEstimate(samples, m_impl->uniforms.seedBlock, m_impl->frameBlocks);
}

std::vector<double> GpuEngine::radianceSums()
{
    if (!m_impl->target || m_impl->descriptors.set == VK_NULL_HANDLE)
        throw UsageError("GpuEngine::radianceSums called before beginFrame");
    m_impl->readback();
    return m_impl->target->readSums(m_impl->frameBlocks);
}

std::string GpuEngine::frameConfiguration() const
{
    if (!m_impl->target || !m_impl->tracer.scene())
        return {};
    const SceneTracer& t = m_impl->tracer;
    return "pipeline " + t.pipeline().specializationFor(m_impl->uniforms, t.gpuScene().pipelineScene()).describe() +
           ", integrator " + (m_impl->restir ? std::string("restir-di passes") : toString(m_impl->integrator)) +
           (m_impl->cost ? ", each sample timed (--heatmap)" : "");
}

std::map<std::string, double> GpuEngine::frameStageSeconds() const { return m_impl->frameStages; }

std::map<std::string, double> GpuEngine::stageSeconds() const
{
    std::map<std::string, double> stages = m_impl->frameStages;
    if (!m_impl->tracer.scene())
        return stages;
    const GpuScene& scene = m_impl->tracer.gpuScene();
    stages["upload_host"] = scene.uploadSeconds();
    if (scene.buildTimes().blasGpuSeconds >= 0.0)
        stages["blas_build_gpu"] = scene.buildTimes().blasGpuSeconds;
    if (scene.buildTimes().tlasGpuSeconds >= 0.0)
        stages["tlas_build_gpu"] = scene.buildTimes().tlasGpuSeconds;
    return stages;
}

std::map<std::string, std::uint64_t> GpuEngine::frameBytesPerPixel() const
{
    return m_impl->restir ? RestirBuffers::bytesPerPixel() : std::map<std::string, std::uint64_t>{};
}

std::string GpuEngine::costUnavailable(const RenderSettings& settings) const
{
    if (settings.estimator == Estimator::RestirDi)
        return "restir-di's passes are not timed per pixel";
    if (!m_impl->device().shaderClock())
        return fmt::format("{} has no shader clock (VK_KHR_shader_clock with shaderSubgroupClock)", deviceName());
    return {};
}

void GpuEngine::setCostRecording(bool on) { m_impl->recordCost = on; }

CostMap GpuEngine::costMap()
{
    Impl& e = *m_impl;
    if (!e.cost || e.costSamples == 0)
        return {};
    CostMap map{.width = static_cast<int>(e.cost->width()),
                .height = static_cast<int>(e.cost->height()),
                .perSample = e.cost->readTicks(e.device(), e.context.commandPool()),
                .unit = "shader-clock ticks per sample"};
    for (float& ticks : map.perSample)
        ticks = static_cast<float>(double(ticks) / double(e.costSamples));
    return map;
}

SampleTally GpuEngine::tally() const
{
    if (!m_impl->target)
        return {};
    Impl& e = *m_impl;
    const shader::SampleCounters counters = e.target->readCounters();
    SampleTally t{.nanSamples = counters.nanSamples, .infSamples = counters.infSamples, .threadsUsed = 1};
    if (e.uniforms.countRays != 0u)
    {
        vk::submitAndWait(e.device(), e.context.commandPool(),
                          [&](VkCommandBuffer cmd) { e.target->recordTraceCountersReadback(cmd); });
        std::tie(t.rays, t.lightSamples) = e.target->readTraceCounts();
        t.raysCounted = true;
    }
    return t;
}
} // namespace rt::gpu
