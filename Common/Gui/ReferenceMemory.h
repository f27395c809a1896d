// The references a window has finished in this session, kept so that a render asked for again (the same
// settings and seed, a plot point of the same spp, the GPU window's image traced again after a CPU engine's)
// finds its reference here rather than rendering it again, with --compare's cache on disk off too. The newest
// kKept are kept; their images are shared with the table and the plot that hold them.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

#include "Gui/ReferenceTask.h"

namespace rt::gui
{
class ReferenceMemory
{
public:
    static constexpr std::size_t kKept = 32;

    /// Keeps `reference` when it has an image (a failed one is asked for again), the oldest dropped past kKept.
    void remember(const FinishedReference& reference)
    {
        if (!reference.image)
            return;
        std::erase_if(m_kept, [&](const FinishedReference& r) { return r.task == reference.task; });
        m_kept.push_back(reference);
        if (m_kept.size() > kKept)
            m_kept.erase(m_kept.begin());
    }

    /// The reference of `task` finished before, marked as found (fromCache, no seconds of its own); nullopt.
    std::optional<FinishedReference> find(const ReferenceTask& task) const
    {
        const auto it = std::find_if(m_kept.begin(), m_kept.end(), [&](const FinishedReference& r) { return r.task == task; });
        if (it == m_kept.end())
            return std::nullopt;
        FinishedReference found = *it;
        found.fromCache = true;
        found.seconds = 0.0;
        return found;
    }

private:
    std::vector<FinishedReference> m_kept; // oldest first
};
} // namespace rt::gui
