// Distribution ray tracing of direct light only (Cook et al. 1984): at the first
// non-specular surface, light_samples shadow rays to points on the lights and
// bsdf_samples BSDF-sampled rays (glossy reflection), combined with MIS. Perfect
// specular surfaces are followed up to max_depth. No indirect light.
#pragma once

#include "integrators/integrator.h"

namespace penumbra {

class DirectIntegrator final : public Integrator {
public:
    explicit DirectIntegrator(const IntegratorOptions& options) : m_options(options) {}
    Spectrum Li(const Ray& ray, const RenderContext& ctx, Sampler& sampler) const override;
    // With both kinds of samples, Li weighs them by MIS at every surface.
    bool pairs_light_and_bsdf_samples() const override {
        return m_options.light_samples > 0 && m_options.bsdf_samples > 0;
    }

private:
    IntegratorOptions m_options;
};

}  // namespace penumbra
