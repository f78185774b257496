// Directional albedo of glTF's anisotropic specular lobe (KHR_materials_anisotropy), the
// E(w) = f0 A(w) + (f90 - f0) B(w) of specular_albedo.h for alpha_x = mix(alpha, 1, s^2),
// alpha_y = alpha, tabulated over (alpha, s, cos(theta), phi) for the base's layering.
//
// No isotropic stand-in is good enough: E at the roughness projected on wo's azimuth
// reflects up to 0.037 less than the lobe (a white dielectric would gain that much) and
// E at min(alpha_x, alpha_y) up to 0.037 less too (the lobe's wider half vectors see more
// Fresnel), while any larger alpha loses up to 0.4 at grazing angles. So, as Kulla &
// Conty (2017) do for their lobes, we integrate the albedo numerically, once per process
// and distribution, when the first anisotropic material asks for it (about a second).
#pragma once

#include "core/math/vec.h"
#include "materials/lobes/microfacet.h"

namespace penumbra {

// Anisotropic lobes clamp both alphas to this (MetalRoughBsdf::kDeltaAlpha).
constexpr float kAnisotropicMinAlpha = 1e-4f;

// The lobe's alphas for glTF's alpha (roughness^2) and anisotropy strength s, both
// clamped to kAnisotropicMinAlpha: (alpha_x along the anisotropy direction, alpha_y).
Vec2 anisotropic_alphas(float alpha, float strength);

// A and B of one anisotropic lobe, interpolated from the table.
class AnisotropicSpecularAlbedo {
public:
    AnisotropicSpecularAlbedo() = default;
    AnisotropicSpecularAlbedo(MicrofacetType type, float alpha, float strength);
    // (A, B) towards the unit direction w (local frame, x along the anisotropy direction).
    Vec2 at(Vec3 w) const;
    // The cosine-weighted hemispherical average (1/pi) int (A, B)(w) cos(theta) dw of
    // exactly the interpolant at() returns.
    Vec2 average() const { return m_average; }
    // (A, B) averaged over the azimuth, (2/pi) int_0^{pi/2} d phi, at the table's column
    // cos(theta) = (i / (columns() - 1))^3: at() is linear in cos(theta) between columns,
    // so these are the exact nodes of the interpolant's azimuthal average.
    static int columns();
    Vec2 azimuthal_average(int column) const;

private:
    const struct AnisotropyAlbedoTable* m_table = nullptr;
    int m_j = 0, m_k = 0;          // grid cell in alpha and strength
    float m_fj = 0, m_fk = 0;      // position inside it
    Vec2 m_average;
};

}  // namespace penumbra
