// The path loop's instances for the estimator Mixture (Integrator/PathVariantInstances.h says why a file of their own).
#include "Integrator/PathVariantInstances.h"

namespace rt::cpu
{
template <>
PathVariant estimatorVariant<Estimator::Mixture>(bool media, bool textures, bool rayLanes)
{
    return detail::forEstimator<Estimator::Mixture>(media, textures, rayLanes);
}
} // namespace rt::cpu
