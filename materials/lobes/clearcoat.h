// KHR_materials_clearcoat's lobe: c F(v.h) D G / (4 cos_o cos_i) with Schlick's Fresnel
// for IOR 1.5 (f0 0.04, f90 1), its own roughness and its own normal, so it is
// evaluated in its own frame. Reflection only; the layering is in gltf_bsdf.h.
#pragma once

#include <optional>

#include "core/math/frame.h"
#include "materials/bsdf.h"
#include "materials/lobes/microfacet.h"
#include "materials/albedo/specular_albedo.h"

namespace penumbra {

class ClearcoatLobe {
public:
    // Below this alpha the coat is a perfect mirror (a Dirac lobe), as in MetalRoughBsdf.
    static constexpr float kDeltaAlpha = 1e-4f;
    static constexpr float kF0 = 0.04f;

    // strength: clearcoat factor x texture, in [0, 1]; alpha: coat roughness^2; normal:
    // the coat's unit normal in the base's local shading frame (z = base normal).
    ClearcoatLobe(float strength, float alpha, Vec3 normal, MicrofacetType type);
    bool is_delta() const { return m_delta; }
    float strength() const { return m_c; }

    // f in the base frame (no cosine); 0 for the mirror, and unless wo and wi are above
    // both the base's and the coat's horizon. The integrators weigh f by the base's
    // cos(theta_i), the microfacet lobe is normalized for the coat's, so Radiance returns
    // f_coat cos_coat(wi) / cos_base(wi): the coat reflects its own albedo E_c(wo) whatever
    // its tilt (the albedo scaling relies on it). Like any shading normal this is not
    // symmetric (Veach 1997, sec. 5.3); Importance returns the adjoint, f(wi, wo). With
    // the coat normal equal to the base normal the factor is exactly 1.
    float eval(Vec3 wo, Vec3 wi, Transport mode) const;
    // Solid-angle density of sample(): visible normals of the coat's frame.
    float pdf(Vec3 wo, Vec3 wi) const;
    // A reflected direction (rough coat only); empty below either horizon.
    std::optional<Vec3> sample(Vec3 wo, Vec2 u) const;
    // The mirror coat's direction for wo and its reflectance c F(cos_c) (no cosine
    // division); empty below either horizon.
    std::optional<Vec3> mirror(Vec3 wo) const;
    float mirror_reflectance(Vec3 wo) const;

    // c E_c(w): what the coat reflects of light arriving from w (its directional albedo
    // at w's cosine to the coat normal, specular_albedo.h); the layers below receive at
    // most 1 - this.
    float layer_albedo(Vec3 w) const;

private:
    float fresnel(float cos_vh) const;

    float m_c;
    bool m_delta;
    Frame m_frame;  // z = coat normal, in base-local coordinates
    MicrofacetDistribution m_dist;
    SpecularAlbedo m_albedo;  // rough coats only
};

}  // namespace penumbra
