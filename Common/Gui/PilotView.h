// Both windows' view of --strategy auto's last pilot (Compare/AutoStrategy.h): what it chose, in how long, and its
// table of candidates, the chosen one marked. The panel's settings show the choice; changing one overrides it.
#pragma once

#include "Compare/AutoStrategy.h"

namespace rt::gui
{
/// Draws `choice` into the current ImGui window: a line (chosen strategy, the pilot's wall time, its image and spp
/// per candidate) and a table (strategy, measurements, relMSE, efficiency 1/(relMSE s)).
void drawPilot(const compare::AutoChoice& choice);
} // namespace rt::gui
