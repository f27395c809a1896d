// The path loop's instances for the estimator Nee (Integrator/PathVariantInstances.h says why a file of their own).
#include "Integrator/PathVariantInstances.h"

namespace rt::cpu
{
template <>
PathVariant estimatorVariant<Estimator::Nee>(bool media, bool textures, bool rayLanes)
{
    return detail::forEstimator<Estimator::Nee>(media, textures, rayLanes);
}
} // namespace rt::cpu
