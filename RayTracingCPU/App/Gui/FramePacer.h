// How often the window redraws. A frame drawn while a render runs takes CPU time from it (ImGui's drawing,
// the GL driver, which is llvmpipe on a machine without a GPU, and the X server), and that time lands in the
// render time the timings table reports: on 2 cores, 10 frames a second (about 15 ms of CPU each) made multi
// core 6 % slower than headless while single core left them the idle core (docs/notebook/PERFORMANCE.md §6; a user
// saw 1.0x for 1.4x on a loaded machine). So while a render runs the window draws a frame every
// kRenderingInterval, when the render thread has news (a render ended), and at once for a person's input (a
// click must not wait half a second); those last frames are counted, and the timings table marks a render
// that had any. A camera key held down (W/A/S/D/Q/E) is input at every frame, kHeldKeyInterval apart: a held
// key sends no events (or X's repeats, 25 a second), and paced frames moved the camera in steps half a second
// apart, at a fifth of its speed. The pointer merely moving over the window draws nothing until the next paced
// frame. Idle, the window draws on any event or every kIdleInterval.
#pragma once

#include <chrono>
#include <cstdint>

#include "Gui/WindowRedraws.h"

namespace rt::gui
{
class FramePacer
{
public:
    using Clock = std::chrono::steady_clock;
    static constexpr double kRenderingInterval = 0.5; // seconds between frames while a render runs
    static constexpr double kIdleInterval = 0.25;
    static constexpr double kAutomatedIdleInterval = 1.0 / 60.0; // --actions step one per frame
    static constexpr double kHeldKeyInterval = 1.0 / 60.0; // while a camera key is held

    enum class Frame
    {
        Skip, // nothing asks for one yet: wait again
        Paced, // the interval has passed
        News, // the render thread woke the window (GlWindow::wake), or idle: any event
        Input // a person's input (GlWindow::inputEvents)
    };

    /// The longest the frame loop waits for events before the next frame is due (`keyHeld`: a camera key is down).
    double timeout(bool rendering, bool automating, Clock::time_point now, bool keyHeld = false) const;

    /// After the wait: which frame to draw, given the window's input count, whether the render thread woke it
    /// and whether a camera key is held. A frame other than Skip counts as drawn.
    Frame next(bool rendering, bool automating, std::uint64_t inputEvents, bool woken, Clock::time_point now,
               bool keyHeld = false);

private:
    static double interval(bool rendering, bool automating, bool keyHeld);

    std::uint64_t m_inputEvents = 0;
    Clock::time_point m_lastFrame{};
};
} // namespace rt::gui
