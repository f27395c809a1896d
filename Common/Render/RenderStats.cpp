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
    if (raysCounted)
    {
        const std::uint64_t segments = rays.total();
        j["segments"] = segments;
        j["segments_per_path"] = paths ? double(segments) / double(paths) : 0.0;
        j["rays"] = rt::toJson(rays, renderSeconds);
        j["light_samples"] = rt::toJson(lightSamples);
    }
    j["nan_samples"] = nanSamples;
    j["inf_samples"] = infSamples;
    j["threads_used"] = threadsUsed;
    j["cancelled"] = cancelled;
    if (!stageSeconds.empty())
        j["stage_seconds"] = stageSeconds;
    if (!frameConfiguration.empty())
        j["frame_configuration"] = frameConfiguration;
    if (!ranks.is_null())
        j["ranks"] = ranks;
    if (!heatmap.is_null())
        j["heatmap"] = heatmap;
    if (!strategyChoice.is_null())
        j["strategy_choice"] = strategyChoice;
    if (request.settings.estimator == Estimator::RestirDi)
    {
        // restir-di's memory per pixel (the bound: reservoirs at most 64 bytes) and the whole frame's,
        // and which combination ran: a biased render says so wherever its numbers go.
        nlohmann::json restir;
        restir["combination"] = request.settings.restirBiased ? "biased" : "unbiased";
        const std::uint64_t pixels = std::uint64_t(width) * std::uint64_t(height);
        for (const auto& [buffer, bytes] : frameBytesPerPixel)
        {
            restir[buffer + "_bytes_per_pixel"] = bytes;
            restir[buffer + "_bytes"] = bytes * pixels;
        }
        j["restir"] = restir;
    }
    return j;
}

void writeStatsJson(const std::filesystem::path& path, const RenderStats& stats)
{
    writeFileAtomically(path, stats.toJson().dump(2) + "\n");
}
} // namespace rt
