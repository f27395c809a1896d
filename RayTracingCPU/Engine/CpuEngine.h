// The CPU engine: the Common scene compiled to a BVH (CpuScene), its samples traced row by row with
// std::execution::seq ("single core") or std::execution::par ("multi core": libstdc++ runs it on TBB).
// Every sample's random stream depends only on (seed, pixel, sample index) and each pixel adds its samples in
// sample order, so both policies, and any cut of the samples into batches, give the same image bit for bit.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "Integrator/PathIntegrator.h"
#include "Integrator/PathVariants.h"
#include "Integrator/RestirPasses.h"
#include "Render/RenderEngine.h"
#include "Scene/Camera.h"
#include "Engine/CpuScene.h"

namespace rt::cpu
{
/// Camera paths per batch: 2^20, half a second on one core of the CI kind for the books' Cornell boxes. Each
/// batch ends with the parallel loop's tail (about 3 ms on 2 cores, docs/notebook/PERFORMANCE.md): fewer, larger
/// batches cost less; progress does not wait for a batch (it works per row), nor does cancellation (polled
/// before every sample). The render driver also keeps a batch near kBatchTargetSeconds (Render/BatchPlan.h).
inline constexpr std::uint64_t kPathsPerBatch = std::uint64_t(1) << 20;

class CpuEngine final : public RenderEngine
{
public:
    /// `kind` is EngineKind::Single or EngineKind::Multi. `specialize`: run the path loop compiled for the
    /// scene's features and the render's estimator (Integrator/PathVariants.h); false: the general loop.
    explicit CpuEngine(EngineKind kind, bool specialize = true);

    EngineKind kind() const override { return m_kind; }
    std::string deviceName() const override;
    double setScene(const Scene& scene) override;
    const Scene* scene() const override { return m_scene ? &m_scene->source() : nullptr; }
    double buildSeconds() const override { return m_buildSeconds; }

    std::uint64_t pathsPerBatch() const override { return kPathsPerBatch; }
    /// A path per lane of every thread.
    std::uint64_t concurrentPaths() const override;
    void beginFrame(const RenderSettings& settings) override;
    /// Polls cancellation before each camera sample and advances `control` after each row; a cancelled batch
    /// puts back the rows it had started.
    BatchResult traceSamples(std::uint32_t firstSample, std::uint32_t count, RenderControl& control) override;
    Image estimate(std::uint32_t samples) override;
    std::vector<double> radianceSums() override;
    SampleTally tally() const override;
    /// The path loop the current frame runs ("path loop: general" or what it is specialised for, and the
    /// scene's features); empty before beginFrame. --stats' frame_configuration.
    std::string frameConfiguration() const override;
    /// restir-di's reservoirs (two per pixel, 64 bytes) and surfaces (64 bytes); empty for other estimators.
    std::map<std::string, std::uint64_t> frameBytesPerPixel() const override;
    /// Empty but for restir-di, whose passes are not timed per pixel.
    std::string costUnavailable(const RenderSettings& settings) const override;
    /// With it on, each pixel's samples are traced in chunks of their own (lanes filled from one pixel's samples:
    /// slower with few samples per batch) and each chunk timed on the host's steady clock, camera rays included.
    void setCostRecording(bool on) override { m_recordCost = on; }
    /// Microseconds per sample: the time of each pixel's chunks over the samples of the batches that completed.
    CostMap costMap() override;
    /// The path loop alone: "general" or e.g. "nee-mis, no media, solid colours only".
    std::string pathVariant() const { return m_frame ? m_frame->variant.describe() : std::string(); }

private:
    /// Per-row tallies, written by exactly one task at a time: no atomics on the hot path, summed by tally().
    struct RowTally
    {
        TraceCounts counts;
        std::uint64_t nan = 0;
        std::uint64_t inf = 0;
        std::size_t thread = 0; // hash of the thread that traced the row last
    };

    enum class RowState : std::uint8_t
    {
        Skipped, // the batch was cancelled before the row started
        Traced,
        Abandoned // cancelled part way through the row: put back like a traced row of a cancelled batch
    };

    struct Frame
    {
        RenderSettings settings;
        shader::RenderUniforms uniforms; // what the shared shading reads (Render/RenderUniforms.h)
        PathVariant variant;
        // Radiance sum of every sample traced so far, row-major, in double: a float sum of 2^20 samples of 0.1
        // drifts by 1 % (each addition rounds to the ulp of the sum; tests/Cpu/StressTest.cpp's long run).
        // Seed blocks (RenderEngine::setSeedBlock) one below the other, width x height each.
        std::vector<dvec3> sum;
        // Each row of `sum` as the current batch found it, copied by the row before it traces: a cancelled batch
        // puts it back. Left uninitialised: zero-filling it took a 600x600 render's start 10-20 ms on one core.
        std::unique_ptr<dvec3[]> before;
        int width = 0;
        int height = 0;
        std::uint32_t blocks = 1; // seed blocks
        std::vector<RowTally> rows;
        std::vector<RowTally> rowsBefore;
        std::vector<RowState> rowStates;
        std::vector<int> rowIndices; // 0 .. height - 1, the range the execution policy walks
        std::optional<RestirBuffers> restir; // restir-di's reservoirs, kept across batches
        // With cost recording: each pixel's seconds of tracing (and the row's as the batch found them, like
        // `before`), and the samples per pixel of the batches that completed. Empty otherwise.
        std::vector<double> costSeconds;
        std::vector<double> costBefore;
        std::uint64_t costSamples = 0;
    };

    /// traceSamples for restir-di: iteration by iteration, each two passes over the image
    /// (Integrator/RestirPasses.h); a cancelled batch is put back whole and the next starts without history.
    BatchResult traceRestir(std::uint32_t firstSample, std::uint32_t count, RenderControl& control);

    EngineKind m_kind;
    bool m_specialize;
    bool m_recordCost = false;
    std::unique_ptr<CpuScene> m_scene;
    SceneFeatures m_features;
    double m_buildSeconds = 0.0;
    std::optional<Frame> m_frame;
};
} // namespace rt::cpu
