#include "materials/metal_rough_bsdf.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>

#include "core/sampling/warp.h"
#include "materials/lobes/fresnel.h"

namespace penumbra {

namespace {

// Unique without a shared counter per model: a thread takes a block of 2^40 numbers once
// (hits on textured materials build a model each, on both threads at once).
uint64_t new_model_id() {
    static std::atomic<uint64_t> threads{0};
    thread_local const uint64_t base = (threads.fetch_add(1, std::memory_order_relaxed) + 1) << 40;
    thread_local uint64_t count = 0;
    return base + ++count;
}

// Both alphas of the lobe: KHR_materials_anisotropy stretches it along x. Anisotropic
// lobes are GGX even under --microfacet beckmann: Beckmann's albedo table over four
// coordinates takes 45 s to integrate (its visible normals invert erf numerically), and the
// switch exists to compare isotropic lobes.
MicrofacetDistribution make_distribution(const MetalRoughParams& p) {
    if (!(p.anisotropy > 0)) return {p.distribution, p.alpha};
    const Vec2 a = anisotropic_alphas(p.alpha, p.anisotropy);
    return {MicrofacetType::Ggx, a.x, a.y};
}

// The film's terms live out of line (GCC attribute): films are rare, and inlined into
// eval() they made the isotropic sample() about 4% slower.
[[gnu::noinline]] Spectrum film_dielectric_fresnel(const MetalRoughParams& p, Spectrum film_f0,
                                                   float c) {
    // KHR_materials_iridescence: F = mix(F_schlick, F_iridescence, factor); the
    // specular factor scales the film's reflection as it scales Schlick's.
    const Spectrum fd = fresnel_schlick(p.dielectric_f0, p.dielectric_f90, c);
    const Spectrum ff = thin_film_reflectance(p.film, film_f0, c) * p.dielectric_f90;
    return fd + (ff - fd) * p.iridescence;
}

[[gnu::noinline]] Spectrum film_specular_fresnel(const MetalRoughParams& p, Spectrum film_f0,
                                                 float c) {
    Spectrum f = film_dielectric_fresnel(p, film_f0, c) * (1 - p.metallic);
    if (p.metallic > 0) {
        // The metal's film sits on base_color as its f0 (the spec's approximation).
        const Spectrum fm = fresnel_schlick(p.base_color, 1, c);
        const Spectrum ff = thin_film_reflectance(p.film, p.base_color, c);
        f += (fm + (ff - fm) * p.iridescence) * p.metallic;
    }
    return f;
}

// The node at or below the smallest v.h seen from cos(theta) = mu (see the constructor).
[[gnu::noinline]] float film_layer_f0(const float* bound, int nodes, float mu) {
    const float sin_theta = std::sqrt(std::max(0.0f, 1 - mu * mu));
    const float c_lo = std::sqrt(std::max(0.0f, 0.5f * (1 - sin_theta)));
    return bound[std::clamp(static_cast<int>(c_lo * nodes), 0, nodes)];
}

// 1 - the Schlick reflectance f0 + (f90 - f0)(1 - mu)^5.
float schlick_transmittance(float f0, float f90, float mu) {
    const float w = std::pow(1 - std::clamp(mu, 0.0f, 1.0f), 5.0f);
    return 1 - (f0 + (f90 - f0) * w);
}

bool is_delta(const MetalRoughParams& p) {
    if (!(p.alpha < MetalRoughBsdf::kDeltaAlpha)) return false;
    if (!(p.anisotropy > 0)) return true;
    // A smooth surface stretched along x is a mirror only while alpha_x is as small.
    return p.alpha + (1 - p.alpha) * (p.anisotropy * p.anisotropy) < MetalRoughBsdf::kDeltaAlpha;
}

}  // namespace

MetalRoughBsdf::MetalRoughBsdf(const MetalRoughParams& p)
    : m_p(p),
      m_dist(make_distribution(p)),
      m_delta(is_delta(p)),
      m_f0_max(max_component(p.dielectric_f0)),
      m_id(new_model_id()) {
    m_aniso = !m_delta && p.anisotropy > 0;
    m_film = p.iridescence > 0 && p.film.thickness > 0;
    if (m_film) {
        m_film_f0 = p.dielectric_f90 > 0 ? min(p.dielectric_f0 / p.dielectric_f90, Spectrum(1))
                                         : Spectrum(0);
        // The film's Fresnel is no Schlick curve, so E = f0 A + (f90 - f0) B cannot hold
        // it exactly. An f0 with f0 + (f90 - f0)(1 - c)^5 >= max_value(F(c)) for every c
        // that the lobe reaches bounds the layer's albedo from above (A and B weigh F
        // pointwise), so the base loses a little instead of gaining. Seen from
        // cos(theta) = mu, reflection into the upper hemisphere has
        // v.h >= sqrt((1 - sin(theta)) / 2), so each mu needs the bound only over
        // c from there to 1: a suffix maximum over nodes. (One bound for all c costs a
        // white dielectric under the spec's default film 0.23 at normal incidence: near
        // grazing the film's Schlick-based interference departs from Schlick's shape.)
        // 32 nodes resolve the film's oscillation in c (a period of 0.1 at 1200 nm). Only
        // the energy-conserving layering of a base needs it.
        const bool needs_bound = m_p.layering == GltfLayering::AlbedoScaled && m_p.metallic < 1;
        m_film_bound.fill(0);
        float bound = 0;
        for (int i = kFilmNodes; i >= 1 && needs_bound; --i) {
            const float c = float(i) / kFilmNodes, m = 1 - c;
            const float w = (m * m) * (m * m) * m;
            const float f = max_component(dielectric_fresnel(c));
            bound = std::max(bound, (f - m_p.dielectric_f90 * w) / (1 - w));
            m_film_bound[i] = std::clamp(bound, 0.0f, 1.0f);
        }
        m_film_bound[0] = m_film_bound[1];
        m_f0_max = m_film_bound[0];
    }
    // KHR_materials_specular's factor 0 on a dielectric leaves no layer at all: the
    // Lambertian base, without Fresnel, table lookups or a lobe choice.
    m_lambert = !m_film && !(m_p.metallic > 0) && !(m_f0_max > 0) && !(m_p.dielectric_f90 > 0);
    if (m_lambert) return;
    if (m_p.layering != GltfLayering::AlbedoScaled || m_p.metallic >= 1) return;
    float e_avg;
    if (m_delta) {
        // A mirror reflects F(mu) = f0 + (f90 - f0)(1 - mu)^5, whose cosine-weighted
        // average is f0 + (f90 - f0) 2 int (1 - mu)^5 mu dmu = f0 + (f90 - f0) / 21.
        e_avg = m_f0_max + (m_p.dielectric_f90 - m_f0_max) / 21;
    } else {
        Vec2 avg;
        if (m_aniso) {
            m_aniso_albedo = AnisotropicSpecularAlbedo(MicrofacetType::Ggx, p.alpha, p.anisotropy);
            avg = m_aniso_albedo.average();
        } else {
            m_albedo = SpecularAlbedo(p.distribution, p.alpha);
            avg = m_albedo.average();
        }
        e_avg = m_f0_max * avg.x + (m_p.dielectric_f90 - m_f0_max) * avg.y;
    }
    if (m_film) e_avg = film_average_albedo();
    // E_avg reaches 1 only for a lossless mirror layer (f0 = f90 = 1), which leaves
    // nothing to the base anyway.
    m_base_norm = e_avg < 1 ? 1 / (1 - e_avg) : 0;
}

float MetalRoughBsdf::fresnel_transmittance(float mu) const {
    if (m_film) return 1 - max_component(dielectric_fresnel(std::clamp(mu, 0.0f, 1.0f)));
    return schlick_transmittance(m_f0_max, m_p.dielectric_f90, mu);
}

float MetalRoughBsdf::layer_f0(float mu) const {
    return m_film ? film_layer_f0(m_film_bound.data(), kFilmNodes, mu) : m_f0_max;
}

float MetalRoughBsdf::film_average_albedo() const {
    // (1/pi) int E(w) cos dw of the layering's E, exactly: the film's f0 bound is constant
    // between the cosines where c_lo crosses a node c (sin = 1 - 2 c^2), and A, B (for an
    // anisotropic lobe their azimuthal average) are linear in mu between the table's
    // columns, so each piece integrates exactly: in closed form from its ends, or for a
    // mirror's (1 - mu)^5 by Gauss-Legendre. (Midpoints fine enough cost 20 us per hit.)
    std::array<float, 2 + kFilmNodes + SpecularAlbedoGrid::kColumns> cuts{};
    int n = 0;
    cuts[n++] = 0;
    cuts[n++] = 1;
    for (int i = 1; i <= kFilmNodes; ++i) {
        const float c = float(i) / kFilmNodes, sin_theta = 1 - 2 * c * c;
        if (!(sin_theta > 0)) break;
        cuts[n++] = std::sqrt(1 - sin_theta * sin_theta);
    }
    const int columns = m_delta ? 0
                        : m_aniso ? AnisotropicSpecularAlbedo::columns()
                                  : SpecularAlbedoGrid::kColumns;
    for (int i = 1; i + 1 < columns; ++i) {
        const float t = float(i) / (columns - 1);
        cuts[n++] = t * t * t;
    }
    std::sort(cuts.begin(), cuts.begin() + n);
    // (A, B) at mu: the mirror's, the isotropic table's, or the anisotropic azimuthal
    // average interpolated between its columns as at() is.
    const auto albedo = [&](float mu) {
        if (m_delta) {
            const float m = 1 - mu;
            return Vec2(1, (m * m) * (m * m) * m);
        }
        if (!m_aniso) return m_albedo.at(mu);
        const int i = std::min(static_cast<int>(std::cbrt(mu) * (columns - 1)), columns - 2);
        const float t0 = float(i) / (columns - 1), t1 = float(i + 1) / (columns - 1);
        const float mu0 = t0 * t0 * t0, mu1 = t1 * t1 * t1;
        const float f = std::clamp((mu - mu0) / (mu1 - mu0), 0.0f, 1.0f);
        return m_aniso_albedo.azimuthal_average(i) * (1 - f) +
               m_aniso_albedo.azimuthal_average(i + 1) * f;
    };
    double sum = 0;
    if (m_delta) {
        // The mirror's 2 mu (f0 + (f90 - f0)(1 - mu)^5): 4-point Gauss-Legendre per piece.
        static constexpr double kX[] = {-0.8611363115940526, -0.3399810435848563,
                                        0.3399810435848563, 0.8611363115940526};
        static constexpr double kW[] = {0.3478548451374538, 0.6521451548625461,
                                        0.6521451548625461, 0.3478548451374538};
        for (int s = 0; s + 1 < n; ++s) {
            const double u = cuts[s], v = cuts[s + 1];
            if (!(v > u)) continue;
            const float f0 = layer_f0(float(0.5 * (u + v)));
            for (int g = 0; g < 4; ++g) {
                const double mu = 0.5 * (u + v) + 0.5 * (v - u) * kX[g];
                const Vec2 ab = albedo(float(mu));
                sum += 0.5 * (v - u) * kW[g] * (f0 * ab.x + (m_p.dielectric_f90 - f0) * ab.y) * 2 * mu;
            }
        }
        return float(sum);
    }
    // A and B are linear on each piece, so from its end values: int_u^v 2 mu e(mu) dmu for
    // e linear from e_u to e_v is (v - u) (e_u (2 u + v) + e_v (u + 2 v)) / 3.
    Vec2 ab_u = albedo(cuts[0]);
    for (int s = 0; s + 1 < n; ++s) {
        const double u = cuts[s], v = cuts[s + 1];
        const Vec2 ab_v = albedo(cuts[s + 1]);
        if (v > u) {
            const float f0 = layer_f0(float(0.5 * (u + v))), f90 = m_p.dielectric_f90;
            const double e_u = f0 * ab_u.x + (f90 - f0) * ab_u.y;
            const double e_v = f0 * ab_v.x + (f90 - f0) * ab_v.y;
            sum += (v - u) * (e_u * (2 * u + v) + e_v * (u + 2 * v)) / 3;
        }
        ab_u = ab_v;
    }
    return float(sum);
}

float MetalRoughBsdf::base_transmittance(Vec3 w) const {
    if (!(m_aniso | m_film)) {
        // The isotropic layer without a film, kept apart so that anisotropy and films add
        // nothing to its cost.
        if (m_p.layering == GltfLayering::Spec || m_delta)
            return schlick_transmittance(m_f0_max, m_p.dielectric_f90, w.z);
        const Vec2 ab = m_albedo.at(w.z);
        return 1 - (m_f0_max * ab.x + (m_p.dielectric_f90 - m_f0_max) * ab.y);
    }
    if (m_p.layering == GltfLayering::Spec || m_delta) {
        // The spec's 1 - F; for a mirror layer this is also 1 - E, its albedo (with a
        // film, the bound's, as the constructor's E_avg assumes).
        if (m_delta && m_film && m_p.layering == GltfLayering::AlbedoScaled)
            return schlick_transmittance(layer_f0(w.z), m_p.dielectric_f90, w.z);
        return fresnel_transmittance(w.z);
    }
    const Vec2 ab = m_aniso ? m_aniso_albedo.at(w) : m_albedo.at(w.z);
    const float f0 = layer_f0(w.z);
    return 1 - (f0 * ab.x + (m_p.dielectric_f90 - f0) * ab.y);
}

Spectrum MetalRoughBsdf::dielectric_fresnel(float c) const {
    if (m_film) return film_dielectric_fresnel(m_p, m_film_f0, c);
    return fresnel_schlick(m_p.dielectric_f0, m_p.dielectric_f90, c);
}

Spectrum MetalRoughBsdf::specular_fresnel(float c) const {
    if (m_film) return film_specular_fresnel(m_p, m_film_f0, c);
    const Spectrum fd = fresnel_schlick(m_p.dielectric_f0, m_p.dielectric_f90, c);
    const Spectrum fm = fresnel_schlick(m_p.base_color, 1, c);
    return fd * (1 - m_p.metallic) + fm * m_p.metallic;
}

thread_local MetalRoughBsdf::WoTerms MetalRoughBsdf::s_wo;

MetalRoughBsdf::WoTerms MetalRoughBsdf::wo_terms(Vec3 wo) const {
    WoTerms& c = s_wo;
    uint32_t key[3];
    std::memcpy(key, &wo, sizeof key);
    if (c.model == m_id && key[0] == c.key[0] && key[1] == c.key[1] && key[2] == c.key[2]) return c;
    c.model = m_id;
    std::memcpy(c.key, key, sizeof key);
    // A metal has no base, a bare base no layer (and neither an albedo table: the
    // constructor stops before it).
    c.transmittance = m_p.metallic >= 1 || m_lambert ? 1.0f : base_transmittance(wo);
    c.probability = m_lambert ? 0.0f : specular_probability(wo, c.transmittance);
    c.lambda = m_delta ? 0.0f : m_dist.lambda(wo);
    return c;
}

Spectrum MetalRoughBsdf::diffuse_term(const WoTerms& t, Vec3 wi, float cos_vh) const {
    if (m_p.metallic >= 1) return Spectrum(0);
    float weight;
    if (m_p.layering == GltfLayering::Spec) {
        // glTF's fresnel_mix: the base keeps what the layer transmits at v.h.
        weight = fresnel_transmittance(cos_vh);
    } else {
        // What the layer leaves on the way in and on the way out, normalized so that
        // the base's cosine-weighted average of the second factor is 1.
        weight = t.transmittance * base_transmittance(wi) * m_base_norm;
    }
    return m_p.base_color * ((1 - m_p.metallic) * std::max(0.0f, weight) * kInvPi);
}

float MetalRoughBsdf::specular_probability(Vec3 wo, float transmittance) const {
    // Lobe weights from the albedo each lobe would have at normal-ish incidence; any
    // positive choice keeps the estimator unbiased, this one keeps variance low.
    const float spec = luminance(specular_fresnel(wo.z));
    const float diff = m_p.metallic >= 1 ? 0.0f
                                         : luminance(m_p.base_color) * (1 - m_p.metallic) *
                                               std::max(0.0f, transmittance);
    const float total = spec + diff;
    if (!(total > 0)) return 0;
    return std::clamp(spec / total, 0.0f, 1.0f);
}

Spectrum MetalRoughBsdf::eval(Vec3 wo, Vec3 wi, Transport) const {
    if (wo.z <= 0 || wi.z <= 0) return Spectrum(0);
    if (m_lambert) return m_p.base_color * kInvPi;
    Vec3 h = wo + wi;
    if (length_squared(h) == 0) return Spectrum(0);
    h = normalize(h);
    const WoTerms& t = wo_terms(wo);
    const float vh = std::max(0.0f, dot(wo, h));
    Spectrum f = diffuse_term(t, wi, vh);
    if (!m_delta) {
        // G(wo, wi) = 1 / (1 + Lambda(wo) + Lambda(wi)), Lambda(wo) kept.
        const float g = 1 / (1 + t.lambda + m_dist.lambda(wi));
        const float spec = m_dist.D(h) * g / (4 * wo.z * wi.z);
        f += specular_fresnel(vh) * spec;
    }
    return f;
}

Spectrum MetalRoughBsdf::eval_diffuse(Vec3 wo, Vec3 wi, Transport) const {
    if (wo.z <= 0 || wi.z <= 0) return Spectrum(0);
    if (m_lambert) return m_p.base_color * kInvPi;
    Vec3 h = wo + wi;
    if (length_squared(h) == 0) return Spectrum(0);
    h = normalize(h);
    return diffuse_term(wo_terms(wo), wi, std::max(0.0f, dot(wo, h)));
}

float MetalRoughBsdf::pdf_specular(const WoTerms& t, Vec3 wo, Vec3 h) const {
    const float woh = dot(wo, h);
    if (woh <= 0) return 0;
    // Visible normals' density G1(wo) (wo.h) D(h) / wo.z; reflection maps h to wi with
    // Jacobian 1 / (4 |wo.h|).
    const float g1 = 1 / (1 + t.lambda);
    return g1 * woh * m_dist.D(h) / wo.z / (4 * woh);
}

float MetalRoughBsdf::pdf(Vec3 wo, Vec3 wi, Transport) const {
    if (wo.z <= 0 || wi.z <= 0) return 0;
    if (m_lambert) return cosine_hemisphere_pdf(wi);
    const WoTerms& t = wo_terms(wo);
    const float ps = t.probability;
    const float spec = m_delta ? 0.0f : pdf_specular(t, wo, normalize(wo + wi));
    return ps * spec + (1 - ps) * cosine_hemisphere_pdf(wi);
}

Spectrum MetalRoughBsdf::eval_pdf(Vec3 wo, Vec3 wi, Transport, float* pdf_out) const {
    // eval()'s and pdf()'s guard, then their shared expressions (the next function).
    if (wo.z <= 0 || wi.z <= 0) {
        *pdf_out = 0;
        return Spectrum(0);
    }
    return eval_pdf(wo_terms(wo), wo, wi, pdf_out);
}

Spectrum MetalRoughBsdf::eval_pdf(const WoTerms& t, Vec3 wo, Vec3 wi, float* pdf) const {
    if (m_lambert) {
        *pdf = cosine_hemisphere_pdf(wi);
        return m_p.base_color * kInvPi;
    }
    Vec3 h = wo + wi;
    if (length_squared(h) == 0) {
        *pdf = this->pdf(wo, wi, Transport::Radiance);
        return Spectrum(0);
    }
    h = normalize(h);
    const float ps = t.probability;
    const float vh = std::max(0.0f, dot(wo, h));
    Spectrum f = diffuse_term(t, wi, vh);
    float spec_pdf = 0;
    if (!m_delta) {
        // eval()'s and pdf_specular()'s expressions, with D(h) once.
        const float d = m_dist.D(h);
        const float g = 1 / (1 + t.lambda + m_dist.lambda(wi));
        f += specular_fresnel(vh) * (d * g / (4 * wo.z * wi.z));
        const float woh = dot(wo, h);
        if (woh > 0) spec_pdf = 1 / (1 + t.lambda) * woh * d / wo.z / (4 * woh);
    }
    *pdf = ps * spec_pdf + (1 - ps) * cosine_hemisphere_pdf(wi);
    return f;
}

std::optional<BsdfSample> MetalRoughBsdf::sample(Vec3 wo, float u_lobe, Vec2 u,
                                                 Transport) const {
    if (wo.z <= 0) return std::nullopt;
    const WoTerms& t = wo_terms(wo);
    const float ps = t.probability;
    if (u_lobe < ps) {
        if (m_delta) {
            const Vec3 wi(-wo.x, -wo.y, wo.z);
            // f * cos / pdf must equal F / ps: f = F / cos, pdf = ps.
            return BsdfSample{wi, specular_fresnel(wo.z) / wi.z, ps, Lobe::Specular, 1};
        }
        const Vec3 h = m_dist.sample_visible(wo, u);
        const Vec3 wi = reflect(wo, h);
        if (wi.z <= 0) return std::nullopt;
        float pdf_value;
        const Spectrum f = eval_pdf(t, wo, wi, &pdf_value);
        if (!(pdf_value > 0)) return std::nullopt;
        return BsdfSample{wi, f, pdf_value, Lobe::Glossy, 1};
    }
    const Vec3 wi = square_to_cosine_hemisphere(u);
    if (wi.z <= 0) return std::nullopt;
    float pdf_value;
    const Spectrum f = eval_pdf(t, wo, wi, &pdf_value);
    if (!(pdf_value > 0)) return std::nullopt;
    return BsdfSample{wi, f, pdf_value, Lobe::Diffuse, 1};
}

}  // namespace penumbra
