// The sheen albedo by quadrature: the table's rows (at build time, albedo_generator.cpp)
// and single values for tests.
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/math/gauss_legendre.h"
#include "core/math/portable_math.h"
#include "core/math/vec.h"
#include "materials/albedo/sheen_albedo_table.h"

namespace penumbra {

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

void integrate_sheen_albedo_row(int j, SheenAlbedoTable& t) {
    const float r = sheen_albedo_row_roughness(j);
    for (int i = 0; i < SheenAlbedoTable::M; ++i)
        t.e[j][i] = integrate_sheen_albedo(sheen_albedo_column_mu(i), r, 64, 64);
}

}  // namespace penumbra
