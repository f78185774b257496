// The glTF 2.0 metallic-roughness BRDF (spec Appendix B, with KHR_materials_specular,
// _ior, _anisotropy and _iridescence): a GGX (or, for comparisons, Beckmann) specular
// lobe with height-correlated Smith masking and Schlick Fresnel (optionally mixed with a
// thin film's), over a Lambertian base. Roughness 0 makes the lobe a perfect mirror.
#pragma once

#include <array>
#include <cstdint>

#include "materials/albedo/anisotropy_albedo.h"
#include "materials/bsdf.h"
#include "materials/lobes/microfacet.h"
#include "materials/albedo/specular_albedo.h"
#include "materials/lobes/thin_film.h"

namespace penumbra {

// How the dielectric's Lambertian base sits under its specular layer. The metal and the
// specular lobe itself are the spec's in both.
enum class GltfLayering {
    // Energy-conserving (the default): the base is weighted by
    //     (1 - E(wo)) (1 - E(wi)) / (1 - E_avg),
    // E the specular lobe's directional albedo with its Fresnel (specular_albedo.h),
    // E_avg its cosine-weighted average (Kelemen & Szirmay-Kalos 2001; Kulla & Conty
    // 2017). Reciprocal, and a white dielectric reflects exactly E(wo) + (1 - E(wo)) = 1.
    AlbedoScaled,
    // The spec's fresnel_mix exactly as Appendix B writes it: the base weighted by
    // 1 - F(v.h). It gains energy away from the normal (a white dielectric reflects
    // about 1.15 at cos(theta_o) = 0.3 and 1.7 at 0.05), so glTF furnace spheres glow at
    // their rims. Kept for comparison with rasterizers that follow the appendix.
    Spec,
};

struct MetalRoughParams {
    Spectrum base_color{1, 1, 1};
    float metallic = 1;
    float alpha = 1;                  // roughness^2
    Spectrum dielectric_f0{0.04f};    // ((ior-1)/(ior+1))^2 * specularColor * specular
    float dielectric_f90 = 1;         // specular factor
    // GGX as the spec says; Beckmann to compare (the --microfacet switch).
    MicrofacetType distribution = MicrofacetType::Ggx;
    GltfLayering layering = GltfLayering::AlbedoScaled;
    // KHR_materials_anisotropy: strength in [0, 1]. The lobe's alpha along the local x
    // axis (the anisotropy direction: the caller's frame must follow it) is
    // mix(alpha, 1, strength^2), along y alpha. 0: isotropic.
    float anisotropy = 0;
    // KHR_materials_iridescence: the share of a thin film's Fresnel in both the
    // dielectric's and the metal's (factor x texture R); 0, or a film of thickness 0, is
    // no film. The dielectric's film sits on its f0 / f90 and is scaled by f90.
    float iridescence = 0;
    ThinFilm film;
};

class MetalRoughBsdf final : public Bsdf {
public:
    // Below this alpha the specular lobe is treated as a Dirac delta.
    static constexpr float kDeltaAlpha = 1e-4f;

    explicit MetalRoughBsdf(const MetalRoughParams& p);
    Spectrum eval(Vec3 wo, Vec3 wi, Transport mode) const override;
    float pdf(Vec3 wo, Vec3 wi, Transport mode) const override;
    Spectrum eval_pdf(Vec3 wo, Vec3 wi, Transport mode, float* pdf_out) const override;
    std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Vec2 u,
                                     Transport mode) const override;
    // The base's diffuse term of eval (its specular lobe aside).
    Spectrum eval_diffuse(Vec3 wo, Vec3 wi, Transport mode) const override;
    bool has_specular() const override { return m_delta; }

private:
    // The terms that depend on wo alone. An integrator asks about one wo per shading
    // point, several times: the light sample's eval and pdf, then sample(), whose pdf
    // and eval ask again; on scenes/glossy.gltf the cache saves 4 of 5 albedo-table
    // lookups of 1 - E(wo) and 2 of 3 Fresnel evaluations per bounce.
    struct WoTerms {
        uint64_t model = 0;           // the m_id of the model they are for (0: none)
        uint32_t key[3] = {0, 0, 0};  // wo's bits (an exact match; NaN never matches)
        float transmittance = 1;      // base_transmittance(wo), where a base exists
        float probability = 0;        // specular_probability(wo)
        float lambda = 0;             // Smith Lambda(wo) of a rough lobe
    };
    // The last wo's terms are kept per thread, not in the model, so that one model can
    // serve every thread's hits (a material's prototype, BsdfStorage::use). By value: a
    // reference to the thread's slot would change under a caller that asked another
    // model in between.
    WoTerms wo_terms(Vec3 wo) const;
    // Probability of choosing the specular lobe for wo, given base_transmittance(wo).
    float specular_probability(Vec3 wo, float transmittance) const;
    // The base's BRDF value; cos_vh only matters to the spec's layering.
    Spectrum diffuse_term(const WoTerms& t, Vec3 wi, float cos_vh) const;
    // The specular lobe's density of the wi whose half vector is h (rough lobes).
    float pdf_specular(const WoTerms& t, Vec3 wo, Vec3 h) const;
    // eval and pdf of one (wo, wi) with wo.z > 0 and wi.z > 0, sharing the half vector
    // and D(h): what sample() returns with its direction.
    Spectrum eval_pdf(const WoTerms& t, Vec3 wo, Vec3 wi, float* pdf) const;

    // Mixed Fresnel of the dielectric and metal layers at cos(theta) = c.
    Spectrum specular_fresnel(float c) const;
    // The dielectric layer's Fresnel alone (with its film).
    Spectrum dielectric_fresnel(float c) const;
    // The fraction of light towards w that the dielectric's specular layer leaves to the
    // base: 1 - E(w) (AlbedoScaled) or 1 - F(w.z) (Spec), scalar as the spec's
    // max_value(F) (KHR_materials_specular).
    float base_transmittance(Vec3 w) const;
    // 1 - max_value(F(mu)) of the dielectric layer.
    float fresnel_transmittance(float mu) const;
    // The f0 that the base's layering uses towards cos(theta) = mu (see m_film_bound).
    float layer_f0(float mu) const;
    // E_avg of the layering with a film, by quadrature over the hemisphere.
    float film_average_albedo() const;

    MetalRoughParams m_p;
    MicrofacetDistribution m_dist;
    bool m_delta;
    bool m_aniso = false;     // alpha_x != alpha_y
    bool m_film = false;      // iridescence > 0 with a film of positive thickness
    bool m_lambert = false;   // no specular lobe (specular 0, no metal): the base alone
    Spectrum m_film_f0;       // the dielectric's f0 under its film: dielectric_f0 / f90
    float m_f0_max;           // the largest channel of dielectric_f0
    // With a film: m_film_bound[i] is the smallest f0 whose Schlick curve (with f90)
    // bounds max_value(F(c)) of the dielectric at every node c = j / kFilmNodes, j >= i.
    // Filled (zeros first) only when there is a film, the only case that reads it: a
    // `{}` here zero-filled its 132 bytes with `rep stos` on every hit, half of this
    // constructor's samples on scenes/glossy.gltf.
    static constexpr int kFilmNodes = 32;
    std::array<float, kFilmNodes + 1> m_film_bound;
    SpecularAlbedo m_albedo;  // AlbedoScaled, rough lobes only
    AnisotropicSpecularAlbedo m_aniso_albedo;  // the same for anisotropic lobes
    float m_base_norm = 1;    // AlbedoScaled: 1 / (1 - E_avg)
    // A number no other model has had in this process (a copy keeps its original's: it
    // holds the same parameters), the key of the thread's cached wo terms. The address
    // would not do: a hit's model is built where the previous hit's was, with other
    // parameters, for the same wo (an orthographic view of a textured plane).
    uint64_t m_id;
    static thread_local WoTerms s_wo;  // this thread's last wo's terms, of model s_wo.model
};

}  // namespace penumbra
