// The engines a program can render with, reached through the render interface (Render/RenderEngine.h) and never
// by their headers: each engine library has a registration object (RayTracingCPU/Engine/CpuEngineRegistration.cpp,
// RayTracingGPU/Engine/GpuEngineRegistration.cpp, CMake object libraries rt_cpu_engines and rt_gpu_engine) that
// adds its factory here during static initialisation, and a program offers the engines whose object it links. So
// the CPU app's window starts the GPU engine, and both apps' --compare renders on every engine, without
// including another engine's headers (docs/ARCHITECTURE.md).
#pragma once

#include <memory>
#include <vector>

#include "Render/EngineOptions.h"
#include "Render/RenderEngine.h"

namespace rt
{
/// Makes the engine of `kind` (one of those it was registered for). Throws rt::Error subclasses (DeviceError:
/// no suitable device; UsageError: a bad option).
using EngineFactory = std::unique_ptr<RenderEngine> (*)(EngineKind kind, const EngineOptions& options);

namespace engines
{
/// Registers `factory` for `kinds`; returns true (for the registration objects' static initialisers). A kind
/// registered twice keeps its first factory.
bool add(std::initializer_list<EngineKind> kinds, EngineFactory factory);
/// Whether this program links an engine of `kind`.
bool has(EngineKind kind);
/// Every kind this program links, in EngineKind's order (single, multi, gpu).
std::vector<EngineKind> available();
/// A new engine of `kind`. Throws UsageError naming the kind when the program has none ("this build has no gpu
/// engine"), and whatever the factory throws.
std::unique_ptr<RenderEngine> make(EngineKind kind, const EngineOptions& options = {});
} // namespace engines
} // namespace rt
