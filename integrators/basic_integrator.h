// The "basic ray tracer" of classic ray tracing (Whitted 1980): at each hit, emission,
// direct light from every punctual light through one shadow ray each, and recursion
// into perfect mirror reflection up to a depth limit. No indirect diffuse light. It never
// transmits, so its paths stay outside all volumes (path_media.h) and see no medium.
#pragma once

#include "integrators/integrator.h"

namespace penumbra {

class BasicIntegrator final : public Integrator {
public:
    explicit BasicIntegrator(const IntegratorOptions& options) : m_options(options) {}
    Spectrum Li(const Ray& ray, const RenderContext& ctx, Sampler& sampler) const override;

private:
    IntegratorOptions m_options;
};

}  // namespace penumbra
