#include "App/Gui/PanelSettings.h"

namespace rt::gui
{
SceneOptions ImageSettings::sceneOptions() const
{
    return SceneOptions{.count = count, .meshPath = meshPath};
}

RenderSettings ImageSettings::renderSettings() const
{
    RenderSettings s;
    s.spp = spp;
    s.depth = depth;
    s.width = width;
    s.aspect = aspect;
    s.sampling = sampling;
    s.estimator = pdf ? Estimator::Mixture : Estimator::BsdfOnly;
    s.unidirectionalLight = unidirectionalLight;
    s.seed = seed;
    return s;
}

ImageSettings ImageSettings::from(const std::string& scene, const SceneOptions& sceneOptions, const RenderSettings& s)
{
    return ImageSettings{.scene = scene,
                         .count = sceneOptions.count,
                         .meshPath = sceneOptions.meshPath,
                         .spp = s.spp,
                         .depth = s.depth,
                         .width = s.width,
                         .aspect = s.aspect,
                         .sampling = s.sampling,
                         .pdf = s.estimator == Estimator::Mixture,
                         .unidirectionalLight = s.unidirectionalLight,
                         .seed = s.seed};
}

bool ImageSettings::sameScene(const ImageSettings& other) const
{
    return scene == other.scene && count == other.count && meshPath == other.meshPath;
}

const char* engineLabel(EngineKind engine)
{
    switch (engine)
    {
    case EngineKind::Single: return "single core";
    case EngineKind::Multi: return "multi core";
    case EngineKind::Gpu: return "GPU";
    }
    return "?";
}

const char* samplingLabel(PixelSampling sampling)
{
    switch (sampling)
    {
    case PixelSampling::Random: return "normal";
    case PixelSampling::Accumulate: return "accumulation";
    case PixelSampling::Stratified: return "stratified";
    }
    return "?";
}
} // namespace rt::gui
