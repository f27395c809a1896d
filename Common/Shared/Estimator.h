// What an estimator (HostDevice.h Estimator) does at a path's vertices, decided once for both engines
// (Shared/ShaderLang.h): the path vertex, the pipelines' keys, the CPU's path loops and --compare ask here.
#ifndef RT_SHARED_ESTIMATOR_H
#define RT_SHARED_ESTIMATOR_H

#include "Shared/HostDevice.h"
#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

/// Whether the estimator samples a light at its diffuse vertices (next-event estimation: nee, nee-mis): the
/// shadow rays, and the weight of an emitter that a BSDF ray finds after such a vertex.
RT_FN bool usesNee(RT_TAG(Estimator) estimator)
{
    return estimator == RT_ENUM(Estimator, Nee) || estimator == RT_ENUM(Estimator, NeeMis);
}

RT_SHADER_NAMESPACE_END

#endif
