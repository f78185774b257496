#include "materials/material.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "core/scene/emission.h"
#include "materials/fresnel.h"
#include "materials/specular_inputs.h"

namespace penumbra {

const Bsdf* BsdfStorage::get() const {
    return std::visit(
        [](const auto& b) -> const Bsdf* {
            if constexpr (std::is_base_of_v<Bsdf, std::decay_t<decltype(b)>>) return &b;
            return nullptr;
        },
        m_v);
}

namespace {

Vec4 sample_texture(const Scene& scene, const TextureRef& ref, const SurfacePoint& sp) {
    const Texture& tex = scene.textures[ref.texture];
    return lookup(tex, scene.images[tex.image], ref.uv(sp.uv0, sp.uv1));
}

// Tangent-space normal map (glTF: +X right/u, +Y up/v, Z out) to a world normal.
Vec3 apply_normal_map(const Scene& scene, const MaterialDesc& m, const SurfacePoint& sp,
                      Vec3 ns) {
    Vec3 t;
    float sign = 1;
    if (sp.tangent.w != 0) {
        t = sp.tangent.xyz();
        sign = sp.tangent.w;
    } else {
        t = sp.dpdu;
    }
    t = t - ns * dot(ns, t);
    if (!(length_squared(t) > 1e-20f)) return ns;
    t = normalize(t);
    // glTF's bitangent is cross(normal, tangent) * w. Generated frames from dp/du
    // follow the v direction of the image, which points down in glTF UVs.
    const Vec3 b = cross(ns, t) * sign;
    const Vec4 texel = sample_texture(scene, m.normal_texture, sp);
    const Vec3 local(( texel.x * 2 - 1) * m.normal_scale, (texel.y * 2 - 1) * m.normal_scale,
                     texel.z * 2 - 1);
    const Vec3 n = t * local.x + b * local.y + ns * local.z;
    const float len = length(n);
    return len > 0 && std::isfinite(len) ? n / len : ns;
}

float opacity_from_alpha(const MaterialDesc& m, float alpha) {
    switch (m.alpha_mode) {
        case AlphaMode::Opaque: return 1;
        case AlphaMode::Mask: return alpha >= m.alpha_cutoff ? 1.0f : 0.0f;
        case AlphaMode::Blend: return std::clamp(alpha, 0.0f, 1.0f);
    }
    return 1;
}

}  // namespace

float surface_opacity(const Scene& scene, const SurfacePoint& sp) {
    const MaterialDesc& m = scene.material(sp.material);
    if (m.alpha_mode == AlphaMode::Opaque) return 1;
    float alpha = m.base_color.w * sp.color.w;
    if (m.base_color_texture.valid()) alpha *= sample_texture(scene, m.base_color_texture, sp).w;
    return opacity_from_alpha(m, alpha);
}

bool scene_has_alpha(const Scene& scene) {
    for (const MaterialDesc& m : scene.materials)
        if (m.alpha_mode != AlphaMode::Opaque) return true;
    return false;
}

ShadingData shade(const Scene& scene, const SurfacePoint& sp, Vec3 wo,
                  const MaterialOptions& options) {
    const MaterialDesc& m = scene.material(sp.material);
    ShadingData sd;

    // Shade the side the viewer is on (glTF surfaces are thin sheets to the rays).
    Vec3 ns = sp.ns;
    if (m.normal_texture.valid()) {
        const Vec3 mapped = apply_normal_map(scene, m, sp, ns);
        // A mapped normal that leans past the geometric horizon would shade the wrong
        // side; keep the interpolated one there.
        if (dot(mapped, sp.ng) > 0) ns = mapped;
    }
    sd.front_face = dot(wo, sp.ng) >= 0;
    const float side = sd.front_face ? 1.0f : -1.0f;
    const Vec3 ng = sp.ng * side;
    ns = ns * side;
    sd.ng = ng;
    sd.frame = Frame::from_normal(ns);
    // KHR_materials_anisotropy turns the frame's x to the anisotropy direction.
    const float anisotropy = align_anisotropy_frame(scene, m, sp, sd.frame);

    Vec4 base = m.base_color * sp.color;
    if (m.base_color_texture.valid()) base = base * sample_texture(scene, m.base_color_texture, sp);
    sd.base_color = base.xyz();
    sd.opacity = opacity_from_alpha(m, base.w);

    float metallic = m.metallic, roughness = m.roughness;
    if (m.metallic_roughness_texture.valid()) {
        const Vec4 mr = sample_texture(scene, m.metallic_roughness_texture, sp);
        roughness *= mr.y;
        metallic *= mr.z;
    }
    metallic = std::clamp(metallic, 0.0f, 1.0f);
    roughness = std::clamp(roughness, 0.0f, 1.0f);

    sd.emission = emitted_radiance(scene, m, sp.uv0, sp.uv1);

    float transmission = m.transmission;
    if (transmission > 0 && m.transmission_texture.valid())
        transmission *= sample_texture(scene, m.transmission_texture, sp).x;
    transmission = std::clamp(transmission, 0.0f, 1.0f);

    const float specular = std::clamp(m.specular, 0.0f, 1.0f);
    if (metallic == 0 && specular == 0 && transmission == 0) {
        // KHR_materials_specular with factor 0 and no metal: exactly Lambertian.
        sd.bsdf.emplace(LambertianBsdf(sd.base_color));
        return sd;
    }
    MetalRoughParams p;
    p.base_color = sd.base_color;
    p.metallic = metallic;
    p.alpha = roughness * roughness;
    const Spectrum f0 = m.specular_color * f0_from_ior(m.ior);
    p.dielectric_f0 = min(f0, Spectrum(1)) * specular;
    p.dielectric_f90 = specular;
    p.distribution = options.gltf_distribution;
    p.layering = options.gltf_layering;
    p.anisotropy = anisotropy;
    set_iridescence(scene, m, sp, p);
    if (transmission == 0 || metallic == 1) {
        sd.bsdf.emplace(MetalRoughBsdf(p));
        return sd;
    }
    // KHR_materials_transmission: a rough dielectric with the material's IOR (exact
    // Fresnel instead of Schlick) whose refracted light takes the base colour; the
    // specular extension scales its reflection as it scales glTF's f0 and f90. The
    // frame faces wo, so the far side has IOR ior when wo is outside, 1/ior inside.
    DielectricParams d;
    const float ior = m.ior > 0 ? m.ior : 1.5f;
    d.eta = sd.front_face ? ior : 1 / ior;
    d.alpha = p.alpha;
    d.distribution = options.gltf_distribution;
    d.reflectance = min(m.specular_color, Spectrum(1)) * specular;
    d.transmittance = sd.base_color;
    sd.bsdf.emplace(GltfTransmissionBsdf(p, transmission, d));
    return sd;
}

}  // namespace penumbra
