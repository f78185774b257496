#include "materials/gltf_bsdf.h"

#include <algorithm>
#include <cmath>

#include "materials/albedo/sheen_albedo.h"

namespace penumbra {

GltfBsdf::GltfBsdf(const Core& core, const std::optional<SheenLobe>& sheen,
                   const std::optional<ClearcoatLobe>& coat)
    : m_core(core), m_sheen(sheen), m_coat(coat) {
    if (m_sheen) m_sheen_max = std::max(0.0f, max_component(m_sheen->color()));
}

const Bsdf& GltfBsdf::core() const {
    return std::visit([](const auto& b) -> const Bsdf& { return b; }, m_core);
}

bool GltfBsdf::has_specular() const {
    return core().has_specular() || (m_coat && m_coat->is_delta() && m_coat->strength() > 0);
}

float GltfBsdf::coat_scale(Vec3 wo, Vec3 wi) const {
    if (!m_coat) return 1;
    return std::max(0.0f, std::min(1 - m_coat->layer_albedo(wo), 1 - m_coat->layer_albedo(wi)));
}

float GltfBsdf::sheen_layer_albedo(Vec3 w) const {
    return m_sheen_max * sheen_albedo(std::abs(w.z), m_sheen->shape().roughness());
}

float GltfBsdf::sheen_scale(Vec3 wo, Vec3 wi) const {
    if (!m_sheen) return 1;
    return std::max(0.0f, std::min(1 - sheen_layer_albedo(wo), 1 - sheen_layer_albedo(wi)));
}

GltfBsdf::Choice GltfBsdf::choose(Vec3 wo) const {
    // What each layer reflects of light from wo, and what it passes down: the coat
    // c E_c(wo), the sheen luminance(color) E_s(wo) of the rest, the core (whose albedo
    // is not known here; 1) what is left.
    const float coat = m_coat ? m_coat->layer_albedo(wo) : 0.0f;
    const float below = 1 - coat;
    float sheen = 0, sheen_pass = 1;
    if (m_sheen) {
        const float e = sheen_albedo(std::abs(wo.z), m_sheen->shape().roughness());
        sheen = below * std::max(0.0f, luminance(m_sheen->color())) * e;
        sheen_pass = std::max(0.0f, 1 - m_sheen_max * e);
    }
    const float core = below * sheen_pass;
    const float total = coat + sheen + core;
    Choice c;
    if (!(total > 0)) return c;
    c.coat = coat / total;
    c.sheen = sheen / total;
    c.core = std::max(0.0f, 1 - c.coat - c.sheen);
    return c;
}

Spectrum GltfBsdf::eval(Vec3 wo, Vec3 wi, Transport mode) const {
    Spectrum below = core().eval(wo, wi, mode);
    if (m_sheen) below = m_sheen->eval(wo, wi) + below * sheen_scale(wo, wi);
    if (!m_coat) return below;
    return Spectrum(m_coat->eval(wo, wi, mode)) + below * coat_scale(wo, wi);
}

Spectrum GltfBsdf::eval_diffuse(Vec3 wo, Vec3 wi, Transport mode) const {
    Spectrum below = core().eval_diffuse(wo, wi, mode);
    if (m_sheen) below = below * sheen_scale(wo, wi);
    return m_coat ? below * coat_scale(wo, wi) : below;
}

float GltfBsdf::pdf(Vec3 wo, Vec3 wi, Transport mode) const {
    const Choice c = choose(wo);
    float p = c.core * core().pdf(wo, wi, mode);
    if (c.sheen > 0) p += c.sheen * m_sheen->pdf(wo, wi);
    if (c.coat > 0) p += c.coat * m_coat->pdf(wo, wi);
    return p;
}

Spectrum GltfBsdf::eval_pdf(Vec3 wo, Vec3 wi, Transport mode, float* pdf_out) const {
    // eval()'s and pdf()'s expressions in their order, so that the values are theirs.
    float core_pdf;
    Spectrum below = core().eval_pdf(wo, wi, mode, &core_pdf);
    const Choice c = choose(wo);
    float p = c.core * core_pdf;
    if (c.sheen > 0) p += c.sheen * m_sheen->pdf(wo, wi);
    if (c.coat > 0) p += c.coat * m_coat->pdf(wo, wi);
    *pdf_out = p;
    if (m_sheen) below = m_sheen->eval(wo, wi) + below * sheen_scale(wo, wi);
    if (!m_coat) return below;
    return Spectrum(m_coat->eval(wo, wi, mode)) + below * coat_scale(wo, wi);
}

std::optional<BsdfSample> GltfBsdf::sample(Vec3 wo, float u_lobe, Vec2 u, Transport mode) const {
    const Choice c = choose(wo);
    std::optional<Vec3> wi;
    Lobe lobe = Lobe::Glossy;
    float eta = 1;
    if (u_lobe < c.coat) {
        if (m_coat->is_delta()) {
            wi = m_coat->mirror(wo);
            if (!wi) return std::nullopt;
            // f |cos| / pdf must be the coat's reflectance over its probability.
            return BsdfSample{*wi, Spectrum(m_coat->mirror_reflectance(wo) / wi->z), c.coat,
                              Lobe::Specular, 1};
        }
        wi = m_coat->sample(wo, u);
    } else if (u_lobe < c.coat + c.sheen) {
        wi = m_sheen->sample(wo, u);
    } else {
        if (!(c.core > 0)) return std::nullopt;
        const float u_inner =
            std::clamp((u_lobe - c.coat - c.sheen) / c.core, 0.0f, 0x1.fffffep-1f);
        std::optional<BsdfSample> s = core().sample(wo, u_inner, u, mode);
        if (!s) return std::nullopt;
        if (s->is_specular()) {
            // A Dirac lobe of the core, seen through the layers above it.
            s->f *= coat_scale(wo, s->wi) * sheen_scale(wo, s->wi);
            s->pdf *= c.core;
            return s;
        }
        wi = s->wi;
        lobe = s->lobe;
        eta = s->eta;  // a rough refraction of the core
    }
    if (!wi) return std::nullopt;
    BsdfSample s{*wi, Spectrum(0), 0, lobe, eta};
    s.f = eval_pdf(wo, *wi, mode, &s.pdf);
    if (!(s.pdf > 0)) return std::nullopt;
    return s;
}

}  // namespace penumbra
