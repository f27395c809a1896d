// The timings table on screen: one line per piece of work, single core, multi core and GPU side by side,
// the fastest engine of each line highlighted, with the speed-ups over single core.
#pragma once

#include "App/Gui/Session.h"

namespace rt::gui
{
/// Draws into the current ImGui window.
void drawTimings(Session& session);
} // namespace rt::gui
