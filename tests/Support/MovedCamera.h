// A render with RenderRequest::camera (the windows' moved camera) against the same view given as the scene's
// own camera: the engine must render the request's camera, the same image bit for bit, and forget it when the
// next request has none.
#pragma once

#include <gtest/gtest.h>

#include "Render/RenderDriver.h"
#include "Scenes/Catalogue.h"

namespace rt::test
{
/// `engine` renders `sceneId` at `settings` (a small image); `makeEngine` makes a second engine of the same kind
/// for the scene whose own camera is the moved one (nullptr: `engine` is reused, given that scene).
template <class MakeEngine>
void expectTheRequestsCameraIsRendered(RenderEngine& engine, const std::string& sceneId, const RenderSettings& settings,
                                       MakeEngine makeEngine)
{
    const Scene scene = makeScene(sceneId);
    CameraDesc moved = scene.camera;
    moved.lookFrom = moved.lookFrom + 0.1f * (moved.lookAt - moved.lookFrom) + vec3(0.05f, 0.02f, 0.0f) *
                                                                                  length(moved.lookAt - moved.lookFrom);
    moved.vfovDegrees *= 0.8f;
    Scene viewed = scene;
    viewed.camera = moved;
    const auto same = [](const Image& a, const Image& b) { return a.width() == b.width() && a.pixels() == b.pixels(); };

    RenderControl control;
    engine.setScene(scene);
    const RenderRequest own{.scene = {.id = sceneId}, .settings = settings};
    const Image sceneCamera = render(engine, own, control).image;
    RenderRequest request = own;
    request.camera = moved;
    const Image requested = render(engine, request, control).image;
    const Image afterwards = render(engine, own, control).image;

    auto other = makeEngine();
    RenderEngine& second = other ? *other : engine;
    second.setScene(viewed);
    const Image reference = render(second, own, control).image;

    EXPECT_TRUE(same(requested, reference)) << "the request's camera renders as the scene's own would";
    EXPECT_FALSE(same(requested, sceneCamera)) << "the moved camera shows another view";
    EXPECT_TRUE(same(afterwards, sceneCamera)) << "a request without a camera renders the scene's again";
}
} // namespace rt::test
