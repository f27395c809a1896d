// fmt formatters for the Common types that appear in messages (logs, errors, RT_CHECK values):
//   vec2 / vec3 / vec4 (any glm::vec)  "(1, 2.5, -3)"; a float spec applies to each component: "{:.2f}"
//   Aabb                               "[(0, 0, 0) .. (1, 2, 3)]"; the spec applies to each component
//   every named enum (Render/NamedEnum.h)  its word ("gpu", "stratified", "mixture")
//   RenderSettings                     "spp 16, depth 50, width 600, aspect 1, sampling random, ..., seed 0
//                                       (600x600)": the settings table's names and words
// The names and the settings' line take string specs ("{:>10}"). Written for fmt 9 (Debian 12's, which
// spdlog uses) and later.
#pragma once

#include <string>
#include <string_view>

#include <spdlog/fmt/fmt.h>

#include "Math/Aabb.h"
#include "Math/Math.h"
#include "Render/RenderSettings.h"
#include "Render/SettingsTable.h"

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

/// Every named enum (Render/NamedEnum.h) formats as its word.
template <rt::NamedEnum Enum>
struct fmt::formatter<Enum> : fmt::formatter<std::string_view>
{
    template <typename FormatContext>
    auto format(Enum value, FormatContext& ctx) const -> decltype(ctx.out())
    {
        return fmt::formatter<std::string_view>::format(rt::toString(value), ctx);
    }
};

/// Every setting as "NAME VALUE", in the settings table's order, then the height.
template <>
struct fmt::formatter<rt::RenderSettings> : fmt::formatter<std::string_view>
{
    template <typename FormatContext>
    auto format(const rt::RenderSettings& s, FormatContext& ctx) const -> decltype(ctx.out())
    {
        std::string text;
        for (const rt::Setting& setting : rt::settingsTable())
            if (setting.used(s)) // the settings the render reads: no light sampler for bsdf, no restir-* for nee
                text += fmt::format("{}{} {}", text.empty() ? "" : ", ", setting.name, setting.text(s));
        text += fmt::format(" ({}x{})", s.width, s.height());
        return fmt::formatter<std::string_view>::format(text, ctx);
    }
};
