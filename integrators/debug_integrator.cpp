#include "integrators/debug_integrator.h"

#include "core/sampling/hash.h"
#include "core/surface_point.h"
#include "materials/material.h"

namespace penumbra {

Spectrum id_color(uint32_t id) {
    const uint64_t h = mix_bits(id + 1);
    return {0.15f + 0.85f * ((h & 0xff) / 255.0f), 0.15f + 0.85f * (((h >> 8) & 0xff) / 255.0f),
            0.15f + 0.85f * (((h >> 16) & 0xff) / 255.0f)};
}

Spectrum DebugIntegrator::Li(const Ray& ray, const RenderContext& ctx, Sampler&) const {
    const Scene& scene = ctx.scene;
    const std::optional<Hit> hit = ctx.accel.intersect(ray);
    if (!hit) return Spectrum(0);
    const SurfacePoint sp = make_surface_point(scene, ray, *hit);
    switch (m_view) {
        case DebugView::ShadingNormal:
            return sp.ns * 0.5f + Spectrum(0.5f);
        case DebugView::GeometricNormal:
            return sp.ng * 0.5f + Spectrum(0.5f);
        case DebugView::Albedo:
            return shade(scene, sp, normalize(-ray.d), ctx.materials).base_color;
        case DebugView::Depth:
            return Spectrum(hit->t * length(ray.d));
        case DebugView::Uv:
            return {sp.uv0.x, sp.uv0.y, 0};
        case DebugView::Instance:
            return id_color(hit->instance);
    }
    return Spectrum(0);
}

}  // namespace penumbra
