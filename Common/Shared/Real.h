// The scalar of Shared code whose algebra needs more than float on the CPU (research notes §0.2): `Real` is
// double in C++ and float in GLSL, with RealVec2/RealVec3 beside it. Such code writes its literals without the
// f suffix (double in C++, float in GLSL) and converts at its float interfaces.
#ifndef RT_SHARED_REAL_H
#define RT_SHARED_REAL_H

#include "Shared/ShaderLang.h"

#ifdef __cplusplus
RT_SHADER_NAMESPACE_BEGIN
using Real = double;
using RealVec2 = glm::dvec2;
using RealVec3 = glm::dvec3;
RT_SHADER_NAMESPACE_END
#else
#define Real float
#define RealVec2 vec2
#define RealVec3 vec3
#endif

#endif
