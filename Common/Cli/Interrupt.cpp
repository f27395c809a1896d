#include "Cli/Interrupt.h"

#include <atomic>
#include <csignal>

#include "Cluster/Job.h"

namespace rt
{
namespace
{
std::atomic<RenderControl*> g_control{nullptr};
std::atomic<bool> g_interrupted{false};
void (*g_previousHandler)(int) = SIG_DFL;
void (*g_previousTermHandler)(int) = SIG_DFL;

extern "C" void onInterrupt(int)
{
    g_interrupted.store(true);
    if (RenderControl* c = g_control.load())
        c->requestCancel();
}
} // namespace

InterruptScope::InterruptScope()
{
    g_interrupted.store(false);
    g_previousHandler = std::signal(SIGINT, onInterrupt);
    // mpirun passes Ctrl-C on to its ranks as SIGTERM (and a rank's death too, a second before SIGKILL). A process
    // of its own keeps SIGTERM's default: kill, timeout and service managers end it at once.
    if (cluster::job().distributed())
        g_previousTermHandler = std::signal(SIGTERM, onInterrupt);
}

InterruptScope::~InterruptScope()
{
    std::signal(SIGINT, g_previousHandler);
    if (cluster::job().distributed())
        std::signal(SIGTERM, g_previousTermHandler);
    g_control.store(nullptr);
}

void InterruptScope::route(RenderControl* control)
{
    g_control.store(control);
    if (control && g_interrupted.load())
        control->requestCancel(); // SIGINT came between two renders
}

bool InterruptScope::interrupted()
{
    return g_interrupted.load();
}
} // namespace rt
