// An emissive triangle of one instance, in world space: an area light. Sampled
// uniformly by area and converted to solid angle at the receiver. Emits from both sides
// (glTF surfaces are thin sheets).
#pragma once

#include "core/lights/light.h"
#include "core/scene/scene.h"

namespace penumbra {

class TriangleLight final : public Light {
public:
    // mean_Le: the material's mean emitted radiance (for the power estimate), computed
    // once per material by the caller.
    TriangleLight(const Scene& scene, uint32_t instance, uint32_t mesh, uint32_t prim,
                  Spectrum mean_Le);
    std::optional<LightSample> sample_Li(const ShadingPoint& ref, Vec2 u,
                                         float time) const override;
    // Finds where the ray (ref.p, wi) meets the triangle; 0 if it misses.
    float pdf_Li(const ShadingPoint& ref, Vec3 wi) const override;
    // Solid-angle density of sampling point p (with unit normal n) from ref.
    float pdf_at(Vec3 ref, Vec3 p) const;
    float power() const override;
    bool is_delta() const override { return false; }
    std::string describe() const override { return "triangle"; }
    float area() const { return m_area; }

private:
    const Scene* m_scene;
    int m_material;
    Vec3 m_p[3];
    Vec3 m_n;  // unit geometric normal
    Vec2 m_uv0[3], m_uv1[3];
    float m_area;
    float m_power;
};

}  // namespace penumbra
