// Fresnel reflectance shared by every model: Schlick's approximation, the exact
// dielectric (with total internal reflection) and conductor (complex IOR) equations,
// Snell's law, and Fresnel, a value type that picks one of them per material.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <optional>

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

// Refracts w (pointing away from the surface, on the side n points to) through the
// interface with normal n; eta is the IOR of the far side over that of w's side. Empty
// under total internal reflection. (Snell's law in vector form, pbrt-v4 sec. 9.3.2.)
inline std::optional<Vec3> refract(Vec3 w, Vec3 n, float eta) {
    const float cos_i = dot(w, n);
    const float sin2_t = std::max(0.0f, 1 - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1) return std::nullopt;
    const float cos_t = std::sqrt(1 - sin2_t);
    return -w / eta + n * (cos_i / eta - cos_t);
}

// Reflectance of s- and p-polarized light at a dielectric interface.
struct PolarizedReflectance {
    float rs = 1, rp = 1;
    float average() const { return 0.5f * (rs + rp); }
};

// Exact Fresnel equations (Born & Wolf; pbrt-v4 eq. 9.4-9.5). cos_i = cos of the angle
// to the normal: positive on the side the normal points to, where the medium has IOR 1
// relative to eta on the other side; negative cos_i looks from the other side (1/eta).
// Beyond the critical angle everything is reflected.
inline PolarizedReflectance fresnel_dielectric_polarized(float cos_i, float eta) {
    if (cos_i < 0) {
        eta = 1 / eta;
        cos_i = -cos_i;
    }
    cos_i = std::min(cos_i, 1.0f);
    const float sin2_t = (1 - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1) return {};
    const float cos_t = std::sqrt(1 - sin2_t);
    const float r_perp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    const float r_parl = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    return {r_perp * r_perp, r_parl * r_parl};
}
inline float fresnel_dielectric(float cos_i, float eta) {
    return fresnel_dielectric_polarized(cos_i, eta).average();
}

// Exact unpolarized Fresnel reflectance of a conductor with complex IOR eta + i k,
// per channel (pbrt-v4 sec. 9.4.2: the dielectric equations with complex eta).
inline float fresnel_complex(float cos_i, float eta, float k) {
    using C = std::complex<float>;
    cos_i = std::clamp(cos_i, 0.0f, 1.0f);
    const C n(eta, k);
    const C sin2_t = (1 - cos_i * cos_i) / (n * n);
    const C cos_t = std::sqrt(1.0f - sin2_t);
    const C r_parl = (n * cos_i - cos_t) / (n * cos_i + cos_t);
    const C r_perp = (cos_i - n * cos_t) / (cos_i + n * cos_t);
    return 0.5f * (std::norm(r_parl) + std::norm(r_perp));
}
inline Spectrum fresnel_conductor(float cos_i, Spectrum eta, Spectrum k) {
    return {fresnel_complex(cos_i, eta.x, k.x), fresnel_complex(cos_i, eta.y, k.y),
            fresnel_complex(cos_i, eta.z, k.z)};
}

struct ComplexIor {
    Spectrum eta, k;
};
enum class Metal { Gold, Copper, Aluminium, Silver };
// Linear-sRGB complex IORs from Tungsten's src/core/bsdfs/ComplexIorData.hpp (B. Bitterli;
// measured n, k spectra integrated to RGB), the table Mitsuba-style renderers share.
inline ComplexIor metal_ior(Metal m) {
    switch (m) {
        case Metal::Gold:
            return {{0.1431189557f, 0.3749570432f, 1.4424785571f},
                    {3.9831604247f, 2.3857207478f, 1.6032152899f}};
        case Metal::Copper:
            return {{0.2004376970f, 0.9240334304f, 1.1022119527f},
                    {3.9129485033f, 2.4528477015f, 2.1421879552f}};
        case Metal::Aluminium:
            return {{1.6574599595f, 0.8803689579f, 0.5212287346f},
                    {9.2238691996f, 6.2695232477f, 4.8370012281f}};
        case Metal::Silver:
            break;
    }
    return {{0.1552646489f, 0.1167232965f, 0.1383806959f},
            {4.8283433224f, 3.1222459278f, 2.1469504455f}};
}

enum class FresnelModel { Schlick, Dielectric, Conductor };

// One Fresnel term for reflection models, chosen per material.
struct Fresnel {
    FresnelModel model = FresnelModel::Schlick;
    Spectrum f0{1};      // Schlick
    float f90 = 1;       // Schlick
    Spectrum eta{1.5f};  // Dielectric: eta.x is the relative IOR; Conductor: per channel
    Spectrum k{0};       // Conductor

    static Fresnel schlick(Spectrum f0, float f90 = 1) {
        Fresnel f;
        f.f0 = f0;
        f.f90 = f90;
        return f;
    }
    static Fresnel dielectric(float eta) {
        Fresnel f;
        f.model = FresnelModel::Dielectric;
        f.eta = Spectrum(eta);
        return f;
    }
    static Fresnel conductor(const ComplexIor& ior) {
        Fresnel f;
        f.model = FresnelModel::Conductor;
        f.eta = ior.eta;
        f.k = ior.k;
        return f;
    }

    // Reflectance at cos_i = cos of the angle between the incident direction and the
    // (micro)normal, on the normal's side.
    Spectrum eval(float cos_i) const {
        switch (model) {
            case FresnelModel::Dielectric:
                return Spectrum(fresnel_dielectric(cos_i, eta.x));
            case FresnelModel::Conductor:
                return fresnel_conductor(cos_i, eta, k);
            case FresnelModel::Schlick:
                break;
        }
        return fresnel_schlick(f0, f90, cos_i);
    }
};

}  // namespace penumbra
