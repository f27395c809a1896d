// --window-size WxH, the same flag in both windows: one parser and one range, so that a bad size stops
// either app with the same one-line error before anything opens, and a size that fits a monitor.
#pragma once

#include <string>

namespace rt
{
/// A window's size in screen pixels (framebuffer pixels where the platform does not scale).
struct WindowSize
{
    int width = 0;
    int height = 0;

    bool operator==(const WindowSize&) const = default;
};

/// Narrower or lower than this, no settings panel fits beside an image: the layouts would show neither.
inline constexpr int kMinWindowSide = 160;
/// The bound of the scripted resize too (Cli/ActionGrammar.h): Vulkan and GL devices commonly refuse
/// framebuffers and textures larger than 16384 pixels a side.
inline constexpr int kMaxWindowSide = 16384;

/// "WxH" with each side in [kMinWindowSide, kMaxWindowSide]. Throws UsageError naming `flag`, the text as
/// written and the bound it breaks.
WindowSize parseWindowSize(const std::string& text, const std::string& flag = "--window-size");

/// `wanted`, each side cut to `workArea`'s (a monitor's usable area; a side of 0 is unknown and cuts nothing)
/// and raised to kMinWindowSide.
WindowSize fitWindowSize(WindowSize wanted, WindowSize workArea);
} // namespace rt
