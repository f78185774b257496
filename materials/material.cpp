#include "materials/material.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "core/media/medium_set.h"
#include "core/scene/coverage.h"
#include "core/scene/emission.h"
#include "materials/bsdf_prototypes.h"
#include "materials/lobes/dispersion.h"
#include "materials/lobes/fresnel.h"
#include "materials/normal_map.h"
#include "materials/specular_inputs.h"

namespace penumbra {

const Bsdf* BsdfStorage::held() const {
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
    return lookup(tex, scene.images[tex.image], ref.uv(sp.uv0, sp.uv1),
                  ref.width(sp.uv_width[0], sp.uv_width[1]));
}

// Tangent-space normal map (glTF: +X right/u, +Y up/v, Z out) to a world normal.
Vec3 apply_normal_map(const Scene& scene, const TextureRef& map, float scale,
                      const SurfacePoint& sp, Vec3 ns) {
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
    const Vec4 texel = sample_texture(scene, map, sp);
    const Vec3 local((texel.x * 2 - 1) * scale, (texel.y * 2 - 1) * scale, texel.z * 2 - 1);
    const Vec3 n = t * local.x + b * local.y + ns * local.z;
    const float len = length(n);
    return len > 0 && std::isfinite(len) ? n / len : ns;
}

// A mapped normal that leans past the geometric horizon would shade the wrong side;
// keep the interpolated one there.
Vec3 mapped_normal(const Scene& scene, const TextureRef& map, float scale, const SurfacePoint& sp) {
    if (!map.valid()) return sp.ns;
    const Vec3 mapped = apply_normal_map(scene, map, scale, sp, sp.ns);
    return dot(mapped, sp.ng) > 0 ? mapped : sp.ns;
}

Spectrum clamp01(Spectrum s) {
    return {std::clamp(s.x, 0.0f, 1.0f), std::clamp(s.y, 0.0f, 1.0f), std::clamp(s.z, 0.0f, 1.0f)};
}

// The emissive factor times its strength is not black: the one test of whether shade()
// reads the material's emission (unlit materials aside), shared with scene_has_emission.
inline bool has_emission_factor(const MaterialDesc& m) {
    return !is_black(m.emissive * m.emissive_strength);
}

// The shading frame on the side the viewer is on (glTF surfaces are thin sheets to the
// rays), normal-mapped, and turned to the anisotropy direction where the material has one
// (KHR_materials_anisotropy). Returns the anisotropy (0 without).
[[gnu::always_inline]] inline float orient_frame(const Scene& scene, const MaterialDesc& m,
                                                 const SurfacePoint& sp, Vec3 wo, ShadingData& sd) {
    Vec3 ns = mapped_normal(scene, m.normal_texture, m.normal_scale, sp);
    sd.front_face = dot(wo, sp.ng) >= 0;
    const float side = sd.front_face ? 1.0f : -1.0f;
    const Vec3 ng = sp.ng * side;
    sd.ng = ng;
    sd.n_side = side_normal(sp, ng);
    ns = ns * side;
    if (m.normal_texture.valid()) ns = valid_reflection_normal(sd.n_side, wo, ns);
    sd.frame = Frame::from_normal(ns);
    sd.bumped = !(sd.n_side == sd.frame.n);
    // The call only where there is anisotropy to align (it returns 0 for the rest).
    return m.anisotropy_strength > 0 ? align_anisotropy_frame(scene, m, sp, sd.frame) : 0.0f;
}

// The material's inputs that only the models built per hit read, each its factor times
// its texture, clamped to its range.
struct MaterialInputs {
    float metallic, roughness, specular, transmission, coat;
    Spectrum specular_color, sheen_color;
    DiffuseTransmissionParams dt;
    // A clearcoat, sheen or diffuse transmission over the core model.
    bool layered() const { return coat > 0 || max_component(sheen_color) > 0 || dt.factor > 0; }
};

// Metalness, roughness and the specular colour, from either workflow.
[[gnu::always_inline]] inline void evaluate_specular_inputs(const Scene& scene,
                                                            const MaterialDesc& m,
                                                            const SurfacePoint& sp,
                                                            MaterialInputs& in) {
    in.metallic = m.metallic;
    in.roughness = m.roughness;
    in.specular_color = m.specular_color;
    in.specular = m.specular;
    if (m.specular_glossiness) {
        // KHR_materials_pbrSpecularGlossiness: the diffuse colour is the base, f0 the
        // specular colour, f90 1, roughness 1 - glossiness; no metal.
        in.metallic = 0;
        float glossiness = 1 - m.roughness;
        if (m.specular_glossiness_texture.valid()) {
            const Vec4 sg = sample_texture(scene, m.specular_glossiness_texture, sp);
            in.specular_color = in.specular_color * sg.xyz();
            glossiness *= sg.w;
        }
        in.roughness = 1 - glossiness;
    } else if (m.metallic_roughness_texture.valid()) {
        const Vec4 mr = sample_texture(scene, m.metallic_roughness_texture, sp);
        in.roughness *= mr.y;
        in.metallic *= mr.z;
    }
    in.metallic = std::clamp(in.metallic, 0.0f, 1.0f);
}

[[gnu::always_inline]] inline MaterialInputs evaluate_inputs(const Scene& scene,
                                                             const MaterialDesc& m,
                                                             const SurfacePoint& sp) {
    MaterialInputs in;
    evaluate_specular_inputs(scene, m, sp, in);
    in.transmission = m.transmission;
    if (in.transmission > 0 && m.transmission_texture.valid())
        in.transmission *= sample_texture(scene, m.transmission_texture, sp).x;
    in.transmission = std::clamp(in.transmission, 0.0f, 1.0f);

    // KHR_materials_specular's textures: A scales the factor, RGB the colour.
    if (m.specular_texture.valid()) in.specular *= sample_texture(scene, m.specular_texture, sp).w;
    in.specular = std::clamp(in.specular, 0.0f, 1.0f);

    // The layers, each only where it is active.
    in.coat = m.clearcoat;
    if (in.coat > 0 && m.clearcoat_texture.valid())
        in.coat *= sample_texture(scene, m.clearcoat_texture, sp).x;
    in.coat = std::clamp(in.coat, 0.0f, 1.0f);
    in.sheen_color = m.sheen_color;
    if (max_component(in.sheen_color) > 0 && m.sheen_color_texture.valid())
        in.sheen_color = in.sheen_color * sample_texture(scene, m.sheen_color_texture, sp).xyz();
    in.sheen_color = clamp01(in.sheen_color);
    in.dt.factor = m.diffuse_transmission;
    if (in.dt.factor > 0 && m.diffuse_transmission_texture.valid())
        in.dt.factor *= sample_texture(scene, m.diffuse_transmission_texture, sp).w;
    in.dt.factor = std::clamp(in.dt.factor, 0.0f, 1.0f);
    if (in.metallic == 1) in.dt.factor = 0;  // a metal has no diffuse base to split
    return in;
}

// The glTF metallic-roughness model's parameters (roughness already raised to the
// options' least and clamped).
[[gnu::always_inline]] inline MetalRoughParams metal_rough_params(
    const Scene& scene, const MaterialDesc& m, const SurfacePoint& sp, const MaterialInputs& in,
    const MaterialOptions& options, Spectrum base_color, float anisotropy) {
    MetalRoughParams p;
    p.base_color = base_color;
    p.metallic = in.metallic;
    p.alpha = in.roughness * in.roughness;
    if (m.specular_glossiness) {
        p.dielectric_f0 = clamp01(in.specular_color);
        p.dielectric_f90 = 1;
    } else {
        const Spectrum f0 = in.specular_color * f0_from_ior(m.ior);
        p.dielectric_f0 = min(f0, Spectrum(1)) * in.specular;
        p.dielectric_f90 = in.specular;
    }
    p.distribution = options.gltf_distribution;
    p.layering = options.gltf_layering;
    p.anisotropy = anisotropy;
    set_iridescence(scene, m, sp, p);
    return p;
}

// KHR_materials_transmission: a rough dielectric with the material's IOR (exact
// Fresnel instead of Schlick) whose refracted light takes the base colour; the
// specular extension scales its reflection as it scales glTF's f0 and f90. The
// frame faces wo, so the far side has IOR ior when wo is outside, 1/ior inside.
// Without KHR_materials_volume the surface is a thin sheet with IOR 1 on both sides;
// dispersion (which needs a volume) refracts at the path's channel's IOR, and the
// path's media give the IOR ratio at nested volumes.
[[gnu::always_inline]] inline DielectricParams dielectric_params(
    const MaterialDesc& m, const MaterialInputs& in, const MetalRoughParams& p,
    const MaterialOptions& options, const PathVolume& path, const ShadingData& sd, bool volume) {
    DielectricParams d;
    const float ior = dispersion_ior(m.ior > 0 ? m.ior : 1.5f, volume ? m.dispersion : 0,
                                     path.dispersion_channel);
    d.eta = volume && path.eta > 0 ? path.eta : sd.front_face || !volume ? ior : 1 / ior;
    d.alpha = p.alpha;
    d.distribution = options.gltf_distribution;
    d.reflectance = min(in.specular_color, Spectrum(1)) * in.specular;
    d.transmittance = sd.base_color;
    // KHR_materials_iridescence: the film's Fresnel on the dielectric's reflection and
    // refraction alike, the film on the outside (the viewer's side on a front face).
    d.iridescence = p.iridescence;
    d.film = p.film;
    d.film_above = sd.front_face;
    return d;
}

// KHR_materials_sheen's lobe, where the sheen colour is not black.
std::optional<SheenLobe> sheen_lobe(const Scene& scene, const MaterialDesc& m,
                                    const SurfacePoint& sp, Spectrum sheen_color) {
    if (!(max_component(sheen_color) > 0)) return std::nullopt;
    float sheen_roughness = m.sheen_roughness;
    if (m.sheen_roughness_texture.valid())
        sheen_roughness *= sample_texture(scene, m.sheen_roughness_texture, sp).w;
    return SheenLobe(sheen_color, std::clamp(sheen_roughness, 0.0f, 1.0f));
}

// KHR_materials_clearcoat's lobe, where the coat is not 0, in the base's frame.
std::optional<ClearcoatLobe> clearcoat_lobe(const Scene& scene, const MaterialDesc& m,
                                            const SurfacePoint& sp, Vec3 wo, float coat,
                                            const MaterialOptions& options, const ShadingData& sd) {
    if (!(coat > 0)) return std::nullopt;
    float coat_roughness = m.clearcoat_roughness;
    if (m.clearcoat_roughness_texture.valid())
        coat_roughness *= sample_texture(scene, m.clearcoat_roughness_texture, sp).y;
    coat_roughness = std::clamp(std::max(coat_roughness, options.min_roughness), 0.0f, 1.0f);
    // The coat has its own normal map; without one it follows the interpolated
    // normal, not the base's normal map (the clearcoat spec's clearcoatNormalTexture).
    // Bent as the base's normal is (valid_reflection_normal), so that the coat's
    // mirror direction stays above the surface too.
    const float side = sd.front_face ? 1.0f : -1.0f;
    Vec3 nc = mapped_normal(scene, m.clearcoat_normal_texture, m.clearcoat_normal_scale, sp) * side;
    if (m.clearcoat_normal_texture.valid()) nc = valid_reflection_normal(sd.n_side, wo, nc);
    nc = sd.frame.to_local(nc);
    if (!(nc.z > 1e-4f)) nc = Vec3(0, 0, 1);  // behind the base normal: no separate frame
    return ClearcoatLobe(coat, coat_roughness * coat_roughness, normalize(nc),
                         options.gltf_distribution);
}

// The layered model: a core (diffuse transmission, metal-rough or transmission) under
// the sheen and clearcoat lobes. KHR_materials_diffuse_transmission splits the diffuse
// base (factor texture A, colour texture RGB).
void emplace_layered(const Scene& scene, const MaterialDesc& m, const SurfacePoint& sp, Vec3 wo,
                     const MaterialOptions& options, MaterialInputs& in, const MetalRoughParams& p,
                     const DielectricParams& d, bool volume, bool opaque, ShadingData& sd) {
    DiffuseTransmissionParams& dt = in.dt;
    dt.color = m.diffuse_transmission_color;
    if (dt.factor > 0 && m.diffuse_transmission_color_texture.valid())
        dt.color = dt.color * sample_texture(scene, m.diffuse_transmission_color_texture, sp).xyz();
    dt.color = clamp01(dt.color);
    const float transmission = in.transmission;
    const GltfBsdf::Core core =
        dt.factor > 0 ? GltfBsdf::Core(GltfDiffuseTransmissionBsdf(p, dt, transmission, d, !volume))
        : opaque      ? GltfBsdf::Core(MetalRoughBsdf(p))
                      : GltfBsdf::Core(GltfTransmissionBsdf(p, transmission, d, !volume));
    sd.bsdf.emplace<GltfBsdf>(core, sheen_lobe(scene, m, sp, in.sheen_color),
                              clearcoat_lobe(scene, m, sp, wo, in.coat, options, sd));
}

// The model built at this hit from the material's inputs: Lambertian where nothing
// else is active, else metal-rough or transmission, layered where a layer is active.
void emplace_model(const Scene& scene, const MaterialDesc& m, const SurfacePoint& sp, Vec3 wo,
                   const MaterialOptions& options, const PathVolume& path, float anisotropy,
                   ShadingData& sd) {
    MaterialInputs in = evaluate_inputs(scene, m, sp);
    const bool layered = in.layered();
    if (!layered && in.metallic == 0 && in.specular == 0 && in.transmission == 0) {
        // KHR_materials_specular with factor 0 and no metal: exactly Lambertian.
        sd.bsdf.emplace<LambertianBsdf>(sd.base_color);
        return;
    }
    in.roughness = std::clamp(std::max(in.roughness, options.min_roughness), 0.0f, 1.0f);
    if (m.specular_color_texture.valid())
        in.specular_color =
            in.specular_color * sample_texture(scene, m.specular_color_texture, sp).xyz();
    const MetalRoughParams p =
        metal_rough_params(scene, m, sp, in, options, sd.base_color, anisotropy);
    const bool volume = material_has_volume(m);
    const DielectricParams d = dielectric_params(m, in, p, options, path, sd, volume);
    const bool opaque = in.transmission == 0 || in.metallic == 1;
    if (layered) {
        emplace_layered(scene, m, sp, wo, options, in, p, d, volume, opaque, sd);
    } else if (opaque) {
        sd.bsdf.emplace<MetalRoughBsdf>(p);
    } else {
        sd.bsdf.emplace<GltfTransmissionBsdf>(p, in.transmission, d, !volume);
    }
}

}  // namespace

float surface_opacity(const Scene& scene, const SurfacePoint& sp) {
    return material_coverage(scene, scene.material(sp.material), sp.uv0, sp.uv1, sp.color.w,
                             sp.uv_width);
}

bool scene_has_alpha(const Scene& scene) {
    for (const MaterialDesc& m : scene.materials)
        if (m.alpha_mode != AlphaMode::Opaque) return true;
    return false;
}

bool scene_has_emission(const Scene& scene) {
    for (const MaterialDesc& m : scene.materials)
        if (m.unlit || has_emission_factor(m)) return true;
    return false;
}

ShadingData shade(const Scene& scene, const SurfacePoint& sp, Vec3 wo,
                  const MaterialOptions& options, const PathVolume& path) {
    const MaterialDesc& m = scene.material(sp.material);
    ShadingData sd;
    const float anisotropy = orient_frame(scene, m, sp, wo, sd);

    Vec4 base = m.base_color * sp.color;
    if (m.base_color_texture.valid()) base = base * sample_texture(scene, m.base_color_texture, sp);
    sd.base_color = base.xyz();
    sd.opacity = coverage_from_alpha(m, base.w);

    if (m.unlit) {
        // KHR_materials_unlit: the base colour (factor x texture x vertex colour) as
        // emitted radiance, and nothing reflected (see shade() in material.h).
        sd.emission = sd.base_color;
        sd.bsdf.emplace<LambertianBsdf>(Spectrum(0));
        return sd;
    }

    // Single-sided emitters (doubleSided false) emit from the glTF front face only. A
    // black factor leaves the emission black (emitted_radiance reads no texture then):
    // tested first, as most materials emit nothing, so that their hits skip the side test.
    if (has_emission_factor(m) && emits_towards(m, front_normal(sp), wo))
        sd.emission = emitted_radiance(scene, m, sp.uv0, sp.uv1, sp.uv_width);

    // A material that is the same at every hit has its model built already; the
    // inputs that only the models built per hit read are worked out after this return,
    // which most hits take.
    if (options.prototypes) {
        if (const BsdfStorage* proto =
                options.prototypes->find(uint32_t(sp.material), sp.color, options)) {
            sd.bsdf.use(*proto);
            return sd;
        }
    }
    emplace_model(scene, m, sp, wo, options, path, anisotropy, sd);
    return sd;
}

}  // namespace penumbra
