#include "core/lights/triangle_light.h"

#include <cmath>

#include "core/lights/spherical_triangle.h"
#include "core/sampling/warp.h"
#include "core/scene/coverage.h"
#include "core/scene/emission.h"
#include "core/scene/motion.h"

namespace penumbra {

TriangleLight::TriangleLight(const Scene& scene, uint32_t instance, uint32_t mesh_index,
                             uint32_t prim, Spectrum mean_Le, TriangleSampling sampling)
    : m_scene(&scene),
      m_instance(instance),
      m_mesh(mesh_index),
      m_prim(prim),
      m_sampling(sampling) {
    const TriangleMesh& mesh = scene.meshes[mesh_index];
    const Instance& inst = scene.instances[instance];
    m_moving = !inst.motion.empty() || !mesh.motion_positions.empty();
    m_material = mesh.material;
    m_two_sided = scene.material(m_material).double_sided;
    Vec3 p[3];
    for (int k = 0; k < 3; ++k) {
        const uint32_t i = mesh.indices[3 * prim + k];
        p[k] = inst.to_world.point(mesh.positions[i]);
        m_uv0[k] = mesh.uv0.empty() ? Vec2() : mesh.uv0[i];
        m_uv1[k] = mesh.uv1.empty() ? Vec2() : mesh.uv1[i];
        m_vertex_alpha[k] = mesh.colors.empty() ? 1.0f : mesh.colors[i].w;
    }
    m_static = place(p[0], p[1], p[2], inst.to_world.swaps_handedness());
    const MaterialDesc& mat = scene.material(m_material);
    m_Le = mat.emissive * mat.emissive_strength;  // as emitted_radiance starts
    m_textured = mat.emissive_texture.valid() && !is_black(m_Le);
    m_covered = mat.alpha_mode != AlphaMode::Opaque;
    m_timed = scene.material_varies(instance, m_material);
    m_area = m_static.area;
    // Power only chooses among lights: any positive estimate keeps sampling unbiased,
    // so a moving triangle is weighed by its size at shutter open. A Lambertian emitter
    // sends pi A Le from each side it emits from.
    m_power = (m_two_sided ? 2 : 1) * kPi * m_area * luminance(mean_Le);
}

TriangleLight::Placed TriangleLight::place(Vec3 p0, Vec3 p1, Vec3 p2, bool mirrored) {
    Placed t{{p0, p1, p2}, Vec3(0, 0, 1), 0};
    // The world-space winding normal; a mirroring transform reverses the winding, and
    // glTF's front face with it (glTF 2.0, 3.7.2.1). make_surface_point's inverse-
    // transpose normal of the object-space winding gives the same side.
    const Vec3 c = cross(p1 - p0, p2 - p0);
    const float len = length(c);
    t.area = 0.5f * len;
    if (len > 0) t.n = (mirrored ? -c : c) / len;
    return t;
}

const TriangleLight::Placed& TriangleLight::placed(float time, Placed* scratch) const {
    if (!m_moving) return m_static;
    const TriangleMesh& mesh = m_scene->meshes[m_mesh];
    const Transform xf = instance_transform_at(m_scene->instances[m_instance], time);
    Vec3 p[3];
    for (int k = 0; k < 3; ++k)
        p[k] = xf.point(position_at(mesh, mesh.indices[3 * m_prim + k], time));
    *scratch = place(p[0], p[1], p[2], xf.swaps_handedness());
    return *scratch;
}

float TriangleLight::area_pdf(Vec3 d, float dist2, float dist, const Placed& t) const {
    // Area density 1/A to solid angle at ref: dist^2 / (|cos| A). Behind a single-sided
    // triangle nothing is emitted towards ref, so sample_Li never goes there and the
    // density of reaching it is 0, as the MIS weights of BSDF-found hits need.
    if (!emits_to(t.n, -d)) return 0;
    const float cos_light = std::abs(dot(t.n, d)) / dist;
    if (!(cos_light > 0) || !(t.area > 0)) return 0;
    return dist2 / (cos_light * t.area);
}

float TriangleLight::solid_angle_pdf(Vec3 ref, Vec3 p, const Placed& t) const {
    const Vec3 d = p - ref;
    const float dist2 = length_squared(d);
    return area_pdf(d, dist2, std::sqrt(dist2), t);
}

Spectrum TriangleLight::Le_at(float b0, float b1, float b2, float time) const {
    if (!m_textured && !m_covered && !m_timed) return m_Le;
    const Vec2 uv0 = m_uv0[0] * b0 + m_uv0[1] * b1 + m_uv0[2] * b2;
    const Vec2 uv1 = m_uv1[0] * b0 + m_uv1[1] * b1 + m_uv1[2] * b2;
    if (m_timed) {
        // The material at the sample's time, as make_surface_point gives a hit there.
        const MaterialDesc& m =
            m_scene->material(m_scene->material_at(m_instance, m_material, time));
        const float alpha =
            m_vertex_alpha[0] * b0 + m_vertex_alpha[1] * b1 + m_vertex_alpha[2] * b2;
        return emitted_radiance(*m_scene, m, uv0, uv1) *
               material_coverage(*m_scene, m, uv0, uv1, alpha);
    }
    const MaterialDesc& m = m_scene->material(m_material);
    const Spectrum Le = m_textured ? emitted_radiance(*m_scene, m, uv0, uv1) : m_Le;
    if (!m_covered) return Le;
    const float alpha =
        m_vertex_alpha[0] * b0 + m_vertex_alpha[1] * b1 + m_vertex_alpha[2] * b2;
    return Le * material_coverage(*m_scene, m, uv0, uv1, alpha);
}

namespace {
// pbrt-v4's limits (Triangle::MinSphericalSampleArea, MaxSphericalSampleArea): below,
// Arvo's trigonometry loses the triangle's shape to float rounding, where area sampling
// is already nearly uniform in solid angle; near 2 pi the triangle almost fills the
// hemisphere and its edges' great circles become ill-conditioned.
constexpr float kMinSphericalArea = 3e-4f, kMaxSphericalArea = 6.22f;

bool has_normal(const ShadingPoint& ref) { return ref.n.x != 0 || ref.n.y != 0 || ref.n.z != 0; }
}  // namespace

float TriangleLight::spherical_solid_angle(Vec3 ref, const Placed& t) const {
    if (m_sampling != TriangleSampling::SolidAngle) return 0;
    const float omega = triangle_solid_angle(t.p, ref);
    return omega >= kMinSphericalArea && omega <= kMaxSphericalArea ? omega : 0.0f;
}

float TriangleLight::density(const ShadingPoint& ref, Vec3 p, const Placed& t) const {
    const float omega = spherical_solid_angle(ref.p, t);
    if (!(omega > 0)) return solid_angle_pdf(ref.p, p, t);
    const Vec3 d = p - ref.p;
    if (!emits_to(t.n, -d)) return 0;
    float pdf = 1 / omega;
    if (has_normal(ref)) {
        // The warp's density at the square point that maps to this direction.
        float w[4];
        receiver_cosine_weights(t.p, ref.p, ref.n, w);
        pdf *= bilinear_pdf(invert_spherical_triangle_sample(t.p, ref.p, normalize(d)), w);
    }
    return pdf;
}

float TriangleLight::pdf_at(const ShadingPoint& ref, Vec3 p, float time) const {
    Placed scratch;
    return density(ref, p, placed(time, &scratch));
}

std::optional<LightSample> TriangleLight::sample_Li(const ShadingPoint& ref, Vec2 u,
                                                    float time) const {
    Placed scratch;
    const Placed& t = placed(time, &scratch);
    if (!(t.area > 0)) return std::nullopt;
    float b0, b1, b2, pdf = 0;  // 0: GCC cannot see both branches set it
    Vec3 p;
    const float omega = spherical_solid_angle(ref.p, t);
    if (omega > 0) {
        // A planar triangle emits towards ref from all its points or from none.
        if (!emits_to(t.n, ref.p - t.p[0])) return std::nullopt;
        pdf = 1 / omega;
        if (has_normal(ref)) {
            // Warp product sampling (pbrt-v4, 6.5.4): the square first goes through a
            // bilinear density that follows |cos| at the receiver towards each vertex.
            float w[4];
            receiver_cosine_weights(t.p, ref.p, ref.n, w);
            u = sample_bilinear(u, w);
            pdf *= bilinear_pdf(u, w);
        }
        const std::optional<Vec3> b = sample_spherical_triangle(t.p, ref.p, u);
        if (!b) return std::nullopt;
        b0 = b->x, b1 = b->y, b2 = b->z;
    } else {
        const Vec2 b = square_to_triangle(u);
        b0 = 1 - b.x - b.y, b1 = b.x, b2 = b.y;
    }
    p = t.p[0] * b0 + t.p[1] * b1 + t.p[2] * b2;
    const Vec3 d = p - ref.p;
    const float dist2 = length_squared(d);
    if (!(dist2 > 0)) return std::nullopt;
    const float dist = std::sqrt(dist2);
    // Area sampling's density from the distance just found, not a second pass over p.
    if (!(omega > 0)) pdf = area_pdf(d, dist2, dist, t);
    if (!(pdf > 0) || !std::isfinite(pdf)) return std::nullopt;
    const Spectrum Le = Le_at(b0, b1, b2, time);
    if (is_black(Le)) return std::nullopt;
    return LightSample{d / dist, dist, Le, pdf, false, p};
}

float TriangleLight::pdf_Li(const ShadingPoint& ref, Vec3 wi, float time) const {
    // Moller-Trumbore: only used for MIS weights, never for visibility.
    Placed scratch;
    const Placed& tri = placed(time, &scratch);
    const Vec3 e1 = tri.p[1] - tri.p[0], e2 = tri.p[2] - tri.p[0];
    const Vec3 pv = cross(wi, e2);
    const float det = dot(e1, pv);
    if (det == 0) return 0;
    const Vec3 tv = ref.p - tri.p[0];
    const float b1 = dot(tv, pv) / det;
    if (b1 < 0 || b1 > 1) return 0;
    const Vec3 qv = cross(tv, e1);
    const float b2 = dot(wi, qv) / det;
    if (b2 < 0 || b1 + b2 > 1) return 0;
    const float t = dot(e2, qv) / det;
    if (!(t > 0)) return 0;
    return density(ref, ref.p + wi * t, tri);
}

float TriangleLight::power() const { return m_power; }

std::optional<LightBounds> TriangleLight::bounds() const {
    if (m_moving || !(m_power > 0)) return std::nullopt;
    LightBounds b;
    b.lo = min(m_static.p[0], min(m_static.p[1], m_static.p[2]));
    b.hi = max(m_static.p[0], max(m_static.p[1], m_static.p[2]));
    b.phi = m_power;
    b.w = m_static.n;
    b.cos_theta_o = 1;
    b.cos_theta_e = 0;  // Lambertian: emission spreads pi/2 about the normal
    b.two_sided = m_two_sided;
    return b;
}

}  // namespace penumbra
