// Unidirectional path tracing with next-event estimation and multiple importance
// sampling (power heuristic) between light and BSDF sampling (Veach 1997, ch. 9), and
// Russian roulette. The strategy option turns one of the two estimators off. The path
// carries the volumes it is in (path_media.h): each segment and shadow ray is attenuated
// by its medium's transmittance, and a dispersive volume fixes the path's colour channel.
#pragma once

#include "integrators/integrator.h"

namespace penumbra {

class PathIntegrator final : public Integrator {
public:
    explicit PathIntegrator(const IntegratorOptions& options) : m_options(options) {}
    Spectrum Li(const Ray& ray, const RenderContext& ctx, Sampler& sampler) const override;

private:
    IntegratorOptions m_options;
};

}  // namespace penumbra
