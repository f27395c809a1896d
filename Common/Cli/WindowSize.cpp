#include "Cli/WindowSize.h"

#include <algorithm>

#include <spdlog/fmt/fmt.h>

#include "Cli/ValueParsing.h"
#include "Error.h"

namespace rt
{
WindowSize parseWindowSize(const std::string& text, const std::string& flag)
{
    const auto size = parseSize(text);
    if (!size)
        throw UsageError(fmt::format("{} must be WIDTHxHEIGHT in pixels, e.g. 1280x800 (got '{}')", flag, text));
    for (const auto& [side, value] : {std::pair{"width", size->first}, {"height", size->second}})
        if (value < kMinWindowSide || value > kMaxWindowSide)
            throw UsageError(fmt::format("{} {}: the {} must be from {} to {} pixels (got {})", flag, text, side,
                                         kMinWindowSide, kMaxWindowSide, value));
    return {int(size->first), int(size->second)};
}

WindowSize fitWindowSize(WindowSize wanted, WindowSize workArea)
{
    const auto fit = [](int side, int available) {
        if (available > 0)
            side = std::min(side, available);
        return std::clamp(side, kMinWindowSide, kMaxWindowSide);
    };
    return {fit(wanted.width, workArea.width), fit(wanted.height, workArea.height)};
}
} // namespace rt
