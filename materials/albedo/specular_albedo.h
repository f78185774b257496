// Directional albedo of glTF's specular lobe, tabulated, for energy-conserving layering
// of the diffuse base under it (materials/metal_rough_bsdf.h, GltfLayering).
//
// The lobe is f_s = F(v.h) D(h) G(v, l) / (4 n.v n.l) with Schlick's
// F = f0 + (f90 - f0) (1 - v.h)^5, so its albedo at cos(theta_v) = mu is linear in the
// Fresnel parameters:
//     E(mu) = f0 A(mu) + (f90 - f0) B(mu),
//     A(mu) = int D G / (4 n.v n.l) n.l dl,   B(mu) = int (1 - v.h)^5 D G / (4 n.v n.l) n.l dl.
// A and B depend only on mu and alpha, so one table per distribution serves every
// material. Like Kulla & Conty (2017) and Turquin (2019) we integrate them numerically
// instead of shipping a fitted table: at build time (albedo_generator.cpp
// writes the table that the library compiles in), so a render computes nothing.
#pragma once

#include "core/math/vec.h"
#include "materials/lobes/microfacet.h"

namespace penumbra {

// A and B of one lobe (a distribution and an alpha), interpolated from the table.
class SpecularAlbedo {
public:
    SpecularAlbedo() = default;
    SpecularAlbedo(MicrofacetType type, float alpha);
    // (A, B) at cos(theta) = mu, clamped to [0, 1].
    Vec2 at(float mu) const;
    // (A_avg, B_avg) = 2 int_0^1 (A, B)(mu) mu dmu: the cosine-weighted hemispherical
    // averages of exactly the interpolant that at() returns, so that layering
    // normalized by them integrates to what it should.
    Vec2 average() const { return m_average; }

private:
    const struct SpecularAlbedoTable* m_table = nullptr;
    int m_row = 0;     // table row below alpha
    float m_frac = 0;  // position between that row and the next
    Vec2 m_average;
};

// The table's grid, exposed for tests: rows are alpha = (j / (rows - 1))^4, columns
// mu = (i / (columns - 1))^3. A and B change fastest where alpha and mu are both small
// (a smooth lobe seen at grazing angles: masking depends on alpha / mu), so both axes
// are dense there; a 32 x 32 grid uniform in sqrt(alpha) and mu^2 was off by 0.037 at
// alpha 2e-4, mu 0.002. Row 0 is the mirror limit (A = 1, B = (1 - mu)^5).
struct SpecularAlbedoGrid {
    static constexpr int kRows = 64;
    static constexpr int kColumns = 64;
};

// (A, B) by quadrature over the visible normals, for the table and for tests:
// n_radial Gauss-Legendre nodes times n_angular midpoints.
Vec2 integrate_specular_albedo(MicrofacetType type, float alpha, float mu, int n_radial,
                               int n_angular);
// The same for any (also anisotropic) distribution and a unit wo with wo.z > 0.
Vec2 integrate_specular_albedo(const MicrofacetDistribution& dist, Vec3 wo, int n_radial,
                               int n_angular);

}  // namespace penumbra
