// fmt formatters for the Common types that appear in messages (logs, errors, RT_CHECK values):
//   vec2 / vec3 / vec4 (any glm::vec)  "(1, 2.5, -3)"; a float spec applies to each component: "{:.2f}"
//   Aabb                               "[(0, 0, 0) .. (1, 2, 3)]"; the spec applies to each component
//   EngineKind, PixelSampling, Estimator  their toString() names ("gpu", "stratified", "mixture")
//   RenderSettings                     "spp 16, depth 50, 600x600, random, mixture, unidirectional light on,
//                                       seed 0"
// The names and the settings' line take string specs ("{:>10}"). Written for fmt 9 (Debian 12's, which
// spdlog uses) and later.
#pragma once

#include <string>
#include <string_view>

#include <spdlog/fmt/fmt.h>

#include "Math/Aabb.h"
#include "Math/Math.h"
#include "Render/RenderSettings.h"

template <glm::length_t L, typename T, glm::qualifier Q>
struct fmt::formatter<glm::vec<L, T, Q>> : fmt::formatter<T>
{
    template <typename FormatContext>
    auto format(const glm::vec<L, T, Q>& v, FormatContext& ctx) const -> decltype(ctx.out())
    {
        auto out = ctx.out();
        *out++ = '(';
        for (glm::length_t i = 0; i < L; ++i)
        {
            if (i > 0)
            {
                *out++ = ',';
                *out++ = ' ';
            }
            ctx.advance_to(out);
            out = fmt::formatter<T>::format(v[i], ctx);
        }
        *out++ = ')';
        return out;
    }
};

template <>
struct fmt::formatter<rt::Aabb> : fmt::formatter<rt::vec3>
{
    template <typename FormatContext>
    auto format(const rt::Aabb& box, FormatContext& ctx) const -> decltype(ctx.out())
    {
        auto out = ctx.out();
        *out++ = '[';
        ctx.advance_to(out);
        out = fmt::formatter<rt::vec3>::format(box.min, ctx);
        for (const char c : std::string_view(" .. "))
            *out++ = c;
        ctx.advance_to(out);
        out = fmt::formatter<rt::vec3>::format(box.max, ctx);
        *out++ = ']';
        return out;
    }
};

namespace rt::detail
{
/// The enums' formatter: their toString() name, through the string_view formatter.
template <typename Enum>
struct NamedEnumFormatter : fmt::formatter<std::string_view>
{
    template <typename FormatContext>
    auto format(Enum value, FormatContext& ctx) const -> decltype(ctx.out())
    {
        return fmt::formatter<std::string_view>::format(rt::toString(value), ctx);
    }
};
} // namespace rt::detail

template <>
struct fmt::formatter<rt::EngineKind> : rt::detail::NamedEnumFormatter<rt::EngineKind>
{
};

template <>
struct fmt::formatter<rt::PixelSampling> : rt::detail::NamedEnumFormatter<rt::PixelSampling>
{
};

template <>
struct fmt::formatter<rt::Estimator> : rt::detail::NamedEnumFormatter<rt::Estimator>
{
};

template <>
struct fmt::formatter<rt::RenderSettings> : fmt::formatter<std::string_view>
{
    template <typename FormatContext>
    auto format(const rt::RenderSettings& s, FormatContext& ctx) const -> decltype(ctx.out())
    {
        const std::string text = fmt::format(
            "spp {}, depth {}, {}x{}, {}, {}, {} light sampling, {} light selection, Russian roulette {}, "
            "unidirectional light {}, seed {}",
            s.spp, s.depth, s.width, s.height(), s.sampling, s.estimator, rt::toString(s.lightSampler),
            rt::toString(s.lightSelection),
            s.russianRoulette ? "on" : "off",
            s.unidirectionalLight ? "on" : "off", s.seed);
        return fmt::formatter<std::string_view>::format(text, ctx);
    }
};
