// The render settings a pipeline may be specialised on (HostDevice.h's kSpecId*): each accessor returns the
// specialization constant when the engine set one and the uniform when it left kSpecDynamic, so one SPIR-V
// module serves the specialised pipelines and the general one. Read the settings through these, never through
// `uniforms` directly. Needs the `uniforms` block of Bindings.glsl.
#ifndef RT_SPECIALIZATION_GLSL
#define RT_SPECIALIZATION_GLSL

layout(constant_id = kSpecIdEstimator) const uint kSpecEstimator = kSpecDynamic;
layout(constant_id = kSpecIdLightSampler) const uint kSpecLightSampler = kSpecDynamic;
layout(constant_id = kSpecIdLightSelection) const uint kSpecLightSelection = kSpecDynamic;
layout(constant_id = kSpecIdSampling) const uint kSpecSampling = kSpecDynamic;

uint settingEstimator() { return kSpecEstimator != kSpecDynamic ? kSpecEstimator : uniforms.estimator; }
uint settingLightSampler() { return kSpecLightSampler != kSpecDynamic ? kSpecLightSampler : uniforms.lightSampler; }
uint settingLightSelection()
{
    return kSpecLightSelection != kSpecDynamic ? kSpecLightSelection : uniforms.lightSelection;
}
uint settingSampling() { return kSpecSampling != kSpecDynamic ? kSpecSampling : uniforms.sampling; }

#endif
