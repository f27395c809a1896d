// Test kernel (tests/Gpu/ShaderParityTest.cpp): evaluates the shaders' building blocks on inputs from the
// host, so that the test can compare them with their C++ twins in Common. One invocation per case; `mode`
// selects the function family and the layout of a case (kParity* in the test).
#version 460
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require

#include "Shared/HostDevice.h"

layout(local_size_x = 64) in;
layout(binding = 0, scalar) readonly buffer Inputs { uint inputs[]; };
layout(binding = 1, scalar) writeonly buffer Outputs { uint outputs[]; };
layout(binding = 2, scalar) readonly buffer PerlinBlock { PerlinData perlinTables; };
layout(binding = 3, scalar) readonly buffer LightBlock { LightData lights[]; };
layout(binding = 4, scalar) readonly buffer LightBvhBlock { LightBvhNode lightBvh[]; };
layout(binding = 5, scalar) readonly buffer LightBvhLeafBlock { uint lightBvhLeaves[]; };
layout(push_constant, scalar) uniform Push { uint mode; uint caseCount; uint inputStride; uint outputStride; };

#include "Shared/Random.h"
#include "Shared/RayOffset.h"
#include "Shared/Sphere.h"
#include "Shared/LightBvh.h"
#include "Shared/LightSampling.h"
#include "Shared/Warps.h"
#include "Shared/Perlin.h"
#include "Shared/Bsdf/Conductor.h"
#include "Shared/Bsdf/GltfPbr.h"
#include "Shared/Bsdf/RoughDielectric.h"
#include "Textures/Srgb.glsl"

uint inBase;
uint outBase;

float inFloat(uint i) { return uintBitsToFloat(inputs[inBase + i]); }
vec2 inVec2(uint i) { return vec2(inFloat(i), inFloat(i + 1u)); }
vec3 inVec3(uint i) { return vec3(inFloat(i), inFloat(i + 1u), inFloat(i + 2u)); }
void outUint(uint i, uint v) { outputs[outBase + i] = v; }
void outFloat(uint i, float v) { outUint(i, floatBitsToUint(v)); }
void outVec2(uint i, vec2 v) { outFloat(i, v.x); outFloat(i + 1u, v.y); }
void outVec3(uint i, vec3 v) { outFloat(i, v.x); outFloat(i + 1u, v.y); outFloat(i + 2u, v.z); }

void main()
{
    uint c = gl_GlobalInvocationID.x;
    if (c >= caseCount)
        return;
    inBase = c * inputStride;
    outBase = c * outputStride;
    if (mode == 0u) // Random: (seed, pixel, sample) -> 4 nextUint, then 4 nextFloat
    {
        Rng rng = rngForSample(inputs[inBase], inputs[inBase + 1u], inputs[inBase + 2u]);
        for (uint k = 0u; k < 4u; ++k)
            outUint(k, nextUint(rng));
        for (uint k = 4u; k < 8u; ++k)
            outFloat(k, nextFloat(rng));
    }
    else if (mode == 1u) // RayOffset: (p, n, scale) -> offsetRayOrigin(p, n, scale)
        outVec3(0u, offsetRayOrigin(inVec3(0u), inVec3(3u), inFloat(6u)));
    else if (mode == 2u) // Warps: (u, oneMinusCosThetaMax) -> cosine, sphere, cone, disk, triangle
    {
        vec2 u = inVec2(0u);
        outVec3(0u, sampleCosineHemisphere(u));
        outVec3(3u, sampleUniformSphere(u));
        outVec3(6u, sampleUniformCone(u, inFloat(2u)));
        outVec2(9u, sampleUniformDiskConcentric(u));
        outVec2(11u, sampleUniformTriangle(u));
    }
    else if (mode == 3u) // LightSampling: (light, p, u, strategy, n) -> ok, wi, pdf, lightPdf(wi), outcome
    {                     // strategy kNoIndex: book 3's sampler, else NEE's LightSampler with receiver n
        LightData light = lights[inputs[inBase]];
        vec3 p = inVec3(1u);
        uint strategy = inputs[inBase + 6u];
        vec3 n = inVec3(7u);
        LightSample ls;
        bool book3 = strategy == kNoIndex;
        bool ok = book3 ? sampleLight(light, p, inVec2(4u), ls) : sampleLight(light, strategy, p, n, inVec2(4u), ls);
        outUint(0u, ok ? 1u : 0u);
        outVec3(1u, ls.wi);
        outFloat(4u, ls.pdf);
        outFloat(5u, !ok ? 0.0 : book3 ? lightPdf(light, p, ls.wi) : lightPdf(light, strategy, p, n, ls.wi));
        outUint(6u, ls.outcome);
    }
    else if (mode == 4u) // Perlin: p -> noise, turbulence (7 octaves)
    {
        vec3 p = inVec3(0u);
        outFloat(0u, perlinNoise(p));
        outFloat(1u, perlinTurbulence(p, 7));
    }
    else if (mode == 5u) // Sphere: (o, d, center, radius) -> hit, t0, t1
    {
        SphereRoots roots;
        vec3 d = inVec3(3u);
        float a = dot(d, d);
        bool hit = sphereRoots(inVec3(0u) - inVec3(6u), d, a, 1.0 / a, inFloat(9u), roots);
        outUint(0u, hit ? 1u : 0u);
        outFloat(1u, roots.t0);
        outFloat(2u, roots.t1);
    }
    else if (mode == 6u) // Srgb: 8-bit code -> linear, as a UNORM texel fetch gives it to srgbToLinear
        outFloat(0u, srgbToLinear(vec3(float(inputs[inBase]) / 255.0)).x);
    else if (mode == 8u) // Sobol: (seed, pixel, sample) -> 4 nextFloat2 of the Owen-scrambled Sobol stream
    {
        Rng rng = rngForSobolSample(inputs[inBase], inputs[inBase + 1u], inputs[inBase + 2u]);
        for (uint k = 0u; k < 8u; k += 2u)
            outVec2(k, nextFloat2(rng));
    }
    else if (mode == 9u) // Microfacet: one material for every case (input stride 0), the case's own uniforms
    {                     // from (seed, case): -> ok, wi, pdf, weight of the material's sampler
        uint kind = inputs[inBase + 1u];
        vec3 wo = inVec3(2u);
        Rng rng = rngForSample(inputs[inBase], c, 0u);
        float uLobe = nextFloat(rng);
        vec2 u = vec2(nextFloat(rng), nextFloat(rng));
        BsdfSample s;
        s.wi = vec3(0.0);
        s.weight = vec3(0.0);
        s.pdf = 0.0;
        bool ok = false;
        if (kind == 0u)
            ok = sampleConductor(ConductorParams(inFloat(5u), inFloat(6u), false, vec3(0.0), inVec3(8u), inVec3(11u)),
                                 wo, u, s);
        else if (kind == 1u)
            ok = sampleRoughDielectric(inFloat(5u), inFloat(7u), wo, uLobe, u, s);
        else
            ok = sampleGltfPbr(GltfPbrParams(inVec3(8u), inFloat(7u), inFloat(5u), inFloat(14u)), wo, uLobe, u, s);
        outUint(0u, ok ? 1u : 0u);
        outVec3(1u, s.wi);
        outFloat(4u, s.pdf);
        outVec3(5u, s.weight);
    }
    else if (mode == 7u) // LightBvh: (p, n, twoSided, u) -> selected light, its pmf, lightBvhPmf of it
    {
        vec3 p = inVec3(0u);
        vec3 n = inVec3(3u);
        bool twoSided = inputs[inBase + 6u] != 0u;
        float pmf;
        uint light = selectLightBvh(p, n, twoSided, inFloat(7u), pmf);
        outUint(0u, light);
        outFloat(1u, pmf);
        outFloat(2u, light == kNoIndex ? 0.0 : lightBvhPmf(light, p, n, twoSided));
    }
}
