// What a path-tracing pipeline is compiled for (HostDevice.h's kSpecId*).
// The render settings: each accessor returns the specialization constant when the engine set one and the
// uniform when it left kSpecDynamic, so one SPIR-V module serves the specialised pipelines and the general
// one. Read the settings through these, never through `uniforms` directly.
// The scene's features: kHas* are false when the pipeline was compiled for a scene without the feature, and
// the code behind `if (kHasX)` is then dead, which the driver removes once the constants are known. The
// general pipeline sets every bit (kSpecDynamic): every feature present, as before specialisation.
// Needs the `uniforms` block of Bindings.glsl.
#ifndef RT_SPECIALIZATION_GLSL
#define RT_SPECIALIZATION_GLSL

#include "Shared/Estimator.h"

layout(constant_id = kSpecIdEstimator) const uint kSpecEstimator = kSpecDynamic;
layout(constant_id = kSpecIdLightSampler) const uint kSpecLightSampler = kSpecDynamic;
layout(constant_id = kSpecIdLightSelection) const uint kSpecLightSelection = kSpecDynamic;
layout(constant_id = kSpecIdSampling) const uint kSpecSampling = kSpecDynamic;
layout(constant_id = kSpecIdFeatures) const uint kSpecFeatures = kSpecDynamic;
layout(constant_id = kSpecIdExactSphereC) const uint kSpecExactSphereC = kSpecDynamic;
layout(constant_id = kSpecIdHitUv) const uint kSpecHitUv = kSpecDynamic;
layout(constant_id = kSpecIdCountRays) const uint kSpecCountRays = kSpecDynamic;
// Not a render setting: 1 in the wavefront integrator's pipelines, 0 in the megakernel's.
layout(constant_id = kSpecIdWavefront) const uint kSpecWavefront = 0u;
const bool kWavefront = kSpecWavefront != 0u;
// Not a render setting either: 1 in restir-di's pipelines (Shaders/Restir/).
layout(constant_id = kSpecIdRestir) const uint kSpecRestir = 0u;
const bool kRestirPass = kSpecRestir != 0u;

uint settingEstimator() { return kSpecEstimator != kSpecDynamic ? kSpecEstimator : uniforms.estimator; }
uint settingLightSampler() { return kSpecLightSampler != kSpecDynamic ? kSpecLightSampler : uniforms.lightSampler; }
uint settingLightSelection()
{
    return kSpecLightSelection != kSpecDynamic ? kSpecLightSelection : uniforms.lightSelection;
}
uint settingSampling() { return kSpecSampling != kSpecDynamic ? kSpecSampling : uniforms.sampling; }
/// Whether the render counts its rays (--count-rays): a constant 0 in every specialised pipeline that does not.
bool settingCountRays() { return (kSpecCountRays != kSpecDynamic ? kSpecCountRays : uniforms.countRays) != 0u; }
/// Whether the render's estimator samples a light at its vertices (Shared/Estimator.h usesNee).
bool settingUsesNee()
{
    return usesNee(settingEstimator());
}

// Specialization-constant expressions (OpSpecConstantOp): constants once the pipeline is compiled.
const bool kHasSpheres = (kSpecFeatures & kFeatureSpheres) != 0u;
const bool kHasMedia = (kSpecFeatures & kFeatureMedia) != 0u;
const bool kHasMotion = (kSpecFeatures & kFeatureMotion) != 0u;
const bool kHasLambertian = (kSpecFeatures & kFeatureLambertian) != 0u;
const bool kHasMetal = (kSpecFeatures & kFeatureMetal) != 0u;
const bool kHasDielectric = (kSpecFeatures & kFeatureDielectric) != 0u;
const bool kHasIsotropic = (kSpecFeatures & kFeatureIsotropic) != 0u;
const bool kHasConductor = (kSpecFeatures & kFeatureConductor) != 0u;
const bool kHasRoughDielectric = (kSpecFeatures & kFeatureRoughDielectric) != 0u;
const bool kHasGltfPbr = (kSpecFeatures & kFeatureGltfPbr) != 0u;
const bool kHasCheckerTextures = (kSpecFeatures & kFeatureCheckerTextures) != 0u;
const bool kHasImageTextures = (kSpecFeatures & kFeatureImageTextures) != 0u;
const bool kHasNoiseTextures = (kSpecFeatures & kFeatureNoiseTextures) != 0u;
const bool kHasSphereLights = (kSpecFeatures & kFeatureSphereLights) != 0u;
const bool kHasQuadLights = (kSpecFeatures & kFeatureQuadLights) != 0u;
const bool kHasTriangleLights = (kSpecFeatures & kFeatureTriangleLights) != 0u;
const bool kHasThinLens = (kSpecFeatures & kFeatureThinLens) != 0u;
const bool kHasGradientBackground = (kSpecFeatures & kFeatureGradientBackground) != 0u;

// The light shapes the shared light samplers (Shared/LightSampling.h) must handle: there, in C++ and in the
// shaders that do not include this file (the parity kernel), every shape.
#ifdef RT_SHARED_LIGHT_SAMPLING_H
#error "Specialization.glsl (through Bindings.glsl) must come before Shared/LightSampling.h"
#endif
#define RT_HAS_LIGHT_SHAPE(Shape) kHas##Shape##Lights

// Whether the sphere tests (Shared/Sphere.h) compute the exact c where it cancels: there, and in the shaders
// without this file (the parity kernel), always.
#ifdef RT_SHARED_SPHERE_H
#error "Specialization.glsl (through Bindings.glsl) must come before Shared/Sphere.h"
#endif
const bool kExactSphereC = kSpecExactSphereC != 0u;
#define RT_EXACT_SPHERE_C kExactSphereC

// Whether the closest-hit shaders compute a hit's uv (read by image textures only).
const bool kHitUv = kSpecHitUv != 0u;

#endif
