#include "Support/StressScenes.h"

#include <algorithm>
#include <cmath>

#include "Scene/SceneBuilder.h"
#include "Scenes/Catalogue.h"
#include "Support/RenderWithSettings.h"
#include "Support/SmallSettings.h"

namespace rt::test
{
namespace
{
RenderResult renderOnce(RenderEngine& engine, const Scene& scene, const RenderSettings& settings)
{
    engine.setScene(scene);
    RenderControl control;
    return renderWithSettings(engine, settings, control);
}

std::uint64_t nonFinite(const RenderStats& stats) { return stats.nanSamples + stats.infSamples; }
} // namespace

MovedSceneAgreement compareMovedScene(RenderEngine& engine, const std::string& sceneId, const SceneTransform& t,
                                      int width, int spp, FloatLimits limits)
{
    const Scene original = makeScene(sceneId);
    SceneOptions options;
    options.transform = t;
    Scene moved = limits == FloatLimits::Enforce ? makeScene(sceneId, options) : original;
    if (limits == FloatLimits::Ignore)
        transformScene(moved, t, limits);
    RenderSettings settings = settingsFor(original, width, spp, 10);
    settings.estimator = original.defaults.estimator;
    const BlockEstimate a = estimateBlocks(engine, original, settings);
    const BlockEstimate b = estimateBlocks(engine, moved, settings);
    return {disagreeingBlocks(a, b, kMaxZ), a.nonFiniteSamples + b.nonFiniteSamples};
}

std::string toString(ConvexShape shape)
{
    switch (shape)
    {
    case ConvexShape::Sphere: return "Sphere";
    case ConvexShape::Quad: return "Quad";
    case ConvexShape::Triangle: return "Triangle";
    }
    return "?";
}

ConvexUnderSky renderConvexUnderSky(RenderEngine& engine, ConvexShape shape, const SceneTransform& t)
{
    SceneBuilder b("convex-under-sky");
    const std::uint32_t grey = b.lambertian(vec3(0.5f));
    switch (shape)
    {
    case ConvexShape::Sphere: b.sphere(b.world(), vec3(0.0f), 1.0f, grey); break;
    case ConvexShape::Quad: b.quad(b.world(), {-1.2f, -1.0f, 0.2f}, {2.3f, 0.2f, -0.3f}, {0.1f, 2.0f, 0.4f}, grey); break;
    case ConvexShape::Triangle:
    {
        MeshData m;
        m.name = "triangle";
        m.positions = {{-1.3f, -1.0f, 0.3f}, {1.2f, -0.8f, -0.4f}, {0.1f, 1.3f, 0.2f}};
        m.indices = {0, 1, 2};
        b.mesh(b.world(), b.addMesh(std::move(m)), grey);
        break;
    }
    }
    Scene& s = b.scene();
    s.background = {BackgroundType::Constant, vec3(1.0f), vec3(1.0f)};
    s.camera.lookFrom = {0.4f, 0.6f, 4.0f};
    s.camera.lookAt = vec3(0.0f);
    s.camera.vfovDegrees = 45.0f;
    s.camera.focusDistance = 4.0f;
    Scene scene = b.finish();
    // The ray offsets must work at any scale, also below the size limit that whole rooms need (a shape
    // scaled by 1e-3 is 3.5e-3 units across).
    transformScene(scene, t, FloatLimits::Ignore);

    RenderSettings settings = settingsFor(scene, 32, 4, 6);
    settings.estimator = Estimator::BsdfOnly;
    settings.russianRoulette = RussianRoulette::Off;
    const RenderResult r = renderOnce(engine, scene, settings);
    ConvexUnderSky out{.lowest = 1e30f, .highest = -1e30f, .nonFiniteSamples = nonFinite(r.stats)};
    for (const vec3& p : r.image.pixels())
    {
        out.lowest = std::min(out.lowest, p.x);
        out.highest = std::max(out.highest, p.x);
        out.shapePixels += std::fabs(p.x - 0.5f) < 1e-4f ? 1 : 0;
    }
    return out;
}

GroundPair renderGroundSphereAndPlane(RenderEngine& engine, float kRadius)
{
    const auto build = [&](bool sphere) {
        SceneBuilder b(sphere ? "huge-ground-sphere" : "ground-plane");
        const std::uint32_t w = b.world();
        const std::uint32_t grey = b.lambertian(vec3(0.5f));
        if (sphere)
            b.sphere(w, {0.0f, -kRadius, 0.0f}, kRadius, grey);
        else
            b.quad(w, {-100.0f, 0.0f, -100.0f}, {0.0f, 0.0f, 200.0f}, {200.0f, 0.0f, 0.0f}, grey); // faces +y
        // High above: the plane's own ray offset (1/65536 of its largest coordinate, 1.5e-3 here) lifts its
        // shading points, which brightened it by 0.3 % under a light 2 units up; at 20 units, 0.015 %.
        b.quad(w, {-3.0f, 20.0f, -3.0f}, {6.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 6.0f}, b.diffuseLight(vec3(5.0f))); // faces -y
        Scene& s = b.scene();
        s.camera.lookFrom = {0.0f, 1.5f, 3.0f};
        s.camera.lookAt = vec3(0.0f);
        s.camera.vfovDegrees = 50.0f;
        s.camera.focusDistance = 3.0f;
        return b.finish();
    };
    const Scene sphere = build(true);
    const Scene plane = build(false);
    RenderSettings settings = settingsFor(plane, 64, 16, 4);
    settings.estimator = Estimator::NeeMis;
    return {estimateBlocks(engine, sphere, settings), estimateBlocks(engine, plane, settings)};
}

TinySphereCheck renderTinyFarSphere(RenderEngine& engine, float distance)
{
    constexpr float kRadius = 1e-3f;
    constexpr int kWidth = 32;
    SceneBuilder b("tiny-far-sphere");
    b.sphere(b.world(), {0.0f, 0.0f, -distance}, kRadius, b.diffuseLight(vec3(1.0f)));
    Scene& s = b.scene();
    s.background = {BackgroundType::Constant, vec3(0.0f), vec3(0.0f)};
    s.camera.lookFrom = vec3(0.0f);
    s.camera.lookAt = {0.0f, 0.0f, -distance};
    // The image is 4 radii high: half of it is the sphere.
    s.camera.vfovDegrees = float(2.0 * std::atan(2.0 * kRadius / distance) * 180.0 / 3.14159265358979);
    s.camera.focusDistance = distance;
    const Scene scene = b.finish();
    RenderSettings settings = settingsFor(scene, kWidth, 4, 1);
    settings.estimator = Estimator::BsdfOnly;
    settings.unidirectionalLight = false;
    const RenderResult r = renderOnce(engine, scene, settings);

    TinySphereCheck out{.nonFiniteSamples = nonFinite(r.stats)};
    const double radiiPerPixel = 4.0 / kWidth; // of the focus plane, where the sphere's centre lies
    for (int y = 0; y < kWidth; ++y)
        for (int x = 0; x < kWidth; ++x)
        {
            // Nearest and farthest points of the pixel's square from the image centre, in radii.
            const double x0 = (x - kWidth / 2) * radiiPerPixel, x1 = x0 + radiiPerPixel;
            const double y0 = (y - kWidth / 2) * radiiPerPixel, y1 = y0 + radiiPerPixel;
            const double nx = std::max({x0, -x1, 0.0}), ny = std::max({y0, -y1, 0.0});
            const double fx = std::max(std::fabs(x0), std::fabs(x1)), fy = std::max(std::fabs(y0), std::fabs(y1));
            const float value = r.image.at(x, y).x;
            if (std::hypot(fx, fy) < 0.8)
            {
                ++out.insidePixels;
                out.wrongInside += std::fabs(value - 1.0f) > 1e-5f ? 1 : 0;
            }
            else if (std::hypot(nx, ny) > 1.2)
            {
                ++out.outsidePixels;
                out.wrongOutside += value != 0.0f ? 1 : 0;
            }
        }
    return out;
}

AccumulationDrift renderLongAccumulation(RenderEngine& engine, std::uint32_t spp, PixelSampling sampling)
{
    constexpr int kWidth = 4;
    SceneBuilder b("long-accumulation");
    // The quad covers the left half of the view: columns 0-1 see it, 2-3 the sky. Only columns 0 and 3 are
    // checked: a sample of column 1 or 2 can fall exactly on the edge.
    b.quad(b.world(), {-10.0f, -10.0f, 0.0f}, {10.0f, 0.0f, 0.0f}, {0.0f, 20.0f, 0.0f}, b.lambertian(vec3(0.5f)));
    Scene& s = b.scene();
    s.background = {BackgroundType::Constant, vec3(0.1f), vec3(0.1f)};
    s.camera.lookFrom = {0.0f, 0.0f, 2.0f};
    s.camera.lookAt = vec3(0.0f);
    s.camera.vfovDegrees = 60.0f;
    s.camera.focusDistance = 2.0f;
    const Scene scene = b.finish();
    RenderSettings settings = settingsFor(scene, kWidth, int(spp), 4);
    settings.aspect = 1.0f;
    settings.estimator = Estimator::BsdfOnly;
    settings.russianRoulette = RussianRoulette::Off;
    settings.sampling = sampling;
    const RenderResult r = renderOnce(engine, scene, settings);

    AccumulationDrift out{.nonFiniteSamples = nonFinite(r.stats)};
    const double quad = double(0.5f * 0.1f), sky = double(0.1f);
    for (int y = 0; y < kWidth; ++y)
        for (const int x : {0, kWidth - 1})
        {
            const double exact = x == 0 ? quad : sky;
            (x == 0 ? out.quadPixels : out.skyPixels)++;
            for (int c = 0; c < 3; ++c)
                out.worstRelativeError =
                    std::max(out.worstRelativeError, std::fabs(double(r.image.at(x, y)[c]) - exact) / exact);
        }
    return out;
}
} // namespace rt::test
