// 64-bit FNV-1a (Fowler, Noll and Vo): the on-disk caches' keys and the scene fingerprint hash their JSON text and
// data with it, so that a file name is the same on every run and platform (std::hash is neither).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include <spdlog/fmt/fmt.h>

namespace rt::compare
{
class Fnv1a
{
public:
    void bytes(const void* data, std::size_t size)
    {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i)
            m_hash = (m_hash ^ p[i]) * 0x100000001b3ull;
    }
    template <typename T> void value(const T& v)
    {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes(&v, sizeof v);
    }
    template <typename T> void vector(const std::vector<T>& v)
    {
        value(v.size());
        if (!v.empty())
            bytes(v.data(), v.size() * sizeof(T));
    }
    void string(const std::string& s)
    {
        value(s.size());
        bytes(s.data(), s.size());
    }
    std::uint64_t hash() const { return m_hash; }

private:
    std::uint64_t m_hash = 0xcbf29ce484222325ull;
};

inline std::string hex(std::uint64_t v) { return fmt::format("{:016x}", v); }

/// The hash of `text` as 16 hex digits: a cache entry's file name.
inline std::string fnv1aHex(const std::string& text)
{
    Fnv1a h;
    h.string(text);
    return hex(h.hash());
}
} // namespace rt::compare
