#include "Render/SettingsTable.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include <nlohmann/json.hpp>
#include <spdlog/fmt/fmt.h>
#include <spdlog/fmt/ranges.h>

#include "Cli/ValueParsing.h"
#include "Error.h"
#include "Shared/Estimator.h"

namespace rt
{
namespace
{
template <auto Member>
using FieldType = std::remove_cvref_t<decltype(std::declval<RenderSettings&>().*Member)>;

template <auto Member>
std::string fieldText(const RenderSettings& s)
{
    using T = FieldType<Member>;
    const T& v = s.*Member;
    if constexpr (std::is_same_v<T, bool>)
        return v ? "on" : "off";
    else if constexpr (std::is_enum_v<T>)
        return toString(v);
    else
        return fmt::format("{}", v); // floats: the shortest text that reads back the same value
}

template <auto Member>
nlohmann::json fieldJson(const RenderSettings& s)
{
    using T = FieldType<Member>;
    if constexpr (std::is_enum_v<T>)
        return toString(s.*Member);
    else
        return s.*Member;
}

template <auto Member>
bool assignField(const Setting& setting, RenderSettings& s, std::string_view text)
{
    using T = FieldType<Member>;
    if constexpr (std::is_same_v<T, bool>)
    {
        const auto on = parseOnOff(text);
        if (on)
            s.*Member = *on;
        return on.has_value();
    }
    else if constexpr (std::is_enum_v<T>)
    {
        const auto value = parseName<T>(text);
        if (value)
            s.*Member = *value;
        return value.has_value();
    }
    else if constexpr (std::is_integral_v<T>)
    {
        const auto value = parseInteger(text);
        if (!value || double(*value) < setting.minimum || double(*value) > setting.maximum)
            return false;
        s.*Member = static_cast<T>(*value);
        return true;
    }
    else
    {
        // Read in double, so that 1e308 is refused as beyond a float rather than read as inf.
        const std::string copy(text);
        char* end = nullptr;
        const double value = std::strtod(copy.c_str(), &end);
        if (copy.empty() || end != copy.c_str() + copy.size() || !std::isfinite(value) || !(value > setting.minimum) ||
            !(value <= setting.maximum))
            return false;
        s.*Member = static_cast<T>(value);
        return true;
    }
}

template <auto Member>
void copyField(RenderSettings& to, const RenderSettings& from)
{
    to.*Member = from.*Member;
}

template <auto Member>
double fieldNumber(const RenderSettings& s)
{
    return static_cast<double>(s.*Member);
}

template <typename Enum>
std::vector<std::string_view> words()
{
    std::vector<std::string_view> out;
    for (const EnumName<Enum>& n : EnumNames<Enum>::values)
        out.emplace_back(n.name);
    return out;
}

/// A setting's uniform is its field as the shaders hold it: a uint for on/off and integers, the tag for an enum.
template <auto Member, auto Uniform>
void uniformField(const RenderSettings& s, shader::RenderUniforms& u)
{
    using T = std::remove_cvref_t<decltype(u.*Uniform)>;
    u.*Uniform = static_cast<T>(s.*Member);
}

/// The entry of the field `Member`: its type, choices and accessors from the field's C++ type, and its writer
/// into the uniform `Uniform` where it has one.
template <auto Member, auto Uniform = nullptr>
Setting field(Setting s)
{
    if constexpr (Uniform != nullptr)
        s.toUniforms = &uniformField<Member, Uniform>;
    using T = FieldType<Member>;
    if constexpr (std::is_same_v<T, bool>)
        s.type = SettingType::OnOff;
    else if constexpr (std::is_enum_v<T>)
    {
        s.type = SettingType::Choice;
        s.choices = words<T>();
    }
    else if constexpr (std::is_integral_v<T>)
        s.type = SettingType::Integer;
    else
        s.type = SettingType::Real;
    s.text = &fieldText<Member>;
    s.json = &fieldJson<Member>;
    s.assign = &assignField<Member>;
    s.copy = &copyField<Member>;
    if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>)
        s.number = &fieldNumber<Member>;
    return s;
}

bool usesLights(const RenderSettings& s) { return shader::usesNee(s.estimator); }

bool usesRestir(const RenderSettings& s) { return s.estimator == Estimator::RestirDi; }

std::vector<Setting> makeTable()
{
    return {
        field<&RenderSettings::spp>({
            .name = "spp",
            .jsonKey = "spp",
            .label = "Samples per pixel",
            .help = "Samples per pixel, 1 to 16777216 (default: the scene's)",
            .tooltip = "samples per pixel of the render (stratified sampling rounds down to a square)",
            .minimum = 1,
            .maximum = kMaxSpp,
            .fromScene = true,
        }),
        field<&RenderSettings::depth, &shader::RenderUniforms::depth>({
            .name = "depth",
            .jsonKey = "depth",
            .label = "Max depth",
            .help = "Ray segments per path at most, the camera ray included: 1 sees only the emitters (default: the "
                    "scene's, usually 50)",
            .tooltip = "ray segments per path at most, the camera ray included",
            .minimum = 1,
            .maximum = std::numeric_limits<int>::max(),
            .fromScene = true,
        }),
        field<&RenderSettings::width>({
            .name = "width",
            .jsonKey = "width",
            .label = "Image width",
            .help = "Image width in pixels, 1 to 65536 (default: the scene's)",
            .tooltip = "image width in pixels",
            .minimum = 1,
            .maximum = kMaxImageSide,
            .fromScene = true,
        }),
        field<&RenderSettings::aspect>({
            .name = "aspect",
            .jsonKey = "aspect",
            .label = "Aspect ratio",
            .help = "Aspect ratio width/height, e.g. 1 or 1.7778 (default: the scene's)",
            .tooltip = "aspect ratio width / height",
            .minimum = 0.0,
            .maximum = double(std::numeric_limits<float>::max()),
            .fromScene = true,
        }),
        field<&RenderSettings::estimator, &shader::RenderUniforms::estimator>({
            .name = "estimator",
            .jsonKey = "estimator",
            .label = "Estimator",
            .help = "How a path gathers light (default: the scene's: nee-mis, or mixture for the books' scenes). "
                    "bsdf: follow sampled BSDF directions only (books 1-2); mixture: book 3's one-sample mix of "
                    "BSDF and light directions, no shadow rays; nee: a shadow ray to one sampled light at every "
                    "diffuse vertex, BSDF rays ignore the lights; nee-mis: NEE and BSDF rays both count, weighted "
                    "by the power heuristic; restir-di: at each camera path's first diffuse or glossy vertex, "
                    "direct light by spatiotemporal reservoir resampling (Bitterli et al. 2020: --restir-candidates, "
                    "--restir-spatial, --restir-radius, --restir-temporal-cap, --restir-biased), nee-mis beyond; "
                    "iterations of one sample per pixel",
            .tooltip = "bsdf: BSDF sampling only (books 1 and 2); mixture: book 3's mix of BSDF and light "
                       "directions, no shadow rays; nee: a shadow ray to one light per diffuse vertex; nee-mis: NEE "
                       "and BSDF rays weighted by the power heuristic; restir-di: reservoir resampling of direct light at "
                       "the first vertex, nee-mis beyond",
            .fromScene = true,
            .compareFlag = "--estimators",
        }),
        field<&RenderSettings::lightSampler, &shader::RenderUniforms::lightSampler>({
            .name = "light-sampler",
            .jsonKey = "light_sampler",
            .label = "Light sampler",
            .help = "How nee and nee-mis pick a point on a light: area (uniform over its surface), solid-angle "
                    "(uniform over the directions it covers: cones for spheres, spherical rectangles for "
                    "rectangular quads, spherical triangles (Arvo) for triangles of 3e-4 to 6.22 sr, area "
                    "where no solid-angle sampler applies) or projected (by the cosine over a sphere's cap "
                    "when it lies above the receiver's horizon, and over rectangles and triangles by a "
                    "bilinear warp of their spherical samplers; else as solid-angle). The mixture keeps "
                    "book 3's.",
            .tooltip = "how nee and nee-mis pick a point on a light: area: uniform over its surface; solid-angle: "
                       "uniform over the directions it covers; projected: by the cosine at the receiver",
            .compareFlag = "--light-samplers",
            .usedBy = &usesLights,
        }),
        field<&RenderSettings::lightSelection, &shader::RenderUniforms::lightSelection>({
            .name = "light-selection",
            .jsonKey = "light_selection",
            .label = "Light selection",
            .help = "Which light nee and nee-mis sample at a vertex: uniform (each of the N emitters 1/N), power "
                    "(in proportion to area x emitted luminance, by an alias table) or bvh (by a light BVH: in "
                    "proportion to a bound of what each group of emitters can contribute at the vertex, from its "
                    "power, distance, orientation and the receiver's horizon)",
            .tooltip = "which light nee and nee-mis sample: uniform (each 1/N), in proportion to its power, or by "
                       "a light BVH's bound of what it contributes at the vertex",
            .compareFlag = "--light-selections",
            .usedBy = &usesLights,
        }),
        field<&RenderSettings::restirCandidates, &shader::RenderUniforms::restirCandidates>({
            .name = "restir-candidates",
            .jsonKey = "restir_candidates",
            .label = "ReSTIR candidates",
            .help = "restir-di: light samples resampled per pixel and iteration, from the light selection and "
                    "sampler (M of Bitterli et al. 2020), 1 to 1024",
            .tooltip = "restir-di: light samples resampled per pixel and iteration",
            .minimum = 1,
            .maximum = 1024,
            .usedBy = &usesRestir,
        }),
        field<&RenderSettings::restirSpatial, &shader::RenderUniforms::restirSpatial>({
            .name = "restir-spatial",
            .jsonKey = "restir_spatial",
            .label = "ReSTIR neighbours",
            .help = "restir-di: neighbours' reservoirs combined per pixel and iteration (spatial reuse within "
                    "--restir-radius), 0 to 64",
            .tooltip = "restir-di: neighbours' reservoirs reused per pixel and iteration",
            .minimum = 0,
            .maximum = 64,
            .usedBy = &usesRestir,
        }),
        field<&RenderSettings::restirRadius, &shader::RenderUniforms::restirRadius>({
            .name = "restir-radius",
            .jsonKey = "restir_radius",
            .label = "ReSTIR radius",
            .help = "restir-di: spatial reuse draws its neighbours uniformly in a disk of this many pixels about the "
                    "pixel (Bitterli et al. 2020: 30 at 1920 x 1080, 1.6 % of the width; at 128 px lamp-room's image "
                    "had 0.78x the relMSE at 4 px: docs/notebook/PERFORMANCE.md §64), 1 to 1024",
            .tooltip = "restir-di: the radius in pixels spatial reuse draws its neighbours in",
            .minimum = 1,
            .maximum = 1024,
            .usedBy = &usesRestir,
        }),
        field<&RenderSettings::restirBiased, &shader::RenderUniforms::restirBiased>({
            .name = "restir-biased",
            .jsonKey = "restir_biased",
            .label = "ReSTIR biased",
            .help = "restir-di: on: the biased combination (1 / the inputs' summed M, Bitterli et al. 2020 Alg. 4), "
                    "without the shadow rays that find which inputs could have produced the chosen point; off: the "
                    "unbiased one (pairwise MIS over targets with visibility: docs/RESTIR.md)",
            .tooltip = "restir-di: on: cheaper, biased reuse (labelled biased in every output); off: unbiased",
            .usedBy = &usesRestir,
        }),
        field<&RenderSettings::restirTemporalCap, &shader::RenderUniforms::restirTemporalCap>({
            .name = "restir-temporal-cap",
            .jsonKey = "restir_temporal_cap",
            .label = "ReSTIR history",
            .help = "restir-di: temporal reuse's cap on the last iteration's M, in multiples of --restir-candidates "
                    "(Bitterli et al. 2020 recommend 20); 0 turns temporal reuse off. A long history lowers one "
                    "iteration's error but correlates the iterations a render adds up (docs/RESTIR.md), 0 to 1000",
            .tooltip = "restir-di: how much of the last iterations a pixel's reservoir keeps (x candidates); 0: none",
            .minimum = 0,
            .maximum = 1000,
            .usedBy = &usesRestir,
        }),
        field<&RenderSettings::sampling, &shader::RenderUniforms::sampling>({
            .name = "sampling",
            .jsonKey = "sampling",
            .label = "Pixel sampling",
            .help = "Pixel sampling: random (independent jitter), stratified (floor(sqrt(spp))^2 jittered strata), "
                    "accumulate (progressive 1-spp passes) or sobol (every 2D draw of a sample - pixel, lens, light "
                    "point, BSDF direction - an Owen-scrambled Sobol point over the pixel's samples, Burley 2020: "
                    "stratified at every power-of-two spp). Default: the scene's: sobol, or random for the books' "
                    "scenes",
            .tooltip = "random (the thesis' \"normal\"): spp jittered samples per pixel in one pass; accumulate (the "
                       "thesis' \"accumulation\"): 1-spp passes shown as they finish; stratified: floor(sqrt(spp))^2 "
                       "jittered strata; sobol: Owen-scrambled Sobol points",
            .fromScene = true,
            .compareFlag = "--samplings",
        }),
        field<&RenderSettings::russianRoulette, &shader::RenderUniforms::russianRoulette>({
            .name = "russian-roulette",
            .jsonKey = "russian_roulette",
            .label = "Russian roulette",
            .help = "From the third segment, a path whose throughput's largest component m fell below 1 ends at "
                    "random and the survivors are scaled up (unbiased; with bsdf and mixture a path ends after the "
                    "light its last direction finds): on: survival m (pbrt-v4's rule); sqrt: survival sqrt(m) "
                    "(Blender Cycles' rule: longer paths, less variance); off: paths run to --depth",
            .tooltip = "on: paths of low throughput m end at random with survival m, survivors scaled up "
                       "(unbiased); sqrt: survival sqrt(m) (Cycles); off: paths run to the depth",
            .compareFlag = "--roulettes",
            .compareTag = "rr",
        }),
        field<&RenderSettings::unidirectionalLight, &shader::RenderUniforms::unidirectionalLight>({
            .name = "unidirectional-light",
            .jsonKey = "unidirectional_light",
            .label = "Unidirectional light",
            .help = "on: emitters emit from their front face only; off: from both faces (default: the scene's)",
            .tooltip = "on: emitters emit from their front face only; off: from both faces",
            .fromScene = true,
        }),
        field<&RenderSettings::seed, &shader::RenderUniforms::seed>({
            .name = "seed",
            .jsonKey = "seed",
            .label = "Seed",
            .help = "Seed of the per-pixel, per-sample random streams (0..4294967295)",
            .tooltip = "seed of the random streams",
            .minimum = 0,
            .maximum = double(std::numeric_limits<std::uint32_t>::max()),
        }),
    };
}
} // namespace

std::string Setting::expected() const
{
    switch (type)
    {
    case SettingType::Integer:
        return fmt::format("an integer in [{}, {}]", static_cast<long long>(minimum), static_cast<long long>(maximum));
    case SettingType::Real:
        return fmt::format("a number > {} that a float can hold", minimum);
    case SettingType::OnOff: return "on or off";
    case SettingType::Choice:
    {
        std::string out;
        for (std::size_t i = 0; i < choices.size(); ++i)
        {
            if (i > 0)
                out += i + 1 == choices.size() ? " or " : ", ";
            out += choices[i];
        }
        return out;
    }
    }
    return "?";
}

std::string Setting::placeholder() const
{
    switch (type)
    {
    case SettingType::Integer: return "N";
    case SettingType::Real: return "X";
    case SettingType::OnOff: return "on|off";
    case SettingType::Choice: return fmt::format("{}", fmt::join(choices, "|"));
    }
    return "?";
}

std::string Setting::noun() const
{
    std::string out(label);
    if (!out.empty())
        out[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(out[0])));
    return out;
}

std::string Setting::refusal(std::string_view value) const
{
    return fmt::format(fmt::runtime(number ? "{} must be {} (got {})" : "{} must be {} (got '{}')"), noun(),
                       expected(), value);
}

bool Setting::accepts(std::string_view value) const
{
    RenderSettings scratch;
    return assign(*this, scratch, value);
}

void Setting::set(RenderSettings& settings, std::string_view value, std::string_view what) const
{
    if (!assign(*this, settings, value))
        throw UsageError(fmt::format("{}: {}", what, refusal(value)));
}

std::span<const Setting> settingsTable()
{
    static const std::vector<Setting> table = makeTable();
    return table;
}

const Setting* findSetting(std::string_view name)
{
    const auto table = settingsTable();
    const auto it = std::find_if(table.begin(), table.end(), [&](const Setting& s) { return s.name == name; });
    return it == table.end() ? nullptr : &*it;
}

const Setting& setting(std::string_view name)
{
    if (const Setting* s = findSetting(name))
        return *s;
    throw std::logic_error(fmt::format("the settings table has no '{}'", name));
}

void writeSettingUniforms(const RenderSettings& settings, shader::RenderUniforms& uniforms)
{
    for (const Setting& s : settingsTable())
        if (s.toUniforms != nullptr)
            s.toUniforms(settings, uniforms);
}

std::vector<const Setting*> strategySettings()
{
    std::vector<const Setting*> out;
    for (const Setting& s : settingsTable())
        if (!s.compareFlag.empty())
            out.push_back(&s);
    return out;
}
} // namespace rt
