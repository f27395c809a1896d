// The timings table on screen: for each piece of work, a line per engine that rendered it (single core, multi
// core, GPU) with its render time (tracing alone), its setup apart (acceleration structures; pipelines compiled,
// or cached), the fastest engine highlighted and the speed-up over single core.
#pragma once

#include "Gui/TimingsTable.h"

namespace rt::gui
{
struct TimingsDrawn
{
    bool latestVisible = true; // the latest timing's row is on screen (true with no rows): --state-json's
    bool clearClicked = false; // the Clear button: the window empties its table (and what waits on it)
};

/// Draws `table` into the current ImGui window, scrolled to the row of the latest timing when one arrived.
TimingsDrawn drawTimings(const TimingsTable& table);
} // namespace rt::gui
