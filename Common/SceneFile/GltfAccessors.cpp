#include "SceneFile/GltfAccessors.h"

#include <algorithm>
#include <bit>
#include <cstring>

#include <spdlog/fmt/fmt.h>

namespace rt
{
namespace
{
static_assert(std::endian::native == std::endian::little, "glTF's data is little-endian: add byte swaps here");

const char* typeName(int type)
{
    switch (type)
    {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "an unknown type";
    }
}

/// Components of an accessor type (0 for an unknown one).
int componentCount(int type)
{
    switch (type)
    {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
    }
}

/// Bytes of a component type (0 for one glTF does not define).
std::size_t componentBytes(int componentType)
{
    switch (componentType)
    {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
    }
}

template <typename T>
T load(const unsigned char* p)
{
    T v;
    std::memcpy(&v, p, sizeof(T));
    return v;
}

/// One component at `p`, normalised as the spec's equations say when `normalized`.
double component(const unsigned char* p, int componentType, bool normalized)
{
    switch (componentType)
    {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
        return normalized ? std::max(load<std::int8_t>(p) / 127.0, -1.0) : load<std::int8_t>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return normalized ? load<std::uint8_t>(p) / 255.0 : load<std::uint8_t>(p);
    case TINYGLTF_COMPONENT_TYPE_SHORT:
        return normalized ? std::max(load<std::int16_t>(p) / 32767.0, -1.0) : load<std::int16_t>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return normalized ? load<std::uint16_t>(p) / 65535.0 : load<std::uint16_t>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return normalized ? load<std::uint32_t>(p) / 4294967295.0 : load<std::uint32_t>(p);
    default: return load<float>(p);
    }
}

/// `count` elements of `elementBytes` bytes, `stride` apart, from `first`: bytes already checked.
struct Run
{
    const unsigned char* first = nullptr;
    std::size_t stride = 0;
    std::size_t count = 0;

    const unsigned char* operator[](std::size_t i) const { return first + i * stride; }
};

/// The run of `count` elements of `elementBytes` starting `byteOffset` bytes into bufferView `viewIndex`,
/// checked to lie inside the view and the view inside its buffer. `where` names the referring value.
Run checkedRun(const GltfDocument& doc, const std::string& where, int viewIndex, std::size_t byteOffset,
               std::size_t count, std::size_t elementBytes, bool strided)
{
    const tinygltf::Model& m = doc.model;
    if (viewIndex < 0 || static_cast<std::size_t>(viewIndex) >= m.bufferViews.size())
        doc.fail(where, fmt::format("bufferView {} does not exist (the file has {})", viewIndex, m.bufferViews.size()));
    const tinygltf::BufferView& view = m.bufferViews[static_cast<std::size_t>(viewIndex)];
    const std::string viewPointer = fmt::format("/bufferViews/{}", viewIndex);
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= m.buffers.size())
        doc.fail(viewPointer + "/buffer",
                 fmt::format("buffer {} does not exist (the file has {})", view.buffer, m.buffers.size()));
    const std::size_t bufferBytes = m.buffers[static_cast<std::size_t>(view.buffer)].data.size();
    if (view.byteOffset > bufferBytes || view.byteLength > bufferBytes - view.byteOffset)
        doc.fail(viewPointer, fmt::format("bytes {} to {} lie beyond buffer {} ({} bytes)", view.byteOffset,
                                          view.byteOffset + view.byteLength, view.buffer, bufferBytes));
    const std::size_t stride = strided && view.byteStride != 0 ? view.byteStride : elementBytes;
    if (stride < elementBytes)
        doc.fail(viewPointer + "/byteStride",
                 fmt::format("a stride of {} bytes is shorter than an element ({} bytes)", stride, elementBytes));
    // The last element ends at byteOffset + (count - 1) stride + elementBytes <= byteLength, without overflow.
    const std::size_t room = byteOffset <= view.byteLength ? view.byteLength - byteOffset : 0;
    if (count > 0 &&
        (byteOffset > view.byteLength || count - 1 > room / stride || room - (count - 1) * stride < elementBytes))
        doc.fail(where, fmt::format("{} elements of {} bytes from byte {} of bufferView {} (stride {}) overrun its "
                                    "{} bytes",
                                    count, elementBytes, byteOffset, viewIndex, stride, view.byteLength));
    const unsigned char* base = m.buffers[static_cast<std::size_t>(view.buffer)].data.data();
    return {count > 0 ? base + view.byteOffset + byteOffset : nullptr, stride, count};
}

/// The sparse substitutions of `accessor` (§3.6.2.3) applied to `out` (`components` per element).
void applySparse(const GltfDocument& doc, const tinygltf::Accessor& a, const std::string& pointer, int components,
                 std::vector<double>& out)
{
    const auto& sparse = a.sparse;
    const std::string where = pointer + "/sparse";
    if (sparse.count < 1 || static_cast<std::size_t>(sparse.count) > a.count)
        doc.fail(where + "/count", fmt::format("expected 1 to {} substitutions, got {}", a.count, sparse.count));
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0)
        doc.fail(where, "a byteOffset is negative");
    const std::size_t indexBytes = componentBytes(sparse.indices.componentType);
    if (indexBytes == 0 || sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
        sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_SHORT ||
        sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT)
        doc.fail(where + "/indices/componentType",
                 fmt::format("expected UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, got {}",
                             sparse.indices.componentType));
    const auto n = static_cast<std::size_t>(sparse.count);
    const Run indices = checkedRun(doc, where + "/indices", sparse.indices.bufferView,
                                   static_cast<std::size_t>(sparse.indices.byteOffset), n, indexBytes, false);
    const std::size_t bytes = componentBytes(a.componentType);
    const Run values = checkedRun(doc, where + "/values", sparse.values.bufferView,
                                  static_cast<std::size_t>(sparse.values.byteOffset), n, bytes * components, false);
    for (std::size_t i = 0; i < n; ++i)
    {
        const auto target = static_cast<std::size_t>(component(indices[i], sparse.indices.componentType, false));
        if (target >= a.count)
            doc.fail(where + "/indices", fmt::format("substitution {} targets element {} of {}", i, target, a.count));
        for (int c = 0; c < components; ++c)
            out[target * components + c] = component(values[i] + c * bytes, a.componentType, a.normalized);
    }
}

std::vector<double> read(const GltfDocument& doc, int index, int components, const std::string& usedAs,
                         bool normalize)
{
    const tinygltf::Model& m = doc.model;
    if (index < 0 || static_cast<std::size_t>(index) >= m.accessors.size())
        doc.fail(usedAs, fmt::format("accessor {} does not exist (the file has {})", index, m.accessors.size()));
    const tinygltf::Accessor& a = m.accessors[static_cast<std::size_t>(index)];
    const std::string pointer = fmt::format("/accessors/{}", index);
    if (componentCount(a.type) != components)
        doc.fail(pointer + "/type", fmt::format("{} uses it as {} numbers per element, but its type is {}", usedAs,
                                                components, typeName(a.type)));
    const std::size_t bytes = componentBytes(a.componentType);
    if (bytes == 0)
        doc.fail(pointer + "/componentType", fmt::format("unknown component type {}", a.componentType));
    const bool normalized = normalize && a.normalized;
    std::vector<double> out;
    if (a.bufferView < 0)
    {
        if (a.count > kMaxGltfZeroAccessorCount)
            doc.fail(pointer + "/count", fmt::format("{} elements without a bufferView (at most {})", a.count,
                                                     kMaxGltfZeroAccessorCount));
        out.assign(a.count * components, 0.0);
    }
    else
    {
        const Run run = checkedRun(doc, pointer, a.bufferView, a.byteOffset, a.count, bytes * components, true);
        out.resize(a.count * components);
        double* o = out.data();
        for (std::size_t i = 0; i < a.count; ++i)
        {
            const unsigned char* e = run[i];
            if (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) // the common case, without the switch
                for (int c = 0; c < components; ++c)
                    *o++ = load<float>(e + 4 * c);
            else
                for (int c = 0; c < components; ++c)
                    *o++ = component(e + c * bytes, a.componentType, normalized);
        }
    }
    if (a.sparse.isSparse)
        applySparse(doc, a, pointer, components, out);
    return out;
}
} // namespace

std::vector<double> readGltfAccessor(const GltfDocument& doc, int index, int components, const std::string& usedAs)
{
    return read(doc, index, components, usedAs, true);
}

std::vector<std::uint32_t> readGltfIndices(const GltfDocument& doc, int index, std::size_t vertexCount,
                                           const std::string& usedAs)
{
    const std::vector<double> values = read(doc, index, 1, usedAs, false);
    const int type = doc.model.accessors[static_cast<std::size_t>(index)].componentType;
    if (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        doc.fail(fmt::format("/accessors/{}/componentType", index),
                 fmt::format("{} needs UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT indices, got {}", usedAs, type));
    std::vector<std::uint32_t> out(values.size());
    for (std::size_t i = 0; i < values.size(); ++i)
    {
        if (!(values[i] < static_cast<double>(vertexCount)))
            doc.fail(fmt::format("/accessors/{}", index),
                     fmt::format("index {} is {}, beyond the {} vertices of the primitive ({})", i, values[i],
                                 vertexCount, usedAs));
        out[i] = static_cast<std::uint32_t>(values[i]);
    }
    return out;
}
} // namespace rt
