#include "materials/lambertian.h"

#include "core/sampling/warp.h"

namespace penumbra {

Spectrum LambertianBsdf::eval(Vec3 wo, Vec3 wi, Transport) const {
    if (wo.z <= 0 || wi.z <= 0) return Spectrum(0);
    return m_R * kInvPi;
}

float LambertianBsdf::pdf(Vec3 wo, Vec3 wi, Transport) const {
    if (wo.z <= 0 || wi.z <= 0) return 0;
    return cosine_hemisphere_pdf(wi);
}

std::optional<BsdfSample> LambertianBsdf::sample(Vec3 wo, float, Vec2 u, Transport) const {
    if (wo.z <= 0) return std::nullopt;
    const Vec3 wi = square_to_cosine_hemisphere(u);
    const float pdf = cosine_hemisphere_pdf(wi);
    if (pdf <= 0) return std::nullopt;
    return BsdfSample{wi, m_R * kInvPi, pdf, Lobe::Diffuse, 1};
}

}  // namespace penumbra
