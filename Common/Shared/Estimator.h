// What an estimator (HostDevice.h Estimator) does at a path's vertices, decided once for both engines
// (Shared/ShaderLang.h): the path vertex, the pipelines' keys, the CPU's path loops and --compare ask here.
#ifndef RT_SHARED_ESTIMATOR_H
#define RT_SHARED_ESTIMATOR_H

#include "Shared/HostDevice.h"
#include "Shared/ShaderLang.h"

RT_SHADER_NAMESPACE_BEGIN

/// Whether the estimator samples a light at its diffuse vertices (next-event estimation: nee, nee-mis, and
/// restir-di, whose first such vertex resamples what NEE would sample): the
/// shadow rays, and the weight of an emitter that a BSDF ray finds after such a vertex.
RT_FN bool usesNee(RT_TAG(Estimator) estimator)
{
    return estimator == RT_ENUM(Estimator, Nee) || estimator == RT_ENUM(Estimator, NeeMis) ||
           estimator == RT_ENUM(Estimator, RestirDi);
}

/// Whether NEE's samples and the emitters BSDF rays find are weighted by the power heuristic (nee-mis; restir-di
/// after its resampled vertex), rather than NEE's alone counting (nee).
RT_FN bool weighsNeeByMis(RT_TAG(Estimator) estimator)
{
    return estimator == RT_ENUM(Estimator, NeeMis) || estimator == RT_ENUM(Estimator, RestirDi);
}

RT_SHADER_NAMESPACE_END

#endif
