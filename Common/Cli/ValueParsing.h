// The values of flags and scripted actions (both apps' --actions, --window-size, --spp-list, on/off flags),
// parsed whole: no sign, space or other character around the value. Each returns nullopt for text that is
// not such a value; callers turn that into their own error naming the flag.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rt
{
std::optional<long long> parseInteger(std::string_view text);
/// Decimal or scientific notation (std::from_chars); "inf" and "nan" parse, callers that need a finite
/// value check it.
std::optional<float> parseReal(std::string_view text);
/// "X,Y,Z": three parseReal values separated by commas, nothing else.
std::optional<std::array<float, 3>> parseRealTriple(std::string_view text);
/// The parts of a comma-separated list ("a,,b" -> a, "", b; a trailing comma adds none; "" -> none), as
/// std::getline splits them: callers parse and check each.
std::vector<std::string> splitCommas(std::string_view text);
/// "on" or "off".
std::optional<bool> parseOnOff(std::string_view text);
/// "WxH" with two integers, e.g. 1280x800.
std::optional<std::pair<long long, long long>> parseSize(std::string_view text);
} // namespace rt
