#include "RenderTestSupport.h"

#include <cmath>
#include <cstring>

namespace rt::test
{
RenderSettings smallSettings(int width, int spp, int depth, Estimator estimator, float aspect)
{
    RenderSettings s;
    s.width = width;
    s.spp = spp;
    s.depth = depth;
    s.estimator = estimator;
    s.aspect = aspect;
    s.sampling = PixelSampling::Random;
    s.seed = 7;
    return s;
}

RenderResult renderCpu(const Scene& scene, const RenderSettings& settings, EngineKind engine)
{
    cpu::CpuEngine e(engine);
    e.setScene(scene);
    RenderControl control;
    return e.render(settings, control);
}

MeanAndError pixelStatistics(const Image& image)
{
    const double n = double(image.pixelCount());
    const auto value = [](const vec3& p) { return (double(p.x) + p.y + p.z) / 3.0; };
    MeanAndError r;
    for (const vec3& p : image.pixels())
        r.mean += value(p);
    r.mean /= n;
    double squares = 0.0; // two passes: the one-pass formula cancels for nearly constant images
    for (const vec3& p : image.pixels())
        squares += (value(p) - r.mean) * (value(p) - r.mean);
    const double variance = squares / (n - 1.0);
    r.pixelStdDev = std::sqrt(variance);
    r.standardError = std::sqrt(variance / n);
    return r;
}

bool bitIdentical(const Image& a, const Image& b)
{
    return a.width() == b.width() && a.height() == b.height() &&
           std::memcmp(a.data(), b.data(), a.pixelCount() * sizeof(vec3)) == 0;
}
} // namespace rt::test
