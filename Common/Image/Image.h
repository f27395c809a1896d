#pragma once

#include <cstddef>
#include <vector>

#include "Math/Math.h"

namespace rt
{
/// A linear-radiance RGB image, row-major, row 0 at the top.
class Image
{
public:
    Image() = default;
    Image(int width, int height) : m_width(width), m_height(height), m_pixels(std::size_t(width) * height, vec3(0.0f)) {}

    int width() const { return m_width; }
    int height() const { return m_height; }
    std::size_t pixelCount() const { return m_pixels.size(); }
    bool empty() const { return m_pixels.empty(); }

    vec3& at(int x, int y) { return m_pixels[std::size_t(y) * m_width + x]; }
    const vec3& at(int x, int y) const { return m_pixels[std::size_t(y) * m_width + x]; }
    vec3* data() { return m_pixels.data(); }
    const vec3* data() const { return m_pixels.data(); }
    std::vector<vec3>& pixels() { return m_pixels; }
    const std::vector<vec3>& pixels() const { return m_pixels; }

    /// Mean of every pixel, per channel.
    vec3 mean() const;

private:
    int m_width = 0;
    int m_height = 0;
    std::vector<vec3> m_pixels;
};
} // namespace rt
