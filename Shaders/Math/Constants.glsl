// The scalar constants and helpers of Common/Math/Math.h.
#ifndef RT_MATH_CONSTANTS_GLSL
#define RT_MATH_CONSTANTS_GLSL

const float kPi = 3.14159265358979323846;
const float kInvPi = 0.31830988618379067154;
const float kInv4Pi = 0.07957747154594766788;

/// sqrt clamped at 0: rounding can push a quantity that is >= 0 in exact arithmetic slightly below it.
float safeSqrt(float x)
{
    return sqrt(max(0.0, x));
}

float lengthSquared(vec3 v)
{
    return dot(v, v);
}

bool isFiniteVec(vec3 v)
{
    return !any(isnan(v)) && !any(isinf(v));
}

#endif
