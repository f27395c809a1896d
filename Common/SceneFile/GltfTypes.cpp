#include "SceneFile/GltfTypes.h"

#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <spdlog/fmt/fmt.h>

#include "Error.h"
#include "SceneFile/JsonNode.h"

namespace rt
{
namespace
{
enum class Kind
{
    Object,
    Array,
    Number,
    Integer, // a number of integral value (an index, a count, an enum)
    String,
    Bool
};

struct Property
{
    const char* pattern; // a JSON pointer, '*' for every item of an array
    Kind kind;
    int length = 0; // for an array of numbers: its exact length (0: any), each item a number
};

// glTF 2.0's schema, parents before their children (a child is looked at only where its parent has its type).
constexpr Property kSchema[] = {
    {"/asset", Kind::Object},
    {"/asset/version", Kind::String},
    {"/scene", Kind::Integer},
    {"/extensionsUsed", Kind::Array},
    {"/extensionsUsed/*", Kind::String},
    {"/extensionsRequired", Kind::Array},
    {"/extensionsRequired/*", Kind::String},
    {"/scenes", Kind::Array},
    {"/scenes/*", Kind::Object},
    {"/scenes/*/nodes", Kind::Array},
    {"/scenes/*/nodes/*", Kind::Integer},
    {"/nodes", Kind::Array},
    {"/nodes/*", Kind::Object},
    {"/nodes/*/children", Kind::Array},
    {"/nodes/*/children/*", Kind::Integer},
    {"/nodes/*/mesh", Kind::Integer},
    {"/nodes/*/camera", Kind::Integer},
    {"/nodes/*/skin", Kind::Integer},
    {"/nodes/*/translation", Kind::Array, 3},
    {"/nodes/*/rotation", Kind::Array, 4},
    {"/nodes/*/scale", Kind::Array, 3},
    {"/nodes/*/matrix", Kind::Array, 16},
    {"/meshes", Kind::Array},
    {"/meshes/*", Kind::Object},
    {"/meshes/*/primitives", Kind::Array},
    {"/meshes/*/primitives/*", Kind::Object},
    {"/meshes/*/primitives/*/attributes", Kind::Object},
    {"/meshes/*/primitives/*/indices", Kind::Integer},
    {"/meshes/*/primitives/*/material", Kind::Integer},
    {"/meshes/*/primitives/*/mode", Kind::Integer},
    {"/materials", Kind::Array},
    {"/materials/*", Kind::Object},
    {"/materials/*/pbrMetallicRoughness", Kind::Object},
    {"/materials/*/pbrMetallicRoughness/baseColorFactor", Kind::Array, 4},
    {"/materials/*/pbrMetallicRoughness/metallicFactor", Kind::Number},
    {"/materials/*/pbrMetallicRoughness/roughnessFactor", Kind::Number},
    {"/materials/*/pbrMetallicRoughness/baseColorTexture", Kind::Object},
    {"/materials/*/pbrMetallicRoughness/baseColorTexture/index", Kind::Integer},
    {"/materials/*/pbrMetallicRoughness/baseColorTexture/texCoord", Kind::Integer},
    {"/materials/*/pbrMetallicRoughness/metallicRoughnessTexture", Kind::Object},
    {"/materials/*/pbrMetallicRoughness/metallicRoughnessTexture/index", Kind::Integer},
    {"/materials/*/pbrMetallicRoughness/metallicRoughnessTexture/texCoord", Kind::Integer},
    {"/materials/*/normalTexture", Kind::Object},
    {"/materials/*/normalTexture/index", Kind::Integer},
    {"/materials/*/occlusionTexture", Kind::Object},
    {"/materials/*/occlusionTexture/index", Kind::Integer},
    {"/materials/*/emissiveTexture", Kind::Object},
    {"/materials/*/emissiveTexture/index", Kind::Integer},
    {"/materials/*/emissiveTexture/texCoord", Kind::Integer},
    {"/materials/*/emissiveFactor", Kind::Array, 3},
    {"/materials/*/alphaMode", Kind::String},
    {"/materials/*/alphaCutoff", Kind::Number},
    {"/materials/*/doubleSided", Kind::Bool},
    {"/materials/*/extensions", Kind::Object},
    {"/accessors", Kind::Array},
    {"/accessors/*", Kind::Object},
    {"/accessors/*/bufferView", Kind::Integer},
    {"/accessors/*/byteOffset", Kind::Integer},
    {"/accessors/*/componentType", Kind::Integer},
    {"/accessors/*/normalized", Kind::Bool},
    {"/accessors/*/count", Kind::Integer},
    {"/accessors/*/type", Kind::String},
    {"/accessors/*/min", Kind::Array},
    {"/accessors/*/max", Kind::Array},
    {"/accessors/*/sparse", Kind::Object},
    {"/bufferViews", Kind::Array},
    {"/bufferViews/*", Kind::Object},
    {"/bufferViews/*/buffer", Kind::Integer},
    {"/bufferViews/*/byteOffset", Kind::Integer},
    {"/bufferViews/*/byteLength", Kind::Integer},
    {"/bufferViews/*/byteStride", Kind::Integer},
    {"/buffers", Kind::Array},
    {"/buffers/*", Kind::Object},
    {"/buffers/*/uri", Kind::String},
    {"/buffers/*/byteLength", Kind::Integer},
    {"/images", Kind::Array},
    {"/images/*", Kind::Object},
    {"/images/*/uri", Kind::String},
    {"/images/*/mimeType", Kind::String},
    {"/images/*/bufferView", Kind::Integer},
    {"/textures", Kind::Array},
    {"/textures/*", Kind::Object},
    {"/textures/*/source", Kind::Integer},
    {"/textures/*/sampler", Kind::Integer},
    {"/samplers", Kind::Array},
    {"/samplers/*", Kind::Object},
    {"/cameras", Kind::Array},
    {"/cameras/*", Kind::Object},
    {"/cameras/*/type", Kind::String},
    {"/cameras/*/perspective", Kind::Object},
    {"/cameras/*/perspective/yfov", Kind::Number},
    {"/cameras/*/perspective/aspectRatio", Kind::Number},
    {"/cameras/*/perspective/znear", Kind::Number},
    {"/cameras/*/perspective/zfar", Kind::Number},
    {"/cameras/*/orthographic", Kind::Object},
    {"/animations", Kind::Array},
    {"/skins", Kind::Array},
};

const char* kindName(Kind kind, int length)
{
    switch (kind)
    {
    case Kind::Object:
        return "an object";
    case Kind::Array:
        return length > 0 ? "an array of numbers" : "an array";
    case Kind::Number:
        return "a number";
    case Kind::Integer:
        return "an integer";
    case Kind::String:
        return "a string";
    case Kind::Bool:
        return "true or false";
    }
    return "";
}

std::string describe(const nlohmann::json& value)
{
    switch (value.type())
    {
    case nlohmann::json::value_t::object:
        return "an object";
    case nlohmann::json::value_t::array:
        return fmt::format("an array of {}", value.size());
    case nlohmann::json::value_t::string:
        return "a string";
    case nlohmann::json::value_t::boolean:
        return value.get<bool>() ? "true" : "false";
    case nlohmann::json::value_t::null:
        return "null";
    default:
        return fmt::format("{}", value.get<double>());
    }
}

bool integral(const nlohmann::json& v)
{
    if (v.is_number_integer() || v.is_number_unsigned())
        return true;
    return v.is_number_float() && std::isfinite(v.get<double>()) && std::floor(v.get<double>()) == v.get<double>();
}

bool matches(const nlohmann::json& v, const Property& p)
{
    switch (p.kind)
    {
    case Kind::Object:
        return v.is_object();
    case Kind::Array:
        if (!v.is_array() || (p.length > 0 && v.size() != std::size_t(p.length)))
            return false;
        if (p.length > 0)
            for (const nlohmann::json& item : v)
                if (!item.is_number())
                    return false;
        return true;
    case Kind::Number:
        return v.is_number();
    case Kind::Integer:
        return integral(v);
    case Kind::String:
        return v.is_string();
    case Kind::Bool:
        return v.is_boolean();
    }
    return false;
}

/// Checks `p` from token `at` of its pattern down from `value`, at `pointer`.
void check(const nlohmann::json& value, const std::vector<std::string>& tokens, std::size_t at, const std::string& pointer,
           const Property& p, const std::filesystem::path& file)
{
    if (at == tokens.size())
    {
        if (!matches(value, p))
            throw SceneError(fmt::format("{}: {}: expected {}{}, got {} (tinygltf would read past it as if absent)",
                                         file.string(), pointer, kindName(p.kind, p.length),
                                         p.length > 0 ? fmt::format(" of length {}", p.length) : std::string(),
                                         describe(value)));
        return;
    }
    if (tokens[at] == "*")
    {
        if (value.is_array())
            for (std::size_t i = 0; i < value.size(); ++i)
                check(value[i], tokens, at + 1, fmt::format("{}/{}", pointer, i), p, file);
        return;
    }
    if (value.is_object())
        if (const auto it = value.find(tokens[at]); it != value.end())
            check(*it, tokens, at + 1, pointer + "/" + tokens[at], p, file);
}
} // namespace

void checkGltfTypes(std::string_view json, const std::filesystem::path& file)
{
    const nlohmann::json doc = nlohmann::json::parse(json, nullptr, false);
    if (doc.is_discarded())
        return;
    for (const Property& p : kSchema)
    {
        std::vector<std::string> tokens;
        for (std::string_view rest = p.pattern + 1; !rest.empty();)
        {
            const std::size_t slash = rest.find('/');
            tokens.emplace_back(rest.substr(0, slash));
            rest = slash == std::string_view::npos ? std::string_view() : rest.substr(slash + 1);
        }
        check(doc, tokens, 0, "", p, file);
    }
}
} // namespace rt
