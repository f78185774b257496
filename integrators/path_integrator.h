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
    Spectrum Li_from_hit(const Ray& ray, const std::optional<Hit>& hit, const RenderContext& ctx,
                         Sampler& sampler, FirstVertex* first = nullptr) const override;
    bool uses_first_hit() const override { return true; }
    // Under MIS every vertex that samples a light also samples its BSDF, and the ray of
    // that sample finds the environment's light with the MIS weight.
    bool pairs_light_and_bsdf_samples() const override {
        return m_options.strategy == LightStrategy::Mis;
    }

private:
    // The path loop; first_hit: the camera ray's closest hit when traced already (nullptr:
    // trace it); first: where given, filled with the first vertex (FirstVertex). Instantiated per
    // scene kind, so that a scene without volumes or alpha does none of their work per bounce
    // (decided once per call, from RenderContext).
    template <bool kMedia, bool kAlpha>
    Spectrum trace(const Ray& ray, const std::optional<Hit>* first_hit, const RenderContext& ctx,
                   Sampler& sampler, FirstVertex* first) const;
    Spectrum dispatch(const Ray& ray, const std::optional<Hit>* first_hit, const RenderContext& ctx,
                      Sampler& sampler, FirstVertex* first) const;
    IntegratorOptions m_options;
};

}  // namespace penumbra
