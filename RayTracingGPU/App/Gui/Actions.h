// Scripted input for running the window without a person (tests, demos): `--actions "scene=rtnw-quads;
// depth=7;resize=0x0;resize=640x400;raytracing=off;heatmap=on;camera=forward:10"`. The grammar and the
// actions both windows share are Common's (Cli/ActionGrammar.h); this window adds its own. Actions run one
// per frame in order, each through Controls (the panel's own functions); a scene action waits for its scene
// to be built before the next one runs; frames=N lets N frames pass, sleep=SECONDS that much time.
#pragma once

#include <string>
#include <vector>

#include "App/Gui/Controls.h"
#include "Cli/ActionGrammar.h"

namespace rt::gpu::gui
{
using Action = ScriptedAction;

/// Splits at ';' and checks every name and value (rt::UsageError naming the bad one), so a typo stops the app
/// before the window opens.
std::vector<Action> parseActions(const std::string& script);

/// Applies one action through `controls`. `frames`, `sleep`, `wait` and `wait-reference` are the frame loop's (it
/// returns false for them).
/// Returns true when the action was applied.
bool applyAction(const Action& action, Controls& controls);

/// The frames a frames action asks for (0 for any other action).
int waitFrames(const Action& action);

/// The wall-clock seconds a sleep action asks for (0 for any other action).
double waitSeconds(const Action& action);

/// The list of actions and their values, for --help.
std::string actionHelp();
} // namespace rt::gpu::gui
