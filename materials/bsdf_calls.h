// A hit's BSDF as the integrators' per-vertex code calls it: the Lambertian model, the
// commonest by far (every diffuse glTF material without a specular lobe), directly and
// inlined, the others through their virtual functions. The values are the same either
// way, bit for bit; a direct call saves the dispatch and lets the result stay in
// registers (about 40 instructions a vertex on the Cornell box, docs/performance.md).
#pragma once

#include <optional>

#include "core/math/frame.h"
#include "materials/bsdf.h"
#include "materials/lobes/lambertian.h"

namespace penumbra {

// World direction w in the hit's shading frame, as the calls below read it. The
// Lambertian model reads only the cosine, z, so its x and y are left 0: two dot products
// fewer for wo and for each light sample's wi at every diffuse vertex.
inline Vec3 to_bsdf_local(const Bsdf& bsdf, const Frame& frame, Vec3 w) {
    if (bsdf.is_lambertian()) return {0, 0, dot(w, frame.n)};  // to_local's z, bit for bit
    return frame.to_local(w);
}

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
