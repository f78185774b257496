// Debug views of the first hit: shading normal, geometric normal, albedo, depth, UV and
// instance id. Misses are black (depth: 0).
#pragma once

#include "integrators/integrator.h"

namespace penumbra {

enum class DebugView { ShadingNormal, GeometricNormal, Albedo, Depth, Uv, Instance };

class DebugIntegrator final : public Integrator {
public:
    explicit DebugIntegrator(DebugView view) : m_view(view) {}
    // Normals are world space, mapped to [0,1] as 0.5 n + 0.5 for viewing; depth is the
    // distance along the (unit) camera ray; uv is (u, v, 0); instances get a hashed colour.
    Spectrum Li(const Ray& ray, const RenderContext& ctx, Sampler& sampler) const override;

private:
    DebugView m_view;
};

// A stable, well-spread colour for an integer id.
Spectrum id_color(uint32_t id);

}  // namespace penumbra
