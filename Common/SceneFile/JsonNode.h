// A JSON value of a scene file together with where it sits (file and JSON pointer, RFC 6901), so that every
// check a reader makes can fail with one line naming the place: `scene.json: /materials/2/fuzz: expected a
// number in [0, 1], got 1.5`. The typed getters are the only way the scene readers look at values.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "Math/Math.h"

namespace rt
{
class JsonNode
{
public:
    /// `value` must outlive the node and every node taken from it. `file` is the name errors start with.
    JsonNode(const nlohmann::json& value, std::string file, std::string pointer = "");

    const nlohmann::json& value() const { return *m_value; }
    const std::string& file() const { return m_file; }
    /// The JSON pointer of this value ("" for the document's root).
    const std::string& pointer() const { return m_pointer; }

    bool has(std::string_view key) const;
    /// The member `key`; throws SceneError if this is not an object or it has no such member.
    JsonNode operator[](std::string_view key) const;
    /// Element `index` of an array.
    JsonNode operator[](std::size_t index) const;
    /// Number of elements; throws SceneError if this is not an array.
    std::size_t size() const;
    /// Throws SceneError if this is not an object, or names a member not in `known` (listing them).
    void allowOnly(std::initializer_list<std::string_view> known) const;

    /// A finite number in [lo, hi].
    float number(float lo = -kMaxFloat, float hi = kMaxFloat) const;
    /// An integer in [lo, hi] (written without fraction or exponent).
    std::int64_t integer(std::int64_t lo, std::int64_t hi) const;
    bool boolean() const;
    std::string string() const;
    /// One of `choices`; returns its position in the list.
    std::size_t choice(std::initializer_list<std::string_view> choices) const;
    /// Three finite numbers, each in [lo, hi].
    vec3 vector3(float lo = -kMaxFloat, float hi = kMaxFloat) const;
    /// Three finite numbers, kept in double (a position far from the world's origin: Scene::origin).
    dvec3 dvector3() const;

    /// Throws SceneError "<file>: <pointer>: <what>".
    [[noreturn]] void fail(const std::string& what) const;

    static constexpr float kMaxFloat = 3.402823466e38f;

private:
    const nlohmann::json* m_value;
    std::string m_file;
    std::string m_pointer;
};

/// Parses `text` (the contents of `file`); a syntax error throws SceneError with the file, line and column.
/// The deepest nesting of arrays and objects a scene file may have: far beyond any scene, far below what the
/// parsers' and serialisers' recursion can take on a thread's stack (60,000 levels overflowed it).
inline constexpr int kMaxJsonNesting = 512;

/// Throws SceneError ("file:line:column: nested deeper than 512 ...") where `text`, JSON, nests arrays and
/// objects deeper than kMaxJsonNesting, before any parser recurses into it. Brackets inside strings do not count.
void checkJsonNesting(std::string_view text, const std::string& file);

nlohmann::json parseJsonText(const std::string& text, const std::string& file);

/// A short rendering of a value for error messages: its JSON text, cut to about 40 characters.
std::string describeJson(const nlohmann::json& value);
} // namespace rt
