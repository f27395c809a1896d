// A small glTF 2.0 writer for tests: meshes from triangles (float positions, normals and uvs; indices of any
// width or none; any primitive mode), nodes with matrices or TRS, materials, cameras and PNG images, written as
// a .gltf with its .bin beside it, a .gltf with everything in data URIs, or a .glb. Values the tests want
// wrong on purpose are written through json() after the fact.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "Math/Math.h"

namespace rt::test
{
class GltfWriter
{
public:
    // Component types (glTF 2.0 §3.6.2.2) and primitive modes (§3.7.2.1).
    static constexpr int kUnsignedByte = 5121;
    static constexpr int kUnsignedShort = 5123;
    static constexpr int kUnsignedInt = 5125;
    static constexpr int kFloat = 5126;
    static constexpr int kNoIndices = 0;
    static constexpr int kTriangles = 4;

    struct Primitive
    {
        std::vector<vec3> positions;
        std::vector<vec3> normals; // empty or one per position
        std::vector<vec2> uvs; // empty or one per position (glTF's: v down the image)
        std::vector<std::uint32_t> indices; // written when indexType is not kNoIndices
        int indexType = kUnsignedInt;
        int material = -1;
        int mode = kTriangles;
    };

    GltfWriter() { m_doc["asset"] = {{"version", "2.0"}, {"generator", "rt tests"}}; }

    nlohmann::json& json() { return m_doc; }
    const std::vector<std::uint8_t>& bin() const { return m_bin; }

    /// Appends `bytes` to the binary buffer (4-byte aligned) as a new bufferView; returns its index.
    int bufferView(const void* data, std::size_t bytes, std::size_t stride = 0)
    {
        while (m_bin.size() % 4 != 0)
            m_bin.push_back(0);
        nlohmann::json view = {{"buffer", 0}, {"byteOffset", m_bin.size()}, {"byteLength", bytes}};
        if (stride != 0)
            view["byteStride"] = stride;
        const auto* p = static_cast<const std::uint8_t*>(data);
        m_bin.insert(m_bin.end(), p, p + bytes);
        return append("bufferViews", view);
    }

    /// An accessor of float vectors (`components` per element: 1, 2 or 3), with min/max for positions.
    int floatAccessor(const float* values, std::size_t count, int components)
    {
        static const char* kTypes[] = {"", "SCALAR", "VEC2", "VEC3", "VEC4"};
        const int view = bufferView(values, count * components * sizeof(float));
        nlohmann::json a = {{"bufferView", view}, {"componentType", kFloat}, {"count", count}, {"type", kTypes[components]}};
        if (components == 3 && count > 0)
        {
            std::vector<float> lo(3, values[0]), hi(3, values[0]);
            for (std::size_t i = 0; i < count; ++i)
                for (int c = 0; c < 3; ++c)
                {
                    lo[c] = std::min(lo[c], values[3 * i + c]);
                    hi[c] = std::max(hi[c], values[3 * i + c]);
                }
            a["min"] = lo;
            a["max"] = hi;
        }
        return append("accessors", a);
    }

    /// A SCALAR accessor of `indices` stored as `componentType` (each must fit).
    int indexAccessor(const std::vector<std::uint32_t>& indices, int componentType)
    {
        std::vector<std::uint8_t> bytes;
        const std::size_t width = componentType == kUnsignedByte ? 1 : componentType == kUnsignedShort ? 2 : 4;
        for (std::uint32_t i : indices)
            for (std::size_t b = 0; b < width; ++b)
                bytes.push_back(static_cast<std::uint8_t>(i >> (8 * b)));
        const int view = bufferView(bytes.data(), bytes.size());
        return append("accessors", {{"bufferView", view},
                                    {"componentType", componentType},
                                    {"count", indices.size()},
                                    {"type", "SCALAR"}});
    }

    nlohmann::json primitive(const Primitive& p)
    {
        nlohmann::json out;
        out["attributes"]["POSITION"] = floatAccessor(&p.positions[0].x, p.positions.size(), 3);
        if (!p.normals.empty())
            out["attributes"]["NORMAL"] = floatAccessor(&p.normals[0].x, p.normals.size(), 3);
        if (!p.uvs.empty())
            out["attributes"]["TEXCOORD_0"] = floatAccessor(&p.uvs[0].x, p.uvs.size(), 2);
        if (p.indexType != kNoIndices)
            out["indices"] = indexAccessor(p.indices, p.indexType);
        if (p.material >= 0)
            out["material"] = p.material;
        if (p.mode != kTriangles)
            out["mode"] = p.mode;
        return out;
    }

    int mesh(const std::vector<Primitive>& primitives, const std::string& name = "")
    {
        nlohmann::json m = {{"primitives", nlohmann::json::array()}};
        for (const Primitive& p : primitives)
            m["primitives"].push_back(primitive(p));
        if (!name.empty())
            m["name"] = name;
        return append("meshes", m);
    }

    int material(const nlohmann::json& m) { return append("materials", m); }
    int camera(const nlohmann::json& c) { return append("cameras", c); }
    int node(const nlohmann::json& n) { return append("nodes", n); }

    /// A perspective camera of `yfov` radians (aspectRatio only if > 0).
    int perspective(double yfov, double aspectRatio = 0.0)
    {
        nlohmann::json p = {{"yfov", yfov}, {"znear", 0.01}};
        if (aspectRatio > 0.0)
            p["aspectRatio"] = aspectRatio;
        return camera({{"type", "perspective"}, {"perspective", p}});
    }

    /// An image of PNG (or other) bytes: in the buffer (as a .glb keeps it), or in a data URI.
    int imageInBuffer(const std::vector<std::uint8_t>& png)
    {
        return append("images", {{"bufferView", bufferView(png.data(), png.size())}, {"mimeType", "image/png"}});
    }
    int imageDataUri(const std::vector<std::uint8_t>& png)
    {
        return append("images", {{"uri", "data:image/png;base64," + base64(png)}});
    }
    int imageFile(const std::string& uri) { return append("images", {{"uri", uri}}); }
    int texture(int image) { return append("textures", {{"source", image}}); }

    /// The scene to render: `roots` as scene 0, the default scene.
    void scene(const std::vector<int>& roots)
    {
        m_doc["scenes"] = nlohmann::json::array({{{"nodes", roots}}});
        m_doc["scene"] = 0;
    }

    /// NAME.gltf with its buffer in NAME.bin beside it.
    std::filesystem::path writeGltf(const std::filesystem::path& dir, const std::string& name)
    {
        nlohmann::json doc = withBuffer(name + ".bin");
        std::ofstream(dir / (name + ".bin"), std::ios::binary)
            .write(reinterpret_cast<const char*>(m_bin.data()), static_cast<std::streamsize>(m_bin.size()));
        return writeText(dir / (name + ".gltf"), doc.dump(1));
    }

    /// NAME.gltf with its buffer in a data URI.
    std::filesystem::path writeEmbedded(const std::filesystem::path& dir, const std::string& name)
    {
        return writeText(dir / (name + ".gltf"),
                         withBuffer("data:application/octet-stream;base64," + base64(m_bin)).dump(1));
    }

    /// NAME.glb: header, JSON chunk, BIN chunk (glTF 2.0 §4).
    std::filesystem::path writeGlb(const std::filesystem::path& dir, const std::string& name)
    {
        const std::filesystem::path file = dir / (name + ".glb");
        const std::vector<std::uint8_t> bytes = glbBytes();
        std::ofstream(file, std::ios::binary)
            .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
        return file;
    }

    std::vector<std::uint8_t> glbBytes() const
    {
        std::string text = withBuffer("").dump();
        while (text.size() % 4 != 0)
            text += ' ';
        std::vector<std::uint8_t> bin = m_bin;
        while (bin.size() % 4 != 0)
            bin.push_back(0);
        std::vector<std::uint8_t> out = {'g', 'l', 'T', 'F'};
        const auto u32 = [&out](std::uint32_t v) {
            for (int b = 0; b < 4; ++b)
                out.push_back(static_cast<std::uint8_t>(v >> (8 * b)));
        };
        const auto total = static_cast<std::uint32_t>(12 + 8 + text.size() + (bin.empty() ? 0 : 8 + bin.size()));
        u32(2);
        u32(total);
        u32(static_cast<std::uint32_t>(text.size()));
        u32(0x4E4F534A); // JSON
        out.insert(out.end(), text.begin(), text.end());
        if (!bin.empty())
        {
            u32(static_cast<std::uint32_t>(bin.size()));
            u32(0x004E4942); // BIN
            out.insert(out.end(), bin.begin(), bin.end());
        }
        return out;
    }

    static std::string base64(const std::vector<std::uint8_t>& bytes)
    {
        static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
        std::string out;
        for (std::size_t i = 0; i < bytes.size(); i += 3)
        {
            const std::uint32_t n = (std::uint32_t(bytes[i]) << 16) |
                                    (i + 1 < bytes.size() ? std::uint32_t(bytes[i + 1]) << 8 : 0) |
                                    (i + 2 < bytes.size() ? std::uint32_t(bytes[i + 2]) : 0);
            out += kDigits[(n >> 18) & 63];
            out += kDigits[(n >> 12) & 63];
            out += i + 1 < bytes.size() ? kDigits[(n >> 6) & 63] : '=';
            out += i + 2 < bytes.size() ? kDigits[n & 63] : '=';
        }
        return out;
    }

    static std::vector<std::uint8_t> readBytes(const std::filesystem::path& file)
    {
        std::ifstream in(file, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }

private:
    int append(const char* list, const nlohmann::json& value)
    {
        m_doc[list].push_back(value);
        return static_cast<int>(m_doc[list].size() - 1);
    }

    /// The document with buffer 0 (at `uri`; none for a .glb's BIN chunk) if anything is in the buffer.
    nlohmann::json withBuffer(const std::string& uri) const
    {
        nlohmann::json doc = m_doc;
        if (!m_bin.empty() && !doc.contains("buffers"))
        {
            nlohmann::json buffer = {{"byteLength", m_bin.size()}};
            if (!uri.empty())
                buffer["uri"] = uri;
            doc["buffers"] = nlohmann::json::array({buffer});
        }
        return doc;
    }

    static std::filesystem::path writeText(const std::filesystem::path& file, const std::string& text)
    {
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }

    nlohmann::json m_doc;
    std::vector<std::uint8_t> m_bin;
};
} // namespace rt::test
