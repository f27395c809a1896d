// Ctrl-C for the headless runs: while an InterruptScope lives, SIGINT (and, in an MPI job, SIGTERM: mpirun's) cancels the render whose RenderControl
// is routed to it (the driver stops at its next check) and marks the scope interrupted, so a run of many
// renders (ray-tracing-gpu --compare) stops after the one in progress. The previous handler comes back when
// the scope ends. One scope at a time.
#pragma once

#include "Render/RenderControl.h"

namespace rt
{
class InterruptScope
{
public:
    InterruptScope();
    ~InterruptScope();
    InterruptScope(const InterruptScope&) = delete;
    InterruptScope& operator=(const InterruptScope&) = delete;

    /// SIGINT cancels `control` from now until route(nullptr) or the scope's end.
    static void route(RenderControl* control);
    /// Whether SIGINT arrived during the scope.
    static bool interrupted();
};
} // namespace rt
