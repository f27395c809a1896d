#include "Engine/CpuEngine.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <execution>
#include <fstream>
#include <functional>
#include <numeric>
#include <thread>
#include <unordered_set>

#if defined(__linux__)
#include <sched.h>
#endif

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "Error.h"
#include "Geometry/Lanes.h"
#include "Render/RenderUniforms.h"

namespace rt::cpu
{
namespace
{
std::string cpuModel()
{
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0)
            if (const auto colon = line.find(':'); colon != std::string::npos)
                return line.substr(colon + 2);
    return "CPU";
}

/// The threads the multi engine's parallel loops run on: the cores this process may use (taskset, cgroups'
/// cpusets), which TBB's default arena follows, rather than the machine's.
unsigned usableThreads()
{
#if defined(__linux__)
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof set, &set) == 0)
        return static_cast<unsigned>(std::max(1, CPU_COUNT(&set)));
#endif
    return std::max(1u, std::thread::hardware_concurrency());
}

} // namespace

CpuEngine::CpuEngine(EngineKind kind, bool specialize) : m_kind(kind), m_specialize(specialize)
{
    if (kind != EngineKind::Single && kind != EngineKind::Multi)
        throw UsageError("the CPU engine runs single or multi, not gpu");
}

std::string CpuEngine::deviceName() const
{
    const unsigned threads = m_kind == EngineKind::Single ? 1u : usableThreads();
    return fmt::format("{} ({} thread{})", cpuModel(), threads, threads == 1 ? "" : "s");
}

std::uint64_t CpuEngine::concurrentPaths() const
{
    return std::uint64_t(m_kind == EngineKind::Single ? 1u : usableThreads()) * std::uint64_t(kLanes);
}

double CpuEngine::setScene(const Scene& scene)
{
    const auto start = std::chrono::steady_clock::now();
    m_frame.reset();
    m_scene.reset();
    m_scene = std::make_unique<CpuScene>(scene);
    m_features = featuresOf(scene);
    m_buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return m_buildSeconds;
}

void CpuEngine::beginFrame(const RenderSettings& settings)
{
    if (!m_scene)
        throw UsageError("CpuEngine::beginFrame called before setScene");
    const int width = settings.width;
    const int height = settings.height();
    const std::uint32_t blocks = seedBlocksOf(settings, m_recordCost);
    shader::RenderUniforms uniforms = makeUniforms(m_scene->source(), frameCamera(m_scene->source()), settings,
                                                   std::uint32_t(width), std::uint32_t(height));
    uniforms.seedBlock = blocks > 1 ? seedBlock() : 0u; // one block: the plain frame, whatever is traced
    const std::size_t values = std::size_t(width) * height * blocks;
    m_frame.emplace(Frame{.settings = settings,
                          .uniforms = uniforms,
                          .variant = choosePathVariant(m_features, settings.estimator, m_specialize, m_scene->tracesRayLanes()),
                          .sum = std::vector<dvec3>(values, dvec3(0.0)),
                          .before = std::make_unique_for_overwrite<dvec3[]>(values),
                          .width = width,
                          .height = height,
                          .blocks = blocks,
                          .rows = std::vector<RowTally>(height),
                          .rowsBefore = std::vector<RowTally>(height),
                          .rowStates = std::vector<RowState>(height),
                          .rowIndices = std::vector<int>(height)});
    std::iota(m_frame->rowIndices.begin(), m_frame->rowIndices.end(), 0);
    if (settings.estimator == Estimator::RestirDi)
        m_frame->restir.emplace(width, height);
    if (m_recordCost)
    {
        if (const std::string why = costUnavailable(settings); !why.empty())
            throw UsageError(why);
        m_frame->costSeconds.assign(std::size_t(width) * height, 0.0);
        m_frame->costBefore.assign(std::size_t(width) * height, 0.0);
    }
    spdlog::debug("CPU {}", frameConfiguration());
}

std::string CpuEngine::frameConfiguration() const
{
    if (!m_frame)
        return {};
    if (m_frame->restir)
        return fmt::format("restir-di passes ({} combination), general shading (scene: {})",
                           m_frame->settings.restirBiased ? "biased" : "unbiased", m_features.describe());
    return fmt::format("path loop: {} (scene: {})", m_frame->variant.describe(), m_features.describe());
}

std::map<std::string, std::uint64_t> CpuEngine::frameBytesPerPixel() const
{
    if (!m_frame || !m_frame->restir)
        return {};
    return {{"reservoirs", RestirBuffers::kReservoirBytesPerPixel}, {"surfaces", RestirBuffers::kSurfaceBytesPerPixel}};
}

BatchResult CpuEngine::traceSamples(std::uint32_t firstSample, std::uint32_t count, RenderControl& control)
{
    if (!m_frame)
        throw UsageError("CpuEngine::traceSamples called before beginFrame");
    if (m_frame->restir)
        return traceRestir(firstSample, count, control);
    Frame& f = *m_frame;
    const int width = f.width;
    // The batch's inputs as locals, read once rather than through the frame in the inner loop.
    const shader::RenderUniforms uniforms = f.uniforms;
    const TracePathsFn trace = f.variant.traceLanes ? f.variant.traceLanes : f.variant.trace;
    const CpuScene& scene = *m_scene;
    std::vector<dvec3>& sums = f.sum;
    std::vector<RowTally>& tallies = f.rows;
    // The camera's part of the shared shading (Shared/Shading/Camera.h) reads no feature a path loop is
    // specialised for: one instance serves every variant.
    CpuShading<PathCode{}> camera(scene, uniforms);
    const bool media = scene.hasMedia();
    const std::size_t blockValues = std::size_t(width) * std::size_t(f.height); // one seed block's sums
    const auto accumulate = [](dvec3& sum, const vec3& l, RowTally& t) {
        if (isFinite(l))
            sum += dvec3(l);
        else if (std::isnan(l.x) || std::isnan(l.y) || std::isnan(l.z))
            ++t.nan;
        else
            ++t.inf;
    };
    const auto row = [&](int y) {
        if (control.cancelRequested())
        {
            f.rowStates[y] = RowState::Skipped;
            return;
        }
        f.rowStates[y] = RowState::Traced;
        const std::size_t rowStart = std::size_t(y) * std::size_t(width);
        for (std::uint32_t b = 0; b < f.blocks; ++b)
            std::copy_n(sums.data() + b * blockValues + rowStart, width, f.before.get() + b * blockValues + rowStart);
        f.rowsBefore[y] = tallies[y];
        double* const cost = f.costSeconds.empty() ? nullptr : f.costSeconds.data() + rowStart;
        if (cost)
            std::copy_n(cost, width, f.costBefore.data() + rowStart);
        RowTally& t = tallies[y];
        t.thread = std::hash<std::thread::id>{}(std::this_thread::get_id());
        // The row's samples in (pixel, sample) order, in chunks of jobs: camera rays first, then the paths (one
        // after the other, or kLanes at a time); each pixel still adds its samples in sample order. Cancellation
        // is polled per chunk: one pixel of a huge-spp batch can hold seconds of paths (issue 13).
        constexpr std::uint32_t kChunk = 256;
        PathJob jobs[kChunk];
        vec3 radiance[kChunk];
        const std::uint64_t total = std::uint64_t(width) * count;
        std::uint32_t n = 0;
        for (std::uint64_t first = 0; first < total; first += n)
        {
            if (control.cancelRequested())
            {
                f.rowStates[y] = RowState::Abandoned;
                return;
            }
            n = static_cast<std::uint32_t>(std::min<std::uint64_t>(kChunk, total - first));
            if (cost) // one pixel's samples, timed alone
                n = static_cast<std::uint32_t>(std::min<std::uint64_t>(n, count - first % count));
            const auto start = cost ? std::chrono::steady_clock::now() : std::chrono::steady_clock::time_point{};
            for (std::uint32_t i = 0; i < n; ++i)
            {
                const std::uint64_t j = first + i;
                jobs[i] = cameraJob(camera, media, std::uint32_t(j / count), std::uint32_t(y), firstSample + std::uint32_t(j % count));
            }
            trace(scene, uniforms, std::span<const PathJob>(jobs, n), radiance, t.counts);
            if (cost)
                cost[first / count] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (f.blocks == 1)
                for (std::uint32_t i = 0; i < n; ++i)
                    accumulate(sums[rowStart + std::size_t((first + i) / count)], radiance[i], t);
            else
                for (std::uint32_t i = 0; i < n; ++i)
                {
                    const std::uint64_t j = first + i;
                    const std::size_t block = camera.seedBlockOf(firstSample + std::uint32_t(j % count));
                    accumulate(sums[block * blockValues + rowStart + std::size_t(j / count)], radiance[i], t);
                }
        }
        control.advance(std::uint64_t(width) * count);
    };
    if (m_kind == EngineKind::Single)
        std::for_each(std::execution::seq, f.rowIndices.begin(), f.rowIndices.end(), row);
    else
        std::for_each(std::execution::par, f.rowIndices.begin(), f.rowIndices.end(), row);
    if (std::find_if(f.rowStates.begin(), f.rowStates.end(),
                     [](RowState r) { return r != RowState::Traced; }) == f.rowStates.end())
    {
        f.costSamples += count;
        return {.complete = true}; // no clock of its own: the driver's host clock is the CPU's
    }
    for (int y = 0; y < f.height; ++y)
        if (f.rowStates[y] != RowState::Skipped) // traced, or abandoned part way: back to the batch's start
        {
            const std::size_t rowStart = std::size_t(y) * std::size_t(width);
            for (std::uint32_t b = 0; b < f.blocks; ++b)
                std::copy_n(f.before.get() + b * blockValues + rowStart, width, sums.data() + b * blockValues + rowStart);
            tallies[y] = f.rowsBefore[y];
            if (!f.costSeconds.empty())
                std::copy_n(f.costBefore.data() + rowStart, width, f.costSeconds.data() + rowStart);
        }
    return {.complete = false};
}

BatchResult CpuEngine::traceRestir(std::uint32_t firstSample, std::uint32_t count, RenderControl& control)
{
    Frame& f = *m_frame;
    RestirBuffers& buffers = *f.restir;
    const shader::RenderUniforms uniforms = f.uniforms;
    const CpuScene& scene = *m_scene;
    if (firstSample == 0)
        buffers.history = false;
    // The batch's start, put back if it is cancelled: its iterations change every pixel's reservoirs.
    std::copy(f.sum.begin(), f.sum.end(), f.before.get());
    f.rowsBefore = f.rows;
    bool cancelled = false;
    const auto forRows = [&](const auto& row) {
        if (m_kind == EngineKind::Single)
            std::for_each(std::execution::seq, f.rowIndices.begin(), f.rowIndices.end(), row);
        else
            std::for_each(std::execution::par, f.rowIndices.begin(), f.rowIndices.end(), row);
    };
    for (std::uint32_t s = firstSample; s < firstSample + count && !cancelled; ++s)
    {
        forRows([&](int y) {
            if (control.cancelRequested())
                return;
            RestirRowTally t;
            restirCandidatesRow(scene, uniforms, buffers, y, s, t);
            f.rows[y].counts += t.counts;
        });
        if (control.cancelRequested())
        {
            cancelled = true;
            break;
        }
        forRows([&](int y) {
            if (control.cancelRequested())
                return;
            RowTally& tally = f.rows[y];
            tally.thread = std::hash<std::thread::id>{}(std::this_thread::get_id());
            RestirRowTally t;
            std::vector<vec3> radiance(std::size_t(f.width));
            restirShadeRow(scene, uniforms, buffers, y, s, radiance.data(), t);
            tally.counts += t.counts;
            const std::size_t rowStart = std::size_t(y) * std::size_t(f.width);
            for (int x = 0; x < f.width; ++x)
            {
                const vec3& l = radiance[std::size_t(x)];
                if (isFinite(l))
                    f.sum[rowStart + std::size_t(x)] += dvec3(l);
                else if (std::isnan(l.x) || std::isnan(l.y) || std::isnan(l.z))
                    ++tally.nan;
                else
                    ++tally.inf;
            }
            control.advance(std::uint64_t(f.width));
        });
        if (control.cancelRequested())
            cancelled = true;
        else
            buffers.history = true;
    }
    if (!cancelled)
        return {.complete = true};
    std::copy_n(f.before.get(), f.sum.size(), f.sum.begin());
    f.rows = f.rowsBefore;
    buffers.history = false;
    return {.complete = false};
}

Image CpuEngine::estimate(std::uint32_t samples)
{
    if (!m_frame || samples == 0)
        throw UsageError("CpuEngine::estimate needs a frame with samples");
    const Frame& f = *m_frame;
    Image image(f.width, f.height * int(f.blocks));
    const std::size_t blockValues = std::size_t(f.width) * std::size_t(f.height);
    for (std::uint32_t b = 0; b < f.blocks; ++b)
    {
        const std::uint32_t inBlock = samplesInSeedBlock(samples, f.uniforms.seedBlock, b);
        for (std::size_t i = b * blockValues; i < (b + 1) * blockValues; ++i)
            image.pixels()[i] = inBlock == 0 ? vec3(0.0f) : vec3(f.sum[i] / double(inBlock));
    }
    return image;
}

std::vector<double> CpuEngine::radianceSums()
{
    if (!m_frame)
        throw UsageError("CpuEngine::radianceSums needs a frame");
    std::vector<double> sums;
    sums.reserve(3 * m_frame->sum.size());
    for (const dvec3& s : m_frame->sum)
        sums.insert(sums.end(), {s.x, s.y, s.z});
    return sums;
}

std::string CpuEngine::costUnavailable(const RenderSettings& settings) const
{
    return settings.estimator == Estimator::RestirDi
               ? "restir-di's passes are not timed per pixel"
               : std::string();
}

CostMap CpuEngine::costMap()
{
    if (!m_frame || m_frame->costSeconds.empty() || m_frame->costSamples == 0)
        return {};
    CostMap map{.width = m_frame->width, .height = m_frame->height, .unit = "microseconds per sample"};
    map.perSample.resize(m_frame->costSeconds.size());
    const double scale = 1e6 / double(m_frame->costSamples);
    for (std::size_t i = 0; i < map.perSample.size(); ++i)
        map.perSample[i] = static_cast<float>(m_frame->costSeconds[i] * scale);
    return map;
}

SampleTally CpuEngine::tally() const
{
    SampleTally total;
    if (!m_frame)
        return total;
    total.raysCounted = true; // always: a count per traced ray (and light sample) costs nothing measurable
    std::unordered_set<std::size_t> threads;
    for (const RowTally& t : m_frame->rows)
    {
        total.rays += t.counts.rays;
        total.lightSamples += t.counts.lightSamples;
        total.nanSamples += t.nan;
        total.infSamples += t.inf;
        if (t.thread)
            threads.insert(t.thread);
    }
    total.threadsUsed = static_cast<int>(threads.size());
    return total;
}
} // namespace rt::cpu
