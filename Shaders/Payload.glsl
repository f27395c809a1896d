// What a traced ray brings back to the raygen shader (payload location kPayloadPath): HitPayload of
// HostDevice.h, which the wavefront integrator also keeps per path. Hit shaders describe the hit; all shading
// (textures, materials, the estimator) happens in raygen or the wavefront's shade kernel.
#ifndef RT_PAYLOAD_GLSL
#define RT_PAYLOAD_GLSL

#include "Shared/HostDevice.h"

#endif
