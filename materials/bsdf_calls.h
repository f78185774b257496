// A hit's BSDF as the integrators' per-vertex code calls it: the Lambertian model, the
// commonest by far (every diffuse glTF material without a specular lobe), directly and
// inlined, the others through their virtual functions. The values are the same either
// way, bit for bit; a direct call saves the dispatch and lets the result stay in
// registers (about 40 instructions a vertex on the Cornell box, docs/performance.md).
#pragma once

#include <optional>

#include "materials/bsdf.h"
#include "materials/lambertian.h"

namespace penumbra {

inline Spectrum bsdf_eval(const Bsdf& bsdf, Vec3 wo, Vec3 wi, Transport mode) {
    if (bsdf.is_lambertian())
        return static_cast<const LambertianBsdf&>(bsdf).LambertianBsdf::eval(wo, wi, mode);
    return bsdf.eval(wo, wi, mode);
}

// Bsdf::eval_pdf: LambertianBsdf keeps the base class's (pdf, then eval).
inline Spectrum bsdf_eval_pdf(const Bsdf& bsdf, Vec3 wo, Vec3 wi, Transport mode,
                              float* pdf_out) {
    if (bsdf.is_lambertian()) {
        const LambertianBsdf& lambert = static_cast<const LambertianBsdf&>(bsdf);
        *pdf_out = lambert.LambertianBsdf::pdf(wo, wi, mode);
        return lambert.LambertianBsdf::eval(wo, wi, mode);
    }
    return bsdf.eval_pdf(wo, wi, mode, pdf_out);
}

inline std::optional<BsdfSample> bsdf_sample(const Bsdf& bsdf, Vec3 wo, float u_lobe, Vec2 u,
                                             Transport mode) {
    if (bsdf.is_lambertian())
        return static_cast<const LambertianBsdf&>(bsdf).LambertianBsdf::sample(wo, u_lobe, u,
                                                                               mode);
    return bsdf.sample(wo, u_lobe, u, mode);
}

}  // namespace penumbra
