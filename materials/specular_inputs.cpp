#include "materials/specular_inputs.h"

#include <algorithm>
#include <cmath>

#include "core/math/portable_math.h"
#include "core/texture.h"

namespace penumbra {

namespace {

Vec4 texel(const Scene& scene, const TextureRef& ref, const SurfacePoint& sp) {
    const Texture& tex = scene.textures[ref.texture];
    return lookup(tex, scene.images[tex.image], ref.uv(sp.uv0, sp.uv1),
                  ref.width(sp.uv_width[0], sp.uv_width[1]));
}

}  // namespace

float align_anisotropy_frame(const Scene& scene, const MaterialDesc& m, const SurfacePoint& sp,
                             Frame& frame) {
    float strength = std::clamp(m.anisotropy_strength, 0.0f, 1.0f);
    if (!(strength > 0)) return 0;
    // The direction in tangent space: (cos, sin) of the rotation, or the texture's RG
    // direction (normalized) rotated by it, counter-clockwise (the spec's
    // mat2(c, s, -s, c) * direction).
    const float c = portable_cos(m.anisotropy_rotation), s = portable_sin(m.anisotropy_rotation);
    Vec2 dir(c, s);
    if (m.anisotropy_texture.valid()) {
        const Vec4 t = texel(scene, m.anisotropy_texture, sp);
        Vec2 d(t.x * 2 - 1, t.y * 2 - 1);
        const float len = std::sqrt(d.x * d.x + d.y * d.y);
        d = len > 0 ? Vec2(d.x / len, d.y / len) : Vec2(1, 0);
        dir = Vec2(c * d.x - s * d.y, s * d.x + c * d.y);
        strength *= std::clamp(t.z, 0.0f, 1.0f);
        if (!(strength > 0)) return 0;
    }
    // The tangent frame as the normal map builds it (material.cpp): glTF's bitangent is
    // cross(normal, tangent) w, with the normal of the side the mesh faces, not the
    // viewer's, so that the direction is a property of the surface.
    const Vec3 n = frame.n;
    Vec3 t = sp.tangent.w != 0 ? sp.tangent.xyz() : sp.dpdu;
    const float sign = sp.tangent.w != 0 ? sp.tangent.w : 1.0f;
    t = t - n * dot(n, t);
    if (!(length_squared(t) > 1e-20f)) return 0;
    t = normalize(t);
    const float side = dot(n, sp.ng) < 0 ? -1.0f : 1.0f;
    const Vec3 b = cross(n * side, t) * sign;
    frame = Frame::from_normal_tangent(n, t * dir.x + b * dir.y);
    return strength;
}

void set_iridescence(const Scene& scene, const MaterialDesc& m, const SurfacePoint& sp,
                     MetalRoughParams& p) {
    float factor = std::clamp(m.iridescence, 0.0f, 1.0f);
    if (!(factor > 0)) return;
    float thickness = m.iridescence_thickness_max;
    if (m.iridescence_texture.valid())
        factor *= std::clamp(texel(scene, m.iridescence_texture, sp).x, 0.0f, 1.0f);
    if (m.iridescence_thickness_texture.valid()) {
        const float g = texel(scene, m.iridescence_thickness_texture, sp).y;
        thickness = m.iridescence_thickness_min +
                    (m.iridescence_thickness_max - m.iridescence_thickness_min) * g;
    }
    p.iridescence = factor;
    p.film = ThinFilm{1, m.iridescence_ior, std::max(0.0f, thickness)};
}

}  // namespace penumbra
