// The references behind the timings table's error column (TimingsTable.h). After a render finishes, the window
// asks the render thread for a reference of the same work at kDefaultReferenceFactor x its spp: the request
// --compare's ladder would render for `--spp-list N` (Compare/ReferenceRequest.h: two independent halves, seeds
// + 1000 and + 2000), looked up first in --compare's reference cache (Compare/ReferenceCache.h) and stored there
// once rendered, so either tool re-uses the other's. The render thread renders references only while no render
// of the person's waits or runs, and a new render cancels the reference's half in progress (a finished half is
// kept): the timings never share the machine with a reference.
#pragma once

#include <memory>
#include <string>

#include "Image/Image.h"
#include "Render/RenderRequest.h"
#include "Render/RenderSettings.h"

namespace rt::gui
{
struct ReferenceTask
{
    RenderRequest base; // the render measured (its seed: the reference's halves are at seed + 1000 and + 2000)
    EngineKind engine = EngineKind::Multi; // that renders the reference
    int spp = 0; // both halves together

    bool operator==(const ReferenceTask&) const = default;
};

struct FinishedReference
{
    ReferenceTask task;
    std::shared_ptr<const Image> image; // the halves' mean; null when it failed
    double ownRelMse = 0.0; // the relMSE its own noise adds to every relMSE against it (Image/Metrics.h)
    bool fromCache = false;
    double seconds = 0.0; // tracing both halves; 0 from the cache
    std::string error; // why it failed
};

struct ReferenceProgress
{
    bool rendering = false; // a reference's half is being rendered now
    ReferenceTask task; // that reference's
    double fraction = 0.0; // of both halves
    int waiting = 0; // references of the current scene queued behind it
};
} // namespace rt::gui
