// The CPU engines in the engine registry (Render/EngineRegistry.h): linked into a program as the object library
// rt_cpu_engines, so that its static initialiser runs, it offers single and multi.
#include "Engine/CpuEngine.h"
#include "Render/EngineRegistry.h"

namespace rt::cpu
{
namespace
{
std::unique_ptr<RenderEngine> makeCpuEngine(EngineKind kind, const EngineOptions& options)
{
    return std::make_unique<CpuEngine>(kind, options.specialize != Specialize::Off);
}

[[maybe_unused]] const bool kRegistered = engines::add({EngineKind::Single, EngineKind::Multi}, &makeCpuEngine);
} // namespace
} // namespace rt::cpu
