// Every field of RenderSettings, declared once: its name, type, range, words, JSON key, help and tooltip text,
// and how to read, write and copy it. The command line (Cli/CommonOptions), both windows' --actions
// (Cli/ActionGrammar) and panels, the stats JSON (toJson), the settings' log line (Format.h), the CPU window's
// timings table and --compare's strategies and labels (Compare/Strategy) all loop over this table, so a new
// setting is one entry here (and its field in RenderSettings) and every one of them offers it.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "Render/RenderSettings.h"

namespace rt
{
enum class SettingType
{
    Integer, // in [minimum, maximum]
    Real, // finite, minimum < value <= maximum
    Choice, // one of `choices`
    OnOff // "on" or "off"
};

struct Setting
{
    std::string_view name; // the command line's --NAME and the windows' NAME=: "light-sampler"
    std::string_view jsonKey; // the stats JSON's and the reference cache's key: "light_sampler"
    std::string_view label; // the panels' and the timings table's: "Light sampler"
    SettingType type;
    std::string_view help; // --help (the default is appended where it is not the scene's)
    std::string_view tooltip; // the panels' tooltip and the windows' --help line
    double minimum = 0.0;
    double maximum = 0.0;
    bool fromScene = false; // the default is the scene's (applySceneDefaults), not RenderSettings'
    std::string_view compareFlag; // --compare's flag listing values to compare ("--estimators"); empty: not varied
    std::string_view compareTag; // OnOff: --compare's labels say TAG-on / TAG-off ("rr-on"); empty: the word alone
    std::vector<std::string_view> choices; // Choice: the words, in the order panels list them

    std::string (*text)(const RenderSettings&); // the value's word or number, as `assign` reads it back
    nlohmann::json (*json)(const RenderSettings&); // numbers as numbers, on/off as booleans, choices as words
    /// Sets the field from `value`; false (the field unchanged) when the value is not `expected()`.
    bool (*assign)(const Setting&, RenderSettings&, std::string_view value);
    void (*copy)(RenderSettings& to, const RenderSettings& from);
    double (*number)(const RenderSettings&); // Integer, Real: the value; null otherwise
    /// Writes the field into the shaders' uniforms (Shared/HostDevice.h's RenderUniforms, which both engines' path
    /// vertex reads); null for a setting the host alone reads (spp, width, aspect: the frame's size and count).
    void (*toUniforms)(const RenderSettings&, shader::RenderUniforms&) = nullptr;
    /// Whether a render with `settings` reads the field (the light sampler: only an estimator with NEE); null:
    /// always.
    bool (*usedBy)(const RenderSettings& settings) = nullptr;

    /// What a value must be: "an integer in [1, 16777216]", "a number > 0", "bsdf, mixture, nee or nee-mis",
    /// "on or off".
    std::string expected() const;
    /// "NOUN must be EXPECTED (got VALUE)": why `value` is refused.
    std::string refusal(std::string_view value) const;
    /// What --help shows after the flag: "N", "X", "on|off", "bsdf|mixture|nee|nee-mis".
    std::string placeholder() const;
    /// The label as a noun inside a sentence: "samples per pixel", "light sampler".
    std::string noun() const;
    /// Whether assign() would take `value`.
    bool accepts(std::string_view value) const;
    /// assign(), or throws UsageError "`what` (NOUN) must be EXPECTED (got VALUE)".
    void set(RenderSettings& settings, std::string_view value, std::string_view what) const;
    bool used(const RenderSettings& settings) const { return usedBy == nullptr || usedBy(settings); }
};

/// The table: spp, depth, width, aspect, estimator, light-sampler, light-selection, sampling, russian-roulette,
/// unidirectional-light, seed (--compare's strategies nest in this order, the estimator outermost).
std::span<const Setting> settingsTable();
/// The setting called `name`, or null.
const Setting* findSetting(std::string_view name);
/// The setting called `name`; throws std::logic_error for a name the table lacks (a programming error).
const Setting& setting(std::string_view name);
/// Every setting's toUniforms into `uniforms`.
void writeSettingUniforms(const RenderSettings& settings, shader::RenderUniforms& uniforms);
/// The settings --compare varies (compareFlag non-empty), in table order.
std::vector<const Setting*> strategySettings();
} // namespace rt
