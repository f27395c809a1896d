// A RenderEngine for the tests of what runs on top of one (--strategy auto's pilot, measure's time limit): it holds
// the scene it is given, one batch holds any number of paths, and it counts nothing; a test's engine adds its frame,
// its samples and its estimate.
#pragma once

#include <cstdint>
#include <string>
#include <utility>

#include "Render/RenderEngine.h"

namespace rt
{
class SceneHoldingEngine : public RenderEngine
{
public:
    explicit SceneHoldingEngine(std::string name) : m_name(std::move(name)) {}
    EngineKind kind() const override { return EngineKind::Single; }
    std::string deviceName() const override { return m_name; }
    double setScene(const Scene& scene) override
    {
        m_scene = &scene;
        return 0.0;
    }
    const Scene* scene() const override { return m_scene; }
    double buildSeconds() const override { return 0.0; }
    std::uint64_t pathsPerBatch() const override { return std::uint64_t(1) << 40; }
    SampleTally tally() const override { return {}; }

private:
    std::string m_name;
    const Scene* m_scene = nullptr;
};
} // namespace rt
