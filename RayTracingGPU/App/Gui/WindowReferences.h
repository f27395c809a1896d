// The GPU window's references for its error column and plot (Gui/ReferenceTask.h), rendered on the window's own
// device in the frames in which the image has nothing left to trace: each half (Compare/ReferenceRequest.h: seed
// + 1000 and + 2000) is a progressive accumulation of its own (a second ProgressiveFrame), a few samples per
// frame, so the window keeps drawing while it renders; the same samples as a headless half of its spp. A
// reference is looked up first among those finished in this session, then in --compare's reference cache, and
// stored there once rendered. References of another scene than the one on screen wait in the queue until it is
// shown again (no scene is built again for a reference). The fewest spp
// go first (the table's row before the plot's long points), the newest among equals.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "Engine/ProgressiveFrame.h"
#include "Gui/ReferenceMemory.h"
#include "Gui/ReferenceTask.h"
#include "Image/Image.h"
#include "Scene/Scene.h"

namespace rt::gpu::gui
{
class WindowReferences
{
public:
    /// `frameSlots`: the window's frames in flight. `cacheDir`: --compare's cache (empty: none).
    WindowReferences(const GpuEngine& engine, std::uint32_t frameSlots, std::filesystem::path cacheDir);

    /// Queues `task` of the scene the engine holds (`scene`), unless it is queued already; one finished before
    /// in this session (ReferenceMemory.h) or found in the cache is finished at once.
    void request(const rt::gui::ReferenceTask& task, const Scene& scene);
    /// Another scene is on the device: the half in progress is dropped (its descriptor sets are stale); the
    /// queue stays.
    void sceneChanged();
    /// Drops the queue and the half in progress (the table was cleared).
    void clear();
    /// A reference of `current` (the scene on screen) is queued or rendering.
    bool pending(const SceneRef& current) const;

    /// Records up to `samples` per pixel of the next reference of `current`, `scene` on the device, into frame
    /// `slot` (whose previous frame has completed), starting that reference (waiting for the device) when none was
    /// in progress. Returns the camera paths recorded.
    std::uint64_t recordSamples(VkCommandBuffer cmd, std::uint32_t slot, std::uint32_t samples, const Scene& scene,
                                const SceneRef& current);
    /// The frame just recorded completes a half: the caller waits for the device, then calls finishHalf.
    bool halfRecorded() const;
    /// Reads the half back (the device idle); after the second, combines them, stores the reference in the cache
    /// and finishes it.
    void finishHalf(const Scene& scene);

    /// References finished (or failed) since the last call, oldest first.
    std::vector<rt::gui::FinishedReference> take() { return std::exchange(m_finished, {}); }
    rt::gui::ReferenceProgress progress(const SceneRef& current) const;

private:
    struct Active
    {
        rt::gui::ReferenceTask task;
        int half = 0;
        std::uint32_t traced = 0; // samples per pixel of the half recorded
        std::optional<Image> firstHalf;
        double seconds = 0.0; // device time of the halves' samples so far
    };

    /// The index in m_queue of the next task of `current`: the fewest spp, the newest among equals;
    /// m_queue.size() when none.
    std::size_t next(const SceneRef& current) const;
    /// Adds the device time of `slot`'s last frame when it traced the half in progress.
    void takeSeconds(std::uint32_t slot);
    void fail(const std::string& why);

    const GpuEngine* m_engine;
    ProgressiveFrame m_frame;
    std::filesystem::path m_cacheDir;
    std::vector<rt::gui::ReferenceTask> m_queue;
    std::optional<Active> m_active; // the front of the queue, once started
    std::uint64_t m_half = 0; // grows with every half started or dropped
    std::vector<std::uint64_t> m_slotHalf; // the half whose samples each slot last recorded
    std::vector<rt::gui::FinishedReference> m_finished;
    rt::gui::ReferenceMemory m_memory;
};
} // namespace rt::gpu::gui
