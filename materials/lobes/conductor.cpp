#include "materials/lobes/conductor.h"

namespace penumbra {

CookTorranceParams ConductorBsdf::params(const ComplexIor& ior, MicrofacetType distribution,
                                         float alpha, MaskingModel masking) {
    CookTorranceParams p;
    p.distribution = distribution;
    p.alpha = alpha;
    p.masking = masking;
    p.fresnel = Fresnel::conductor(ior);
    return p;
}

ConductorBsdf::ConductorBsdf(const ComplexIor& ior, MicrofacetType distribution, float alpha,
                             MaskingModel masking)
    : m_lobe(params(ior, distribution, alpha, masking)) {}

}  // namespace penumbra
