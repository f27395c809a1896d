// The GPU engine in the engine registry (Render/EngineRegistry.h): linked into a program as the object library
// rt_gpu_engine, so that its static initialiser runs, it offers gpu. Validation is on where asked and where the
// environment or a Debug build asks for it (validationWanted).
#include "Cluster/Job.h"
#include "Engine/GpuContext.h"
#include "Engine/GpuEngine.h"
#include "Render/EngineRegistry.h"

namespace rt::gpu
{
namespace
{
std::unique_ptr<RenderEngine> makeGpuEngine(EngineKind, const EngineOptions& options)
{
    return std::make_unique<GpuEngine>(GpuEngineOptions{.deviceIndex = options.device,
                                                        .deviceShare = cluster::job().localRank(),
                                                        .validation = options.validation || validationWanted(),
                                                        .shaderDir = options.shaderDir,
                                                        .specialize = options.specialize,
                                                        .integrator = options.integrator,
                                                        .wavePaths = options.wavePaths,
                                                        .countRays = options.countRays});
}

[[maybe_unused]] const bool kRegistered = engines::add({EngineKind::Gpu}, &makeGpuEngine);
} // namespace
} // namespace rt::gpu
