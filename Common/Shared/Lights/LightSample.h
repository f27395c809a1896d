// A light sample and the unit conversions every light shape's sampler shares (Shared/ShaderLang.h, both
// engines). Conventions of Shared/Lights/: `p` is the shading point (world space), `wi` a unit direction leaving
// p, pdfs are per unit solid angle at p. A pdf is 0 for a direction that cannot be produced (misses the light),
// never a guess. Each shape's header pairs its samplers with their pdfs (pbrt-v4's and Mitsuba's pairing);
// Shared/LightSampling.h dispatches by shape.
#ifndef RT_SHARED_LIGHTS_LIGHT_SAMPLE_H
#define RT_SHARED_LIGHTS_LIGHT_SAMPLE_H

#include "Shared/HostDevice.h"
#include "Shared/ShaderLang.h"

// Whether the code must handle lights of a shape: always in C++; in the shaders a specialization constant
// (Shaders/Specialization.glsl defines the macro first), false where the pipeline was compiled for a scene
// without that shape, and the driver then drops that shape's code.
#ifndef RT_HAS_LIGHT_SHAPE
#define RT_HAS_LIGHT_SHAPE(Shape) true
#endif
/// shape == LightShape::Shape, false at compile time where the pipeline has no light of that shape.
#define RT_LIGHT_IS(shape, Shape) (RT_HAS_LIGHT_SHAPE(Shape) && (shape) == RT_ENUM(LightShape, Shape))

RT_SHADER_NAMESPACE_BEGIN

struct LightSample
{
    vec3 wi; // unit direction from p towards the sampled point
    float pdf; // per unit solid angle
    vec3 point; // the sampled point y on the light (world space)
    float distance; // |y - p|
    vec3 normal; // unit normal of the light at y, on its front side (outward for spheres)
    vec2 uv; // the light's surface coordinates at y: (a, b) of quads, barycentrics (b1, b2) of triangles, 0 on spheres
    uint outcome; // how it was made: kLightSampleFallback, kLightSampleDeclined (bits), 0 as the strategy asked
};

// LightSample::outcome, counted in the stats at NEE's vertices and restir-di's candidates (--stats'
// "light_samples"): the polygon samplers' documented shortcuts are never taken silently. (A receiver inside a sphere light
// is sampled by area under every strategy, having no cone to sample: by design, not marked.)
/// Made by a simpler sampler than the strategy asked: by area where a polygon is too small for its spherical or
/// projected sampler (a triangle also too large), a rectangle's setup does not resolve, or a quad is not a
/// rectangle (Lights/Quad.h, Lights/Triangle.h, LightSampling.h's projected-exact).
RT_CONST(uint, kLightSampleFallback, 1u)
/// Made, then dropped: off the light as its pdf finds it (0), by rounding or for a receiver in the light's plane.
RT_CONST(uint, kLightSampleDeclined, 2u)
/// Beside those two in ShadowRay::lightSample (Shared/PathState.h): the vertex drew a light sample.
RT_CONST(uint, kLightSampleDrawn, 4u)

/// Area-measure pdf 1/area turned into solid angle at squared distance `dist2` with |cos| at the light.
RT_FN float areaToSolidAngle(float dist2, float cosLight, float area)
{
    return cosLight > 0.0f ? dist2 / (cosLight * area) : 0.0f;
}


/// Sets every field of `ls` before a sampler fills it (Shading/Scatter.h says why every out parameter is set).
RT_FN void clearLightSample(RT_IN(LightData) light, RT_OUT(LightSample) ls)
{
    ls.wi = vec3(0.0f);
    ls.pdf = 0.0f;
    ls.point = vec3(0.0f);
    ls.distance = 0.0f;
    ls.normal = light.normal;
    ls.uv = vec2(0.0f);
    ls.outcome = 0u;
}

/// The sampler's last step where rounding may have put its sample off the light: true when ls.pdf > 0, else
/// the sample is marked declined (kLightSampleDeclined) and false returned.
RT_FN bool keepLightSample(RT_INOUT(LightSample) ls)
{
    if (ls.pdf > 0.0f)
        return true;
    ls.outcome |= kLightSampleDeclined;
    return false;
}

/// Completes a sample whose point on the light is set: its distance and direction from p (false, the sample
/// declined, when the point is p itself).
RT_FN bool lightSampleDirection(vec3 p, RT_INOUT(LightSample) ls)
{
    const vec3 w = ls.point - p;
    const float dist2 = lengthSquared(w);
    if (!(dist2 > 0.0f))
    {
        ls.outcome |= kLightSampleDeclined;
        return false;
    }
    ls.distance = sqrt(dist2);
    ls.wi = w / ls.distance;
    return true;
}

RT_SHADER_NAMESPACE_END

#endif
