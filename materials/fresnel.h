// Fresnel reflectance terms shared by every model.
#pragma once

#include <algorithm>

#include "core/math/vec.h"

namespace penumbra {

// Schlick's approximation with explicit f90 (as glTF's KHR_materials_specular uses it).
inline Spectrum fresnel_schlick(Spectrum f0, float f90, float cos_theta) {
    const float m = std::clamp(1 - cos_theta, 0.0f, 1.0f);
    const float m2 = m * m, m5 = m2 * m2 * m;
    return f0 + (Spectrum(f90) - f0) * m5;
}

// Normal-incidence reflectance of a dielectric interface with relative IOR eta.
inline float f0_from_ior(float eta) {
    const float r = (eta - 1) / (eta + 1);
    return r * r;
}

}  // namespace penumbra
