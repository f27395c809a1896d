// What the window's panel holds, split the way re-rendering needs it (style pattern 20): ImageSettings
// change the image, so an image rendered with other ImageSettings is stale and a new render starts;
// DisplaySettings only change how the window looks. The defaulted operator== compares every field, so a
// field added later takes part in the staleness check without anyone remembering to add it.
#pragma once

#include <cstdint>
#include <string>

#include "Render/RenderSettings.h"
#include "Scenes/Catalogue.h"

namespace rt::gui
{
struct ImageSettings
{
    std::string scene = "cornell-box-lights";
    int count = -1; // objects of the scenes that scale (white-spheres); < 0: the scene's default
    std::string meshPath = SceneOptions{}.meshPath; // OBJ of the mesh scenes
    int spp = 100; // samples per pixel asked for
    int depth = 50; // scattering events per path
    int width = 600; // pixels
    float aspect = 1.0f; // width / height
    PixelSampling sampling = PixelSampling::Random;
    bool pdf = true; // on: book 3's mixture of BSDF and light sampling; off: BSDF sampling only
    bool unidirectionalLight = true; // emitters emit from their front face only
    std::uint32_t seed = 0;

    bool operator==(const ImageSettings&) const = default;

    /// The settings as the engines take them.
    SceneOptions sceneOptions() const;
    RenderSettings renderSettings() const;
    /// The panel's values for a scene id and the settings resolved from the command line.
    static ImageSettings from(const std::string& scene, const SceneOptions& sceneOptions, const RenderSettings& settings);
    /// True when both describe the same scene object (id and the options it is built with).
    bool sameScene(const ImageSettings& other) const;
};

/// How the window looks: the thesis' "UI parameters" (colour mode and font).
struct DisplaySettings
{
    bool dark = true;
    std::string font; // a name from availableFonts(); empty: the first available
    float fontSize = 16.0f; // pixels

    bool operator==(const DisplaySettings&) const = default;
};

/// "single core", "multi core", "GPU": the engine names the panel and the timings table show.
const char* engineLabel(EngineKind engine);
/// The panel's names of the pixel sampling types (the thesis calls random sampling "normal").
const char* samplingLabel(PixelSampling sampling);
} // namespace rt::gui
