// The CPU engine: the Common scene compiled to a BVH (CpuScene), rendered pixel by pixel with
// std::execution::seq ("single core") or std::execution::par ("multi core": libstdc++ runs it on TBB).
// Every sample's random stream depends only on (seed, pixel, sample index), so both policies produce the
// same image bit for bit.
#pragma once

#include <memory>

#include "Render/RenderEngine.h"
#include "Scene/CpuScene.h"

namespace rt::cpu
{
class CpuEngine final : public RenderEngine
{
public:
    /// `kind` is EngineKind::Single or EngineKind::Multi.
    explicit CpuEngine(EngineKind kind);

    EngineKind kind() const override { return m_kind; }
    std::string deviceName() const override;
    double setScene(const Scene& scene) override;
    RenderResult render(const RenderSettings& settings, RenderControl& control,
                        const PreviewCallback& preview = {}) override;

    const CpuScene* compiledScene() const { return m_scene.get(); }

private:
    EngineKind m_kind;
    std::unique_ptr<CpuScene> m_scene;
    double m_buildSeconds = 0.0;
};
} // namespace rt::cpu
