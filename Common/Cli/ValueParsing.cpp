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

std::optional<std::array<float, 3>> parseRealTriple(std::string_view text)
{
    std::array<float, 3> out{};
    for (std::size_t i = 0; i < 3; ++i)
    {
        const std::size_t comma = text.find(',');
        if ((i < 2) != (comma != std::string_view::npos))
            return std::nullopt; // too few or too many values
        const auto value = parseReal(text.substr(0, comma));
        if (!value)
            return std::nullopt;
        out[i] = *value;
        text = i < 2 ? text.substr(comma + 1) : std::string_view();
    }
    return out;
}

std::vector<std::string> splitCommas(std::string_view text)
{
    std::vector<std::string> parts;
    while (!text.empty())
    {
        const std::size_t comma = text.find(',');
        parts.emplace_back(text.substr(0, comma));
        text = comma == std::string_view::npos ? std::string_view() : text.substr(comma + 1);
    }
    return parts;
}

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
