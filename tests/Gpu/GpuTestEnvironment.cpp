#include "GpuTestEnvironment.h"

#include <cmath>
#include <memory>

#include "Error.h"

namespace rt::gpu::test
{
namespace
{
struct Shared
{
    std::unique_ptr<GpuEngine> engine;
    std::string error;
};

Shared& shared()
{
    static Shared s = [] {
        Shared out;
        try
        {
            out.engine = std::make_unique<GpuEngine>(GpuEngineOptions{.validation = true});
        }
        catch (const DeviceError& e)
        {
            out.error = e.what();
        }
        return out;
    }();
    return s;
}
} // namespace

GpuEngine* sharedEngine() { return shared().engine.get(); }

const std::string& engineError() { return shared().error; }

RenderResult renderOnGpu(const Scene& scene, const RenderSettings& settings)
{
    GpuEngine& engine = *sharedEngine();
    engine.setScene(scene);
    RenderControl control;
    return engine.render(settings, control);
}

MeanAndError pixelStatistics(const Image& image, int channel)
{
    const auto n = static_cast<double>(image.pixelCount());
    double sum = 0.0;
    double sumSquares = 0.0;
    for (const vec3& p : image.pixels())
    {
        sum += p[channel];
        sumSquares += double(p[channel]) * p[channel];
    }
    MeanAndError m;
    m.mean = sum / n;
    const double variance = std::max(0.0, (sumSquares - n * m.mean * m.mean) / (n - 1.0));
    m.standardError = std::sqrt(variance / n);
    return m;
}
} // namespace rt::gpu::test
