// The path loop's instances for the estimator BsdfOnly (Integrator/PathVariantInstances.h says why a file of their own).
#include "Integrator/PathVariantInstances.h"

namespace rt::cpu
{
template <>
PathVariant estimatorVariant<Estimator::BsdfOnly>(bool media, bool textures, bool rayLanes)
{
    return detail::forEstimator<Estimator::BsdfOnly>(media, textures, rayLanes);
}
} // namespace rt::cpu
