// The timings table on screen: for each piece of work, a line per engine that rendered it (single core, multi
// core, GPU) with its render time (tracing alone), its setup apart (acceleration structures; pipelines compiled,
// or cached), the fastest engine highlighted and the speed-up over single core.
#pragma once

#include "App/Gui/Session.h"

namespace rt::gui
{
/// Draws into the current ImGui window, scrolled to the row of the latest timing when one arrived. Returns
/// whether that row is on screen (true with no rows): --state-json reports it for the window tests.
bool drawTimings(Session& session);
} // namespace rt::gui
