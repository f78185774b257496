#include "materials/albedo/sheen_albedo.h"

#include <algorithm>
#include <cmath>

#include "materials/albedo/sheen_albedo_table.h"

namespace penumbra {

float sheen_albedo(float mu, float r) {
    constexpr int kRows = SheenAlbedoTable::R, kColumns = SheenAlbedoTable::M;
    mu = std::clamp(mu, 0.0f, 1.0f);
    const float r_min = CharlieSheen::kMinRoughness;
    r = std::clamp(r, r_min, 1.0f);
    const float fr = (r - r_min) / (1 - r_min) * (kRows - 1);
    const int j = std::min(static_cast<int>(fr), kRows - 2);
    const float tr = fr - j;
    const float fc = std::sqrt(mu) * (kColumns - 1);
    const int i = std::min(static_cast<int>(fc), kColumns - 2);
    // Linear in mu between columns.
    const float mu0 = sheen_albedo_column_mu(i), mu1 = sheen_albedo_column_mu(i + 1);
    const float tc = std::clamp((mu - mu0) / (mu1 - mu0), 0.0f, 1.0f);
    const auto lerp_row = [&](int row) {
        return kSheenAlbedo.e[row][i] * (1 - tc) + kSheenAlbedo.e[row][i + 1] * tc;
    };
    return lerp_row(j) * (1 - tr) + lerp_row(j + 1) * tr;
}

}  // namespace penumbra
