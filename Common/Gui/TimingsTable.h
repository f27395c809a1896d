// Every render that ran to the end in this run of the app, grouped by the work it did (scene, image size,
// samples, depth, estimator, sampling, light mode) with one column per engine, so single core, multi core
// and the GPU sit side by side for the same work. Cancelled renders are not timings and never enter it. A
// timing taken while the window redrew for a person's input (WindowRedraws.h) is marked: that drawing competed
// with the render for the CPU. Each row's error is measured against a reference of its work
// (ReferenceTask.h), as --compare measures it: relMSE (Image/Metrics.h, the reference's own noise included) and
// the efficiency 1 / (relMSE x render time).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "Gui/ReferenceTask.h"
#include "Gui/WindowRedraws.h"
#include "Image/Image.h"
#include "Render/RenderRequest.h"
#include "Render/RenderStats.h"
#include "Render/SettingsTable.h"

namespace rt::gui
{
/// A render's request but its seed (loop rendering's iterations differ by seed only) and with its true spp
/// (stratified sampling rounds down): the same key is the same work.
struct TimingKey
{
    SceneRef scene;
    RenderSettings settings;
    std::optional<CameraDesc> camera; // a moved camera's view is other work

    static TimingKey of(const RenderRequest& request);
    bool operator==(const TimingKey&) const = default;
};

/// A moved camera as JSON: {look_from, look_at, vup, vfov}; null for the scene's own.
nlohmann::json cameraJson(const std::optional<CameraDesc>& camera);

/// The settings a timings row shows in its own column, in the settings table's order: every one but the size
/// (shown as WxH) and the seed (not part of the key).
std::vector<const Setting*> timingColumns();

struct EngineTiming
{
    double lastSeconds = 0.0; // tracing time of the latest render: no setup (RenderStats::renderSeconds)
    double bestSeconds = 0.0; // and of the fastest
    double mpathsPerSecond = 0.0; // of the latest
    int renders = 0;
    std::string device;
    WindowRedraws redraws; // during the latest render
    // The latest render's setup, apart from its tracing: the scene's acceleration structures (with the GPU's
    // uploads), and the pipelines it compiled (the GPU engine's pipeline_host; none when all were compiled before).
    double buildSeconds = 0.0;
    std::optional<double> compileSeconds;
    // The latest render's relMSE against the row's reference (its own relMSE included); until the reference
    // arrives, its image waits here to be measured.
    std::optional<double> relMse;
    std::shared_ptr<const Image> unmeasured;

    /// 1 / (relMSE x render time), in 1/s: --compare's efficiency; 0 without a relMSE.
    double efficiency() const { return relMse && *relMse > 0.0 && lastSeconds > 0.0 ? 1.0 / (*relMse * lastSeconds) : 0.0; }
};

/// A row's reference: asked for when its first render finished (ReferenceTask.h), then ready or failed.
struct RowReference
{
    enum class State
    {
        Waiting, // queued or rendering on the render thread
        Ready,
        Failed
    };
    State state = State::Waiting;
    ReferenceTask task;
    std::shared_ptr<const Image> image;
    double ownRelMse = 0.0;
    bool fromCache = false;
    double seconds = 0.0; // its halves' tracing time; 0 from the cache
    std::string error;
};

struct TimingRow
{
    TimingKey key;
    std::array<std::optional<EngineTiming>, 3> engines; // by EngineKind
    std::optional<RowReference> reference; // none asked for yet
};

class TimingsTable
{
public:
    /// Adds a finished render, its image (measured against the row's reference, now or once it arrives; null:
    /// no relMSE) and the frames the window drew during it.
    void record(const RenderStats& stats, const WindowRedraws& redraws = {}, std::shared_ptr<const Image> image = {});
    /// The reference the latest record()'s row needs, once: the render's own request at
    /// kDefaultReferenceFactor x its spp, rendered by `engine` when given (the GPU window renders every reference on
    /// its device), else by the engine of the row with the most Mpaths/s (multi for single core, whose work it
    /// does faster); nullopt when the row has asked before.
    std::optional<ReferenceTask> referenceWanted(std::optional<EngineKind> engine = std::nullopt);
    /// Measures the rows waiting for `reference` against it (a reference no row waits for is ignored).
    void attach(const FinishedReference& reference);
    void clear()
    {
        m_rows.clear();
        ++m_revision;
    }
    /// In the order their first render finished.
    const std::vector<TimingRow>& rows() const { return m_rows; }
    /// The row the latest record() went to (rows().size() when empty), and a count that changes with every
    /// record() and clear(): the window scrolls to that row when the count moved.
    std::size_t latestRow() const { return m_latest; }
    std::uint64_t revision() const { return m_revision; }
    /// One object per (row, engine): scene, count, mesh, width, height, spp, depth, sampling, estimator,
    /// russian_roulette, unidirectional_light, engine, seconds, best_seconds, mpaths_per_second, renders, device,
    /// window_redraws, window_redraws_on_input, camera (cameraJson), build_seconds, compiled, compile_seconds (null when not compiled)
    /// (of the latest render), rel_mse and efficiency (null until measured), and the row's reference: state
    /// (waiting, ready, failed), spp, engine, own_rel_mse, from_cache, seconds, error.
    nlohmann::json toJson() const;

private:
    std::vector<TimingRow> m_rows;
    std::size_t m_latest = 0;
    RenderRequest m_latestRequest; // of the latest record(), with its seed
    std::uint64_t m_revision = 0;
};
} // namespace rt::gui
