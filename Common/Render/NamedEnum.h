// The words of an enum that users type (command line, --actions, scene files) and read (panels, stats JSON,
// logs), declared once per enum as a specialisation of EnumNames: toString, parseName, the panels' combo
// items and the "a, b or c" of an error message all read that one array.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace rt
{
/// One value of an enum and its word. `alias`: a second word accepted when parsing (the thesis' names), never
/// printed; empty for none.
template <typename Enum>
struct EnumName
{
    Enum value;
    const char* name;
    const char* alias = "";
};

/// Specialised for every enum users name: `static constexpr std::array<EnumName<Enum>, N> values`, in the
/// order panels list them.
template <typename Enum>
struct EnumNames;

template <typename Enum>
concept NamedEnum = requires { EnumNames<Enum>::values.size(); };

/// The word of `value` ("?" for a value outside the table).
template <NamedEnum Enum>
constexpr const char* toString(Enum value)
{
    for (const EnumName<Enum>& n : EnumNames<Enum>::values)
        if (n.value == value)
            return n.name;
    return "?";
}

/// The value a word names (its name or alias, exactly), or nothing.
template <NamedEnum Enum>
constexpr std::optional<Enum> parseName(std::string_view text)
{
    for (const EnumName<Enum>& n : EnumNames<Enum>::values)
        if (text == n.name || (*n.alias != '\0' && text == n.alias))
            return n.value;
    return std::nullopt;
}

/// "a, b or c" (`last` = " or "), or "a, b and c": the words, for messages and help.
template <NamedEnum Enum>
std::string nameList(std::string_view last = " or ")
{
    std::string out;
    const auto& values = EnumNames<Enum>::values;
    for (std::size_t i = 0; i < values.size(); ++i)
    {
        if (i > 0)
            out += i + 1 == values.size() ? last : std::string_view(", ");
        out += values[i].name;
    }
    return out;
}
} // namespace rt
