#include "materials/albedo/sheen_albedo.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/math/gauss_legendre.h"
#include "core/math/portable_math.h"
#include "core/math/vec.h"
#include "materials/lobes/sheen.h"

namespace penumbra {

namespace {

constexpr int kRows = SheenAlbedoGrid::kRows;
constexpr int kColumns = SheenAlbedoGrid::kColumns;
using Table = std::array<std::array<float, kColumns>, kRows>;

float column_mu(int i) {
    const float s = i / float(kColumns - 1);
    return s * s;
}

float row_roughness(int j) {
    const float r_min = CharlieSheen::kMinRoughness;
    return r_min + (1 - r_min) * (j / float(kRows - 1));
}

Table build_table() {
    Table t;
    tbb::parallel_for(0, kRows, [&](int j) {
        const float r = row_roughness(j);
        for (int i = 0; i < kColumns; ++i)
            t[j][i] = integrate_sheen_albedo(column_mu(i), r, 64, 64);
    });
    return t;
}

}  // namespace

float integrate_sheen_albedo(float mu, float r, int n_cos, int n_phi) {
    // Tangent views see a lobe whose V vanishes; just above, the limit.
    mu = std::clamp(mu, 1e-4f, 1.0f);
    const CharlieSheen sheen(r);
    const Vec3 wo(std::sqrt(1 - mu * mu), 0, mu);
    std::vector<double> xs, ws;
    gauss_legendre(n_cos, xs, ws);
    // dwi = dcos dphi; phi over [0, pi] twice by the symmetry y -> -y.
    double sum = 0;
    for (int k = 0; k < n_phi; ++k) {
        const double phi = kPi * (k + 0.5) / n_phi;
        const float c_phi = float(portable_cos(phi)), s_phi = float(portable_sin(phi));
        for (int x = 0; x < n_cos; ++x) {
            const float c = float(xs[x]), s = std::sqrt(std::max(0.0f, 1 - c * c));
            const Vec3 wi(s * c_phi, s * s_phi, c);
            sum += ws[x] * sheen.value(wo, wi) * c;
        }
    }
    return float(sum * 2 * kPi / n_phi);
}

float sheen_albedo(float mu, float r) {
    static const Table table = build_table();  // thread-safe static, built once
    mu = std::clamp(mu, 0.0f, 1.0f);
    const float r_min = CharlieSheen::kMinRoughness;
    r = std::clamp(r, r_min, 1.0f);
    const float fr = (r - r_min) / (1 - r_min) * (kRows - 1);
    const int j = std::min(static_cast<int>(fr), kRows - 2);
    const float tr = fr - j;
    const float fc = std::sqrt(mu) * (kColumns - 1);
    const int i = std::min(static_cast<int>(fc), kColumns - 2);
    // Linear in mu between columns.
    const float mu0 = column_mu(i), mu1 = column_mu(i + 1);
    const float tc = std::clamp((mu - mu0) / (mu1 - mu0), 0.0f, 1.0f);
    const auto lerp_row = [&](int row) {
        return table[row][i] * (1 - tc) + table[row][i + 1] * tc;
    };
    return lerp_row(j) * (1 - tr) + lerp_row(j + 1) * tr;
}

}  // namespace penumbra
