// The path loop's instances for the estimator NeeMis (Integrator/PathVariantInstances.h says why a file of their own).
#include "Integrator/PathVariantInstances.h"

namespace rt::cpu
{
template <>
PathVariant estimatorVariant<Estimator::NeeMis>(bool media, bool textures, bool rayLanes)
{
    return detail::forEstimator<Estimator::NeeMis>(media, textures, rayLanes);
}
} // namespace rt::cpu
