#include "App/Gui/FramePacer.h"

#include <algorithm>

namespace rt::gui
{
double FramePacer::interval(bool rendering, bool automating, bool keyHeld)
{
    if (keyHeld)
        return kHeldKeyInterval;
    if (rendering)
        return kRenderingInterval;
    return automating ? kAutomatedIdleInterval : kIdleInterval;
}

double FramePacer::timeout(bool rendering, bool automating, Clock::time_point now, bool keyHeld) const
{
    const double since = std::chrono::duration<double>(now - m_lastFrame).count();
    const double wanted = interval(rendering, automating, keyHeld);
    return std::clamp(wanted - since, 1e-3, wanted);
}

FramePacer::Frame FramePacer::next(bool rendering, bool automating, std::uint64_t inputEvents, bool woken,
                                   Clock::time_point now, bool keyHeld)
{
    const bool input = inputEvents != m_inputEvents;
    m_inputEvents = inputEvents;
    const bool due = std::chrono::duration<double>(now - m_lastFrame).count() >= interval(rendering, automating, keyHeld);
    Frame frame = Frame::Skip;
    if (input || (keyHeld && due))
        frame = Frame::Input;
    else if (woken || !rendering)
        frame = Frame::News;
    else if (due)
        frame = Frame::Paced;
    if (frame != Frame::Skip)
        m_lastFrame = now;
    return frame;
}
} // namespace rt::gui
