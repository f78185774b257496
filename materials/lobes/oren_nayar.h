// Rough diffuse reflection: the qualitative Oren & Nayar 1994 model (A and B terms, their
// eq. 30; slope deviation sigma in radians), scaled where needed so its albedo stays <= 1.
// Sigma 0 is Lambertian. Sampled by the cosine-weighted hemisphere.
#pragma once

#include "materials/bsdf.h"

namespace penumbra {

class OrenNayarBsdf final : public Bsdf {
public:
    OrenNayarBsdf(Spectrum reflectance, float sigma);
    Spectrum eval(Vec3 wo, Vec3 wi, Transport mode) const override;
    float pdf(Vec3 wo, Vec3 wi, Transport mode) const override;
    std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Vec2 u, Transport mode) const override;
    Spectrum eval_diffuse(Vec3 wo, Vec3 wi, Transport m) const override { return eval(wo, wi, m); }
    bool has_specular() const override { return false; }

private:
    Spectrum m_R;
    float m_A, m_B;
};

}  // namespace penumbra
