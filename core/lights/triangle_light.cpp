#include "core/lights/triangle_light.h"

#include <cmath>

#include "core/sampling/warp.h"
#include "core/scene/emission.h"

namespace penumbra {

TriangleLight::TriangleLight(const Scene& scene, uint32_t instance, uint32_t mesh_index,
                             uint32_t prim, Spectrum mean_Le)
    : m_scene(&scene) {
    const TriangleMesh& mesh = scene.meshes[mesh_index];
    const Transform& xf = scene.instances[instance].to_world;
    m_material = mesh.material;
    for (int k = 0; k < 3; ++k) {
        const uint32_t i = mesh.indices[3 * prim + k];
        m_p[k] = xf.point(mesh.positions[i]);
        m_uv0[k] = mesh.uv0.empty() ? Vec2() : mesh.uv0[i];
        m_uv1[k] = mesh.uv1.empty() ? Vec2() : mesh.uv1[i];
    }
    const Vec3 c = cross(m_p[1] - m_p[0], m_p[2] - m_p[0]);
    const float len = length(c);
    m_area = 0.5f * len;
    m_n = len > 0 ? c / len : Vec3(0, 0, 1);
    m_power = 2 * kPi * m_area * luminance(mean_Le);  // two-sided
}

float TriangleLight::pdf_at(Vec3 ref, Vec3 p) const {
    const Vec3 d = p - ref;
    const float dist2 = length_squared(d);
    const float cos_light = std::abs(dot(m_n, d)) / std::sqrt(dist2);
    if (!(cos_light > 0) || !(m_area > 0)) return 0;
    // Area density 1/A to solid angle: dist^2 / (|cos| A).
    return dist2 / (cos_light * m_area);
}

std::optional<LightSample> TriangleLight::sample_Li(const ShadingPoint& ref, Vec2 u,
                                                    float) const {
    if (!(m_area > 0)) return std::nullopt;
    const Vec2 b = square_to_triangle(u);
    const float b0 = 1 - b.x - b.y;
    const Vec3 p = m_p[0] * b0 + m_p[1] * b.x + m_p[2] * b.y;
    const Vec3 d = p - ref.p;
    const float dist2 = length_squared(d);
    if (!(dist2 > 0)) return std::nullopt;
    const float dist = std::sqrt(dist2);
    const Vec3 wi = d / dist;
    const float pdf = pdf_at(ref.p, p);
    if (!(pdf > 0) || !std::isfinite(pdf)) return std::nullopt;
    const Vec2 uv0 = m_uv0[0] * b0 + m_uv0[1] * b.x + m_uv0[2] * b.y;
    const Vec2 uv1 = m_uv1[0] * b0 + m_uv1[1] * b.x + m_uv1[2] * b.y;
    const Spectrum Le = emitted_radiance(*m_scene, m_scene->material(m_material), uv0, uv1);
    if (is_black(Le)) return std::nullopt;
    return LightSample{Le, wi, dist, pdf, false};
}

float TriangleLight::pdf_Li(const ShadingPoint& ref, Vec3 wi) const {
    // Moller-Trumbore: only used for MIS weights, never for visibility.
    const Vec3 e1 = m_p[1] - m_p[0], e2 = m_p[2] - m_p[0];
    const Vec3 pv = cross(wi, e2);
    const float det = dot(e1, pv);
    if (det == 0) return 0;
    const Vec3 tv = ref.p - m_p[0];
    const float b1 = dot(tv, pv) / det;
    if (b1 < 0 || b1 > 1) return 0;
    const Vec3 qv = cross(tv, e1);
    const float b2 = dot(wi, qv) / det;
    if (b2 < 0 || b1 + b2 > 1) return 0;
    const float t = dot(e2, qv) / det;
    if (!(t > 0)) return 0;
    return pdf_at(ref.p, ref.p + wi * t);
}

float TriangleLight::power() const { return m_power; }

}  // namespace penumbra
