// Ideal diffuse reflection: f = R / pi, sampled by the cosine-weighted hemisphere.
#pragma once

#include "materials/bsdf.h"

namespace penumbra {

class LambertianBsdf final : public Bsdf {
public:
    explicit LambertianBsdf(Spectrum reflectance) : m_R(reflectance) {}
    Spectrum eval(Vec3 wo, Vec3 wi, Transport mode) const override;
    float pdf(Vec3 wo, Vec3 wi, Transport mode) const override;
    std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Vec2 u,
                                     Transport mode) const override;
    bool has_specular() const override { return false; }

private:
    Spectrum m_R;
};

}  // namespace penumbra
