// An emissive triangle of one instance, in world space: an area light. Sampled uniformly
// in the solid angle it subtends, warped by the receiver's cosine (spherical_triangle.h),
// or uniformly by area. Emits from its glTF front face only, or from both when the
// material is doubleSided (emits_towards).
#pragma once

#include "core/lights/light.h"
#include "core/scene/scene.h"

namespace penumbra {

// How sample_Li picks points. SolidAngle falls back to Area where the solid angle is too
// small for float precision or nearly a hemisphere (pbrt-v4's MinSphericalSampleArea and
// MaxSphericalSampleArea), decided from the receiver alone so pdf_Li decides the same.
enum class TriangleSampling { Area, SolidAngle };

class TriangleLight final : public Light {
public:
    // mean_Le: the material's mean emitted radiance (for the power estimate), computed
    // once per material by the caller.
    TriangleLight(const Scene& scene, uint32_t instance, uint32_t mesh, uint32_t prim,
                  Spectrum mean_Le, TriangleSampling sampling = TriangleSampling::Area);
    // Empty when ref is behind a single-sided triangle (or in its plane).
    std::optional<LightSample> sample_Li(const ShadingPoint& ref, Vec2 u,
                                         float time) const override;
    // Finds where the ray (ref.p, wi) meets the triangle; 0 if it misses or arrives
    // from behind a single-sided triangle.
    float pdf_Li(const ShadingPoint& ref, Vec3 wi, float time) const override;
    // Solid-angle density of sampling point p of the triangle (where it is at time)
    // from ref; 0 when ref is behind a single-sided triangle.
    float pdf_at(const ShadingPoint& ref, Vec3 p, float time) const;
    // pi A luminance(Le) per emitting side, at shutter open.
    float power() const override;
    bool two_sided() const { return m_two_sided; }
    bool is_delta() const override { return false; }
    // Empty for a triangle that moves within the shutter.
    std::optional<LightBounds> bounds() const override;
    TriangleSampling sampling() const { return m_sampling; }
    std::string describe() const override { return "triangle"; }
    float area() const { return m_area; }  // at shutter open

private:
    // The triangle in world space at a time. A static triangle is placed once; one on a
    // moving instance or a deforming mesh is placed at the ray's time exactly as
    // make_surface_point places its hits (core/scene/motion.h), so light samples and the
    // MIS densities of BSDF-sampled hits describe the same triangle.
    struct Placed {
        Vec3 p[3];
        Vec3 n;  // unit normal out of the glTF front face (as SurfacePoint's front_normal)
        float area;
    };
    // The static triangle itself, or the one placed at time in *scratch.
    const Placed& placed(float time, Placed* scratch) const;
    // mirrored: the transform swaps handedness, so the front face winds clockwise.
    static Placed place(Vec3 p0, Vec3 p1, Vec3 p2, bool mirrored);
    // Solid-angle density of area sampling at ref for point p of t; 0 from behind a
    // single-sided triangle. area_pdf: the same from d = p - ref, dist2 = |d|^2 and
    // dist = sqrt(dist2), which sample_Li has anyway.
    float solid_angle_pdf(Vec3 ref, Vec3 p, const Placed& t) const;
    float area_pdf(Vec3 d, float dist2, float dist, const Placed& t) const;
    // emits_towards(material, n, w) with the material's doubleSided kept here.
    bool emits_to(Vec3 n, Vec3 w) const { return m_two_sided || dot(n, w) > 0; }
    // Emitted radiance at barycentrics (b1, b2) and normalized shutter time `time`, times
    // the material's coverage there: an emitter with alpha sends as much light as a
    // camera path sees of it.
    Spectrum Le_at(float b0, float b1, float b2, float time) const;
    // The solid angle of t at ref when sample_Li samples it spherically there, else 0.
    float spherical_solid_angle(Vec3 ref, const Placed& t) const;
    // The density of sample_Li choosing point p of t from ref (either strategy).
    float density(const ShadingPoint& ref, Vec3 p, const Placed& t) const;

    const Scene* m_scene;
    uint32_t m_instance, m_mesh, m_prim;
    bool m_moving;
    bool m_two_sided;
    TriangleSampling m_sampling;
    int m_material;
    Placed m_static;  // at shutter open
    Vec2 m_uv0[3], m_uv1[3];
    // Without an emissive texture the radiance is the same everywhere: kept here, not
    // looked up through the material per sample.
    bool m_textured;
    bool m_covered;  // alphaMode MASK or BLEND: Le_at weighs by the coverage
    bool m_timed;    // the material changes within the shutter (Scene::material_at)
    float m_vertex_alpha[3];  // COLOR_0's alpha (1 without)
    Spectrum m_Le;
    float m_area;
    float m_power;
};

}  // namespace penumbra
