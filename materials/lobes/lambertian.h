// Ideal diffuse reflection: f = R / pi, sampled by the cosine-weighted hemisphere.
#pragma once

#include "core/sampling/warp.h"
#include "materials/bsdf.h"

namespace penumbra {

class LambertianBsdf final : public Bsdf {
public:
    explicit LambertianBsdf(Spectrum reflectance) : Bsdf(true), m_R(reflectance) {}
    // Inline, for bsdf_calls.h: the path tracer's vertices call them directly.
    Spectrum eval(Vec3 wo, Vec3 wi, Transport) const override {
        if (wo.z <= 0 || wi.z <= 0) return Spectrum(0);
        return m_R * kInvPi;
    }
    float pdf(Vec3 wo, Vec3 wi, Transport) const override {
        if (wo.z <= 0 || wi.z <= 0) return 0;
        return cosine_hemisphere_pdf(wi);
    }
    std::optional<BsdfSample> sample(Vec3 wo, float, Vec2 u, Transport) const override {
        if (wo.z <= 0) return std::nullopt;
        const Vec3 wi = square_to_cosine_hemisphere(u);
        const float pdf = cosine_hemisphere_pdf(wi);
        if (pdf <= 0) return std::nullopt;
        return BsdfSample{wi, m_R * kInvPi, pdf, Lobe::Diffuse, 1};
    }
    Spectrum eval_diffuse(Vec3 wo, Vec3 wi, Transport m) const override { return eval(wo, wi, m); }
    bool has_specular() const override { return false; }

private:
    Spectrum m_R;
};

}  // namespace penumbra
