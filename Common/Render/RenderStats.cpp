#include "Render/RenderStats.h"

#include "IO/AtomicFile.h"

namespace rt
{
nlohmann::json RenderStats::toJson() const
{
    nlohmann::json j;
    j["scene"] = request.scene.id;
    const SceneTransform& moved = request.scene.options.transform;
    j["scene_options"] = {{"count", request.scene.options.count},
                          {"mesh", request.scene.options.meshPath},
                          {"translate", {moved.translation.x, moved.translation.y, moved.translation.z}},
                          {"scale", moved.scale},
                          {"fresnel", fresnelOptionName(request.scene.options.fresnel)}};
    j["engine"] = toString(engine);
    j["device"] = device;
    j["settings"] = rt::toJson(request.settings);
    j["width"] = width;
    j["height"] = height;
    j["true_spp"] = trueSpp;
    j["wall_seconds"] = wallSeconds;
    j["build_seconds"] = buildSeconds;
    j["render_seconds"] = renderSeconds;
    if (gpuSeconds >= 0.0)
        j["gpu_seconds"] = gpuSeconds;
    j["paths"] = paths;
    j["mpaths_per_second"] = mpathsPerSecond();
    if (segments > 0)
    {
        j["segments"] = segments;
        j["segments_per_path"] = paths ? double(segments) / double(paths) : 0.0;
    }
    j["nan_samples"] = nanSamples;
    j["inf_samples"] = infSamples;
    j["threads_used"] = threadsUsed;
    j["cancelled"] = cancelled;
    if (!stageSeconds.empty())
        j["stage_seconds"] = stageSeconds;
    if (!frameConfiguration.empty())
        j["frame_configuration"] = frameConfiguration;
    if (!strategyChoice.is_null())
        j["strategy_choice"] = strategyChoice;
    return j;
}

void writeStatsJson(const std::filesystem::path& path, const RenderStats& stats)
{
    writeFileAtomically(path, stats.toJson().dump(2) + "\n");
}
} // namespace rt
