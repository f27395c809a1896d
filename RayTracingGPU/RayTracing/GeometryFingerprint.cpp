#include "RayTracing/GeometryFingerprint.h"

#include <cstring>
#include <vector>

namespace rt::gpu
{
namespace
{
/// A streaming 64-bit hash of bytes, eight at a time (xxHash64's round and final mix: Collet, xxHash,
/// https://github.com/Cyan4973/xxHash). Not cryptographic: scenes are not adversaries.
class Hasher
{
public:
    void bytes(const void* data, std::size_t size)
    {
        const auto* p = static_cast<const unsigned char*>(data);
        std::size_t i = 0;
        for (; i + 8 <= size; i += 8)
        {
            std::uint64_t word;
            std::memcpy(&word, p + i, 8);
            round(word);
        }
        std::uint64_t tail = 0;
        if (size > i)
            std::memcpy(&tail, p + i, size - i);
        round(tail ^ (std::uint64_t(size - i) << 56));
        m_length += size;
    }

    template <typename T>
    void array(const std::vector<T>& values)
    {
        value(std::uint64_t(values.size())); // [a][bc] and [ab][c] differ
        bytes(values.data(), values.size() * sizeof(T));
    }

    template <typename T>
    void value(const T& v)
    {
        bytes(&v, sizeof(T));
    }

    std::uint64_t digest() const
    {
        std::uint64_t h = m_state ^ m_length;
        h ^= h >> 33;
        h *= kPrime2;
        h ^= h >> 29;
        h *= kPrime3;
        h ^= h >> 32;
        return h;
    }

private:
    static constexpr std::uint64_t kPrime1 = 0x9E3779B185EBCA87ull;
    static constexpr std::uint64_t kPrime2 = 0xC2B2AE3D27D4EB4Full;
    static constexpr std::uint64_t kPrime3 = 0x165667B19E3779F9ull;

    void round(std::uint64_t word)
    {
        std::uint64_t k = word * kPrime2;
        k = (k << 31) | (k >> 33);
        k *= kPrime1;
        m_state ^= k;
        m_state = ((m_state << 27) | (m_state >> 37)) * kPrime1 + kPrime3;
    }

    std::uint64_t m_state = 0x27D4EB2F165667C5ull;
    std::uint64_t m_length = 0;
};
} // namespace

GeometryFingerprint fingerprintOf(const SceneLayout& layout)
{
    Hasher blases;
    blases.array(layout.positions);
    blases.array(layout.triangles);
    blases.array(layout.aabbs);
    blases.value(std::uint64_t(layout.blases.size()));
    for (const BlasDesc& b : layout.blases) // field by field: no padding bytes hashed
        for (const std::uint32_t v : {static_cast<std::uint32_t>(b.kind), b.firstVertex, b.vertexCount, b.firstTriangle,
                                      b.triangleCount, b.firstSphereAabb, b.sphereCount, b.firstMediumAabb,
                                      b.mediumCount})
            blases.value(v);

    Hasher tlas;
    tlas.value(blases.digest()); // new BLASes have new addresses: the TLAS follows them
    tlas.value(std::uint64_t(layout.instances.size()));
    for (const TlasInstanceDesc& t : layout.instances)
    {
        tlas.value(t.blas);
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 3; ++r) // the 3x4 the TLAS takes
                tlas.value(t.worldFromObject[c][r]);
        tlas.value(t.record);
        tlas.value(t.hitGroup);
    }
    return {blases.digest(), tlas.digest()};
}
} // namespace rt::gpu
