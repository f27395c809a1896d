// The timings table on screen: one line per piece of work, single core, multi core and GPU side by side,
// the fastest engine of each line highlighted, with the speed-ups over single core.
#pragma once

#include "App/Gui/Session.h"

namespace rt::gui
{
/// Draws into the current ImGui window, scrolled to the row of the latest timing when one arrived. Returns
/// whether that row is on screen (true with no rows): --state-json reports it for the window tests.
bool drawTimings(Session& session);
} // namespace rt::gui
