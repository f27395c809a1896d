#include "SceneFile/JsonNode.h"

#include <cmath>

#include <spdlog/fmt/fmt.h>

#include "Error.h"

namespace rt
{
namespace
{
/// RFC 6901: '~' and '/' in a member name are escaped as ~0 and ~1.
std::string escapePointerToken(std::string_view key)
{
    std::string out;
    for (const char c : key)
    {
        if (c == '~')
            out += "~0";
        else if (c == '/')
            out += "~1";
        else
            out += c;
    }
    return out;
}

const char* typeName(const nlohmann::json& v)
{
    if (v.is_number())
        return "a number";
    if (v.is_string())
        return "a string";
    if (v.is_boolean())
        return "a boolean";
    if (v.is_array())
        return "an array";
    if (v.is_object())
        return "an object";
    return "null";
}
} // namespace

JsonNode::JsonNode(const nlohmann::json& value, std::string file, std::string pointer)
    : m_value(&value), m_file(std::move(file)), m_pointer(std::move(pointer))
{
}

void JsonNode::fail(const std::string& what) const
{
    throw SceneError(fmt::format("{}: {}: {}", m_file, m_pointer.empty() ? "/" : m_pointer, what));
}

bool JsonNode::has(std::string_view key) const { return m_value->is_object() && m_value->contains(key); }

JsonNode JsonNode::operator[](std::string_view key) const
{
    if (!m_value->is_object())
        fail(fmt::format("expected an object with '{}', got {}", key, typeName(*m_value)));
    const auto it = m_value->find(key);
    if (it == m_value->end())
        fail(fmt::format("'{}' is missing", key));
    return {*it, m_file, m_pointer + "/" + escapePointerToken(key)};
}

JsonNode JsonNode::operator[](std::size_t index) const
{
    if (index >= size())
        fail(fmt::format("has no element {}", index));
    return {(*m_value)[index], m_file, fmt::format("{}/{}", m_pointer, index)};
}

std::size_t JsonNode::size() const
{
    if (!m_value->is_array())
        fail(fmt::format("expected an array, got {}", typeName(*m_value)));
    return m_value->size();
}

void JsonNode::allowOnly(std::initializer_list<std::string_view> known) const
{
    if (!m_value->is_object())
        fail(fmt::format("expected an object, got {}", typeName(*m_value)));
    for (const auto& [key, unused] : m_value->items())
    {
        bool found = false;
        for (const std::string_view k : known)
            found = found || k == key;
        if (found)
            continue;
        std::string list;
        for (const std::string_view k : known)
            list += fmt::format("{}{}", list.empty() ? "" : ", ", k);
        fail(fmt::format("unknown key '{}' (expected one of: {})", key, list));
    }
}

float JsonNode::number(float lo, float hi) const
{
    if (!m_value->is_number())
        fail(fmt::format("expected a number, got {}", describeJson(*m_value)));
    const double v = m_value->get<double>();
    if (!std::isfinite(v) || v < lo || v > hi)
        fail(fmt::format("expected a number in [{}, {}], got {}", lo, hi, describeJson(*m_value)));
    return static_cast<float>(v);
}

std::int64_t JsonNode::integer(std::int64_t lo, std::int64_t hi) const
{
    if (m_value->is_number_unsigned())
    {
        const std::uint64_t u = m_value->get<std::uint64_t>();
        if (hi >= 0 && u <= static_cast<std::uint64_t>(hi) && static_cast<std::int64_t>(u) >= lo)
            return static_cast<std::int64_t>(u);
    }
    else if (m_value->is_number_integer())
    {
        const std::int64_t v = m_value->get<std::int64_t>();
        if (v >= lo && v <= hi)
            return v;
    }
    fail(fmt::format("expected an integer in [{}, {}], got {}", lo, hi, describeJson(*m_value)));
}

bool JsonNode::boolean() const
{
    if (!m_value->is_boolean())
        fail(fmt::format("expected true or false, got {}", describeJson(*m_value)));
    return m_value->get<bool>();
}

std::string JsonNode::string() const
{
    if (!m_value->is_string())
        fail(fmt::format("expected a string, got {}", describeJson(*m_value)));
    return m_value->get<std::string>();
}

std::size_t JsonNode::choice(std::initializer_list<std::string_view> choices) const
{
    std::string list;
    for (const std::string_view c : choices)
        list += fmt::format("{}'{}'", list.empty() ? "" : ", ", c);
    if (!m_value->is_string())
        fail(fmt::format("expected one of {}, got {}", list, describeJson(*m_value)));
    const std::string& s = m_value->get_ref<const std::string&>();
    std::size_t i = 0;
    for (const std::string_view c : choices)
    {
        if (c == s)
            return i;
        ++i;
    }
    fail(fmt::format("expected one of {}, got '{}'", list, s));
}

vec3 JsonNode::vector3(float lo, float hi) const
{
    if (!m_value->is_array() || m_value->size() != 3)
        fail(fmt::format("expected an array of 3 numbers, got {}", describeJson(*m_value)));
    return {(*this)[std::size_t{0}].number(lo, hi), (*this)[1].number(lo, hi), (*this)[2].number(lo, hi)};
}

dvec3 JsonNode::dvector3() const
{
    if (!m_value->is_array() || m_value->size() != 3)
        fail(fmt::format("expected an array of 3 numbers, got {}", describeJson(*m_value)));
    dvec3 v;
    for (int i = 0; i < 3; ++i)
    {
        const JsonNode x = (*this)[static_cast<std::size_t>(i)];
        if (!x.value().is_number())
            x.fail(fmt::format("expected a number, got {}", describeJson(x.value())));
        v[i] = x.value().get<double>();
        if (!std::isfinite(v[i]))
            x.fail(fmt::format("expected a finite number, got {}", describeJson(x.value())));
    }
    return v;
}

void checkJsonNesting(std::string_view text, const std::string& file)
{
    int depth = 0;
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i)
    {
        const char c = text[i];
        if (inString)
        {
            if (c == '\\')
                ++i;
            else if (c == '"')
                inString = false;
        }
        else if (c == '"')
            inString = true;
        else if (c == '[' || c == '{')
        {
            if (++depth > kMaxJsonNesting)
            {
                std::size_t line = 1, column = 1;
                for (std::size_t k = 0; k < i; ++k)
                    column = text[k] == '\n' ? (++line, 1) : column + 1;
                throw SceneError(fmt::format("{}:{}:{}: arrays and objects nested deeper than {} levels", file, line,
                                             column, kMaxJsonNesting));
            }
        }
        else if (c == ']' || c == '}')
            --depth;
    }
}

nlohmann::json parseJsonText(const std::string& text, const std::string& file)
{
    checkJsonNesting(text, file);
    try
    {
        return nlohmann::json::parse(text);
    }
    catch (const nlohmann::json::parse_error& e)
    {
        // e.byte is 1-based and points just past the character that stopped the parser.
        const std::size_t end = std::min<std::size_t>(e.byte == 0 ? 0 : e.byte - 1, text.size());
        std::size_t line = 1;
        std::size_t column = 1;
        for (std::size_t i = 0; i < end; ++i)
        {
            if (text[i] == '\n')
            {
                ++line;
                column = 1;
            }
            else
                ++column;
        }
        // nlohmann's message reads "[json.exception.parse_error.101] parse error at line 3, column 7: syntax
        // error while parsing object - ..."; keep what follows the position.
        std::string what = e.what();
        if (const auto colon = what.find(": "); colon != std::string::npos)
            what = what.substr(colon + 2);
        throw SceneError(fmt::format("{}:{}:{}: {}", file, line, column, what));
    }
    catch (const nlohmann::json::exception& e)
    {
        // A number beyond a double ("number overflow parsing '6666...'", out_of_range.406) is no parse_error.
        std::string what = e.what();
        if (const auto bracket = what.find("] "); bracket != std::string::npos)
            what = what.substr(bracket + 2);
        if (what.size() > 120)
            what = what.substr(0, 117) + "...";
        throw SceneError(fmt::format("{}: {}", file, what));
    }
}

std::string describeJson(const nlohmann::json& value)
{
    std::string s = value.dump();
    if (s.size() > 40)
        s = s.substr(0, 37) + "...";
    return s;
}
} // namespace rt
