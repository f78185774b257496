#include "core/media/homogeneous_medium.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace penumbra {

HomogeneousMedium::HomogeneousMedium(Spectrum sigma_a) : m_sigma_a(sigma_a) {
    for (int c = 0; c < 3; ++c) CHECK(sigma_a[c] >= 0, "absorption must be >= 0");
}

Spectrum HomogeneousMedium::sigma_a_from_attenuation(Spectrum color, float distance) {
    Spectrum sigma(0);
    if (!(distance > 0) || std::isinf(distance)) return sigma;
    for (int c = 0; c < 3; ++c) {
        const float a = std::clamp(color[c], 0.0f, 1.0f);
        sigma[c] = a > 0 ? -std::log(a) / distance : std::numeric_limits<float>::infinity();
    }
    return sigma;
}

Spectrum HomogeneousMedium::transmittance(const Ray&, float dist) const {
    Spectrum tr(1);
    // A channel that does not absorb keeps everything even over an infinite distance,
    // and no distance keeps everything even in an opaque one (0 * inf is not a number).
    if (!(dist > 0)) return tr;
    for (int c = 0; c < 3; ++c)
        if (m_sigma_a[c] > 0) tr[c] = std::exp(-m_sigma_a[c] * dist);
    return tr;
}

MediumSample HomogeneousMedium::sample(const Ray& ray, float dist, float) const {
    return MediumSample{dist, transmittance(ray, dist), false};
}

}  // namespace penumbra
