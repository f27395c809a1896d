#include "Image/Image.h"

namespace rt
{
vec3 Image::mean() const
{
    dvec3 sum(0.0);
    for (const vec3& p : m_pixels)
        sum += dvec3(p);
    return m_pixels.empty() ? vec3(0.0f) : vec3(sum / double(m_pixels.size()));
}
} // namespace rt
