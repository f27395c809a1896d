#include "RenderTestSupport.h"

#include <cstring>

#include "Support/RenderWithSettings.h"

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
    return renderWithSettings(e, settings, control);
}

bool bitIdentical(const Image& a, const Image& b)
{
    return a.width() == b.width() && a.height() == b.height() &&
           std::memcmp(a.data(), b.data(), a.pixelCount() * sizeof(vec3)) == 0;
}
} // namespace rt::test
