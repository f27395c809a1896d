// --actions: a small script of UI actions, so the window can be tested without a person. Each action calls
// the Session command its widget calls; one runs per frame, and the waiting ones hold the script over frames.
#pragma once

#include <chrono>

#include <cstddef>
#include <string>
#include <vector>

#include "App/Gui/Session.h"
#include "Cli/ActionGrammar.h"
#include "App/Gui/GlWindow.h"

namespace rt::gui
{
class ActionScript
{
public:
    /// Parses "name=value;name;..." (actionHelp() lists them; the grammar is Cli/ActionGrammar.h). Throws
    /// UsageError naming a bad action.
    explicit ActionScript(const std::string& text);

    /// Runs the next action, or checks the one waiting. Returns true once every action has run.
    bool step(Session& session, GlWindow& window);
    bool done() const { return m_next == m_actions.size(); }
    /// Actions whose command refused (logged as errors); `engine=gpu` without a GPU engine is not one.
    int failures() const { return m_failures; }

private:
    using Action = ScriptedAction;
    /// True when the action is finished (a waiting action returns false until its condition holds).
    bool run(const Action& action, Session& session, GlWindow& window);

    std::vector<Action> m_actions;
    std::size_t m_next = 0;
    bool m_waiting = false; // the current action has started waiting
    int m_framesLeft = 0;
    std::chrono::steady_clock::time_point m_sleepUntil{};
    int m_finishedBefore = 0;
    int m_failures = 0;
};

/// The --help text of --actions.
std::string actionHelp();
} // namespace rt::gui
