// The stress suite's scenes and checks (issue 10, research notes §3.4), written once against the
// RenderEngine interface so that the CPU tests (tests/Cpu/StressTest.cpp) and the GPU tests
// (tests/Gpu/GpuStressTest.cpp) run the same ones. Every check returns what it measured; the tests decide.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "Render/RenderEngine.h"
#include "Scene/SceneTransform.h"
#include "Support/BlockAgreement.h"

namespace rt::test
{
/// A catalogue scene rendered as built and moved by `t` (kAgreementSeeds renders each, `width` pixels,
/// `spp`, depth 10, the scene's estimator): the blocks that disagree beyond |Z| > kMaxZ, and the NaN/Inf
/// samples of all renders.
struct MovedSceneAgreement
{
    std::vector<std::string> disagreements;
    std::uint64_t nonFiniteSamples = 0;
};
/// With `limits` Enforce the moved scene comes from the catalogue (SceneOptions::transform, as the flags
/// give it); Ignore moves it past the float32 limits, to show what they prevent.
MovedSceneAgreement compareMovedScene(RenderEngine& engine, const std::string& sceneId, const SceneTransform& t,
                                      int width, int spp, FloatLimits limits = FloatLimits::Enforce);

enum class ConvexShape
{
    Sphere,
    Quad,
    Triangle
};
std::string toString(ConvexShape shape);

/// One Lambertian shape (albedo 1/2) under a uniform sky of radiance 1, moved by `t`, rendered with BSDF
/// sampling only: a ray leaving a convex or flat shape can only escape, so every sample is 1/2 (shape) or 1
/// (sky), and a pixel below 1/2 means a secondary ray re-hit the shape it left (its sample is 1/4).
struct ConvexUnderSky
{
    float lowest = 0.0f; // darkest pixel
    float highest = 0.0f; // brightest pixel
    int shapePixels = 0; // pixels within 1e-4 of 1/2: the shape must fill part of the image
    std::uint64_t nonFiniteSamples = 0;
};
ConvexUnderSky renderConvexUnderSky(RenderEngine& engine, ConvexShape shape, const SceneTransform& t);

/// A huge ground sphere and a plane in its place (a large quad at its top), each under one small quad light,
/// seen from 1.5 units above: the block estimates of the two, to compare (within the 54 units in view, a
/// sphere of radius 1e6 drops 1.5e-3 below its tangent plane).
struct GroundPair
{
    BlockEstimate sphere;
    BlockEstimate plane;
};
GroundPair renderGroundSphereAndPlane(RenderEngine& engine, float radius = 1e6f);

/// An emitting sphere of radius 1e-3 (radiance 1) `distance` units from the camera on a black background,
/// seen directly (depth 1) at 32x32 with the sphere's diameter half the image height: pixels whose every
/// sample lands within 0.8 radii of the centre must be 1, pixels whose every sample lands beyond 1.2 radii
/// must be 0. Counts the pixels that break either.
struct TinySphereCheck
{
    int wrongInside = 0;
    int wrongOutside = 0;
    int insidePixels = 0;
    int outsidePixels = 0;
    std::uint64_t nonFiniteSamples = 0;
};
TinySphereCheck renderTinyFarSphere(RenderEngine& engine, float distance);

/// A long progressive render of a zero-variance scene (a Lambertian quad of albedo 1/2 under a uniform sky
/// of radiance 0.1, BSDF sampling: every sample of a quad pixel is exactly 0.05, of a sky pixel 0.1) at 4x4
/// pixels: the largest relative error of any pixel against its exact value after `spp` samples. A float
/// running sum drifts by 1 % at 2^20 samples (each addition rounds to an ulp of the sum); a double or
/// compensated one stays at 1e-7.
struct AccumulationDrift
{
    double worstRelativeError = 0.0;
    int quadPixels = 0;
    int skyPixels = 0;
    std::uint64_t nonFiniteSamples = 0;
};
/// `sampling`: PixelSampling::Accumulate for 1-spp passes (one batch per sample), or Random for the
/// engine's own batches (a GPU dispatch per pass would take hours): both add sample after sample to the sum.
AccumulationDrift renderLongAccumulation(RenderEngine& engine, std::uint32_t spp, PixelSampling sampling);
} // namespace rt::test
