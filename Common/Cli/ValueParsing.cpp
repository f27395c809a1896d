#include "Cli/ValueParsing.h"

#include <charconv>

namespace rt
{
namespace
{
template <typename T>
std::optional<T> parseWhole(std::string_view text)
{
    T value{};
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || text.empty())
        return std::nullopt;
    return value;
}
} // namespace

std::optional<long long> parseInteger(std::string_view text) { return parseWhole<long long>(text); }

std::optional<float> parseReal(std::string_view text) { return parseWhole<float>(text); }

std::optional<bool> parseOnOff(std::string_view text)
{
    if (text == "on")
        return true;
    if (text == "off")
        return false;
    return std::nullopt;
}

std::optional<std::pair<long long, long long>> parseSize(std::string_view text)
{
    const std::size_t x = text.find('x');
    if (x == std::string_view::npos)
        return std::nullopt;
    const auto width = parseInteger(text.substr(0, x));
    const auto height = parseInteger(text.substr(x + 1));
    if (!width || !height)
        return std::nullopt;
    return std::pair{*width, *height};
}
} // namespace rt
