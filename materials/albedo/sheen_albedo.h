// Directional albedo E(mu, r) = int D V cos(theta_i) dwi of the Charlie sheen lobe
// (materials/lobes/sheen.h), tabulated at build time, for KHR_materials_sheen's albedo
// scaling of the layers below: min(1 - max3(color) E(mu_o), 1 - max3(color) E(mu_i)).
#pragma once

namespace penumbra {

// The table's grid, exposed for tests: rows r = r_min + (1 - r_min) j / (rows - 1) with
// r_min = CharlieSheen::kMinRoughness (the lobe clamps r there), columns
// mu = (i / (columns - 1))^2 (E changes fastest towards grazing views).
struct SheenAlbedoGrid {
    static constexpr int kRows = 32;
    static constexpr int kColumns = 32;
};

// E at cos(theta) = mu for sheen roughness r (both clamped to [0, 1]), bilinear in the
// table the build integrated (sheen_albedo_table.h).
float sheen_albedo(float mu, float r);

// E by quadrature: n_cos Gauss-Legendre nodes in cos(theta_i) times n_phi midpoints in
// phi (the lobe is symmetric about the plane of wo), for the table and for tests.
float integrate_sheen_albedo(float mu, float r, int n_cos, int n_phi);

}  // namespace penumbra
