// A homogeneous absorbing medium (KHR_materials_volume): Beer-Lambert attenuation with a
// constant absorption coefficient per RGB channel, and no scattering.
#pragma once

#include "core/media/medium.h"

namespace penumbra {

class HomogeneousMedium final : public Medium {
public:
    // sigma_a per channel in 1/world units; each must be >= 0 (infinity: opaque).
    explicit HomogeneousMedium(Spectrum sigma_a);
    // KHR_materials_volume: light reaching attenuation_distance keeps attenuation_color,
    // so sigma_a = -ln(color) / distance per channel. Distance +infinity (the spec's
    // default) or colour 1 is clear; colours are clamped to [0, 1] (a medium never adds
    // light) and 0 is opaque.
    static Spectrum sigma_a_from_attenuation(Spectrum attenuation_color,
                                             float attenuation_distance);

    Spectrum transmittance(const Ray& ray, float dist) const override;
    MediumSample sample(const Ray& ray, float dist, float u) const override;
    bool is_clear() const override { return is_black(m_sigma_a); }
    Spectrum sigma_a() const { return m_sigma_a; }

private:
    Spectrum m_sigma_a;
};

}  // namespace penumbra
