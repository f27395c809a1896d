#include "GpuTestEnvironment.h"

#include <cstdlib>
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
            out.engine =
                std::make_unique<GpuEngine>(GpuEngineOptions{.validation = true, .integrator = suiteIntegrator()});
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

GpuIntegrator suiteIntegrator()
{
    const char* name = std::getenv("RT_GPU_INTEGRATOR");
    if (!name || !*name)
        return GpuIntegrator::Auto;
    if (const auto integrator = parseIntegrator(name))
        return *integrator;
    throw UsageError(std::string("RT_GPU_INTEGRATOR must be megakernel or wavefront (got '") + name + "')");
}

GpuEngine* sharedEngine() { return shared().engine.get(); }

const std::string& engineError() { return shared().error; }

RenderResult renderOnGpu(const Scene& scene, const RenderSettings& settings)
{
    GpuEngine& engine = *sharedEngine();
    engine.setScene(scene);
    RenderControl control;
    return renderWithSettings(engine, settings, control);
}

} // namespace rt::gpu::test
