// Frames a window drew while a render ran: their drawing took CPU time from it (the CPU window's FramePacer.h
// paces them), and a timings row marks a render that had any drawn for a person's input.
#pragma once

namespace rt::gui
{
struct WindowRedraws
{
    int total = 0;
    int onInput = 0; // drawn at once for a person's input, beyond the pacer's
};
} // namespace rt::gui
