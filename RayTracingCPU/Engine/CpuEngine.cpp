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

#include <spdlog/fmt/fmt.h>

#include "Error.h"
#include "Integrator/PathIntegrator.h"

namespace rt::cpu
{
namespace
{
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start)
{
    return std::chrono::duration<double>(Clock::now() - start).count();
}

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

/// Per-row tallies, written by exactly one task each: no atomics on the hot path, summed at the end.
struct RowTally
{
    std::uint64_t segments = 0;
    std::uint64_t nan = 0;
    std::uint64_t inf = 0;
    std::size_t thread = 0;
};

template <typename Policy>
void forEachRow(Policy&& policy, std::vector<int>& rows, const std::function<void(int)>& body)
{
    std::for_each(policy, rows.begin(), rows.end(), body);
}
} // namespace

CpuEngine::CpuEngine(EngineKind kind) : m_kind(kind)
{
    if (kind != EngineKind::Single && kind != EngineKind::Multi)
        throw UsageError("the CPU engine runs single or multi, not gpu");
}

std::string CpuEngine::deviceName() const
{
    const unsigned threads = m_kind == EngineKind::Single ? 1u : std::max(1u, std::thread::hardware_concurrency());
    return fmt::format("{} ({} thread{})", cpuModel(), threads, threads == 1 ? "" : "s");
}

double CpuEngine::setScene(const Scene& scene)
{
    const auto start = Clock::now();
    m_scene = std::make_unique<CpuScene>(scene);
    m_buildSeconds = secondsSince(start);
    return m_buildSeconds;
}

RenderResult CpuEngine::render(const RenderSettings& settings, RenderControl& control, const PreviewCallback& preview)
{
    if (!m_scene)
        throw UsageError("CpuEngine::render called before setScene");
    settings.validate();
    const auto wallStart = Clock::now();
    const Scene& scene = m_scene->source();
    const int width = settings.width;
    const int height = settings.height();
    const Camera camera(scene.camera, width, height);
    const PathOptions options{settings.depth, settings.estimator, settings.unidirectionalLight};

    const bool accumulate = settings.sampling == PixelSampling::Accumulate;
    const bool stratified = settings.sampling == PixelSampling::Stratified;
    const int trueSpp = settings.trueSpp();
    const int strata = stratified ? static_cast<int>(std::lround(std::sqrt(double(trueSpp)))) : 1;
    const float invStrata = 1.0f / float(strata);
    const int passes = accumulate ? trueSpp : 1;
    const int samplesPerPass = accumulate ? 1 : trueSpp;

    Image sum(width, height); // sum of the samples of every finished pass
    Image pass(width, height);
    std::vector<RowTally> tally(height);
    std::vector<int> rows(height);
    std::iota(rows.begin(), rows.end(), 0);
    control.begin(std::uint64_t(height) * passes);

    int passesDone = 0;
    const auto renderStart = Clock::now();
    for (int p = 0; p < passes && !control.cancelRequested(); ++p)
    {
        const int firstSample = p * samplesPerPass;
        const auto row = [&](int y) {
            if (control.cancelRequested())
                return;
            RowTally& t = tally[y];
            t.thread = std::hash<std::thread::id>{}(std::this_thread::get_id());
            for (int x = 0; x < width; ++x)
            {
                const auto pixelIndex = static_cast<std::uint32_t>(y * width + x);
                vec3 acc(0.0f);
                for (int s = firstSample; s < firstSample + samplesPerPass; ++s)
                {
                    Rng rng = Rng::forSample(settings.seed, pixelIndex, static_cast<std::uint32_t>(s));
                    const float jx = rng.nextFloat();
                    const float jy = rng.nextFloat();
                    float fx, fy;
                    if (stratified)
                    {
                        fx = float(x) + (float(s % strata) + jx) * invStrata; // stratum (s % n, s / n)
                        fy = float(y) + (float(s / strata) + jy) * invStrata;
                    }
                    else
                    {
                        fx = float(x) + jx;
                        fy = float(y) + jy;
                    }
                    vec2 lens(0.0f);
                    if (camera.thinLens)
                        lens = vec2(rng.nextFloat(), rng.nextFloat());
                    const float time = rng.nextFloat();
                    const vec3 l = tracePath(*m_scene, options, camera.generateRay(fx, fy, lens, time), rng, t.segments);
                    if (isFinite(l))
                        acc += l;
                    else if (std::isnan(l.x) || std::isnan(l.y) || std::isnan(l.z))
                        ++t.nan;
                    else
                        ++t.inf;
                }
                pass.at(x, y) = acc;
            }
            control.advance();
        };
        if (m_kind == EngineKind::Single)
            forEachRow(std::execution::seq, rows, row);
        else
            forEachRow(std::execution::par, rows, row);
        if (control.cancelRequested() && (accumulate || p + 1 < passes))
            break; // an unfinished pass would give rows different sample counts: drop it
        for (std::size_t i = 0; i < sum.pixelCount(); ++i)
            sum.data()[i] += pass.data()[i];
        ++passesDone;
        if (preview && accumulate && control.previewDue())
        {
            Image estimate(width, height);
            const float scale = 1.0f / float(passesDone * samplesPerPass);
            for (std::size_t i = 0; i < sum.pixelCount(); ++i)
                estimate.data()[i] = sum.data()[i] * scale;
            preview(estimate, passesDone * samplesPerPass);
        }
    }
    const double renderSeconds = secondsSince(renderStart);

    RenderResult result;
    const int samplesTaken = passesDone * samplesPerPass;
    result.image = std::move(sum);
    if (samplesTaken > 0)
        for (vec3& v : result.image.pixels())
            v /= float(samplesTaken);
    if (preview && !accumulate && control.previewDue())
        preview(result.image, samplesTaken);

    RenderStats& st = result.stats;
    st.scene = scene.id;
    st.engine = m_kind;
    st.device = deviceName();
    st.settings = settings;
    st.width = width;
    st.height = height;
    st.trueSpp = samplesTaken;
    st.buildSeconds = m_buildSeconds;
    st.renderSeconds = renderSeconds;
    st.paths = std::uint64_t(width) * height * samplesTaken;
    std::unordered_set<std::size_t> threads;
    for (const RowTally& t : tally)
    {
        st.segments += t.segments;
        st.nanSamples += t.nan;
        st.infSamples += t.inf;
        if (t.thread)
            threads.insert(t.thread);
    }
    st.threadsUsed = static_cast<int>(threads.size());
    st.cancelled = control.cancelRequested();
    st.wallSeconds = secondsSince(wallStart) + m_buildSeconds;
    return result;
}
} // namespace rt::cpu
