// Texture evaluation (RTTNW §4-5), one function per TextureType behind a switch; the GLSL twins are in
// Shaders/Textures/. Colours are linear RGB.
#pragma once

#include <algorithm>
#include <cmath>

#include "Image/ImageIO.h"
#include "Scene/Perlin.h"
#include "Scene/Scene.h"

namespace rt::cpu
{
/// 3-D checker in world space: cells of size `scale`, even cells color0.
inline vec3 checkerTexture(const TextureData& t, const vec3& p)
{
    const vec3 c = glm::floor(p / t.scale);
    const int sum = static_cast<int>(c.x) + static_cast<int>(c.y) + static_cast<int>(c.z);
    return (sum & 1) == 0 ? t.color0 : t.color1;
}

/// Nearest texel at (u, v), v = 0 at the bottom of the image; sRGB texels decoded to linear.
inline vec3 imageTexture(const ImageData& image, const vec2& uv)
{
    const float u = std::clamp(uv.x, 0.0f, 1.0f);
    const float v = 1.0f - std::clamp(uv.y, 0.0f, 1.0f);
    const int i = std::min(static_cast<int>(u * static_cast<float>(image.width)), image.width - 1);
    const int j = std::min(static_cast<int>(v * static_cast<float>(image.height)), image.height - 1);
    const std::uint8_t* texel = &image.rgba[(std::size_t(j) * image.width + i) * 4];
    return {srgb8ToLinear(texel[0]), srgb8ToLinear(texel[1]), srgb8ToLinear(texel[2])};
}

inline vec3 evalTexture(const Scene& scene, std::uint32_t index, const vec2& uv, const vec3& p)
{
    const TextureData& t = scene.textures[index];
    switch (t.type)
    {
    case TextureType::Solid: return t.color0;
    case TextureType::Checker: return checkerTexture(t, p);
    case TextureType::Image: return imageTexture(scene.images[t.image], uv);
    case TextureType::Noise: return vec3(0.5f * (1.0f + perlinNoise(perlinTables(), t.scale * p)));
    case TextureType::Turbulence: return vec3(perlinTurbulence(perlinTables(), t.scale * p, 7));
    case TextureType::Marble:
        // The books' code turbulates the unscaled point (RTTNW §5.8, v3 and v4 alike); scaling it as well
        // gives fine-grained noise instead of the books' broad veins.
        return vec3(0.5f * (1.0f + std::sin(t.scale * p.z + 10.0f * perlinTurbulence(perlinTables(), p, 7))));
    }
    return vec3(0.0f);
}
} // namespace rt::cpu
