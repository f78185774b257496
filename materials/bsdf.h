// The BSDF interface. Everything is in the local shading frame: z is the shading normal,
// wo and wi point away from the surface, and values exclude the cosine factor.
#pragma once

#include <optional>

#include "core/math/vec.h"

namespace penumbra {

enum class Lobe { Diffuse, Glossy, Specular };
// Light flows from lights to the camera (radiance) or the reverse (importance).
enum class Transport { Radiance, Importance };

struct BsdfSample {
    Vec3 wi;
    Spectrum f;      // BSDF value (no cosine); for specular lobes f * |cos| / pdf is the weight
    float pdf = 0;   // solid angle; for specular lobes, the probability of the lobe
    Lobe lobe = Lobe::Diffuse;
    float eta = 1;   // refraction: IOR on wi's side over IOR on wo's side; else 1

    bool is_specular() const { return lobe == Lobe::Specular; }
    Spectrum weight() const { return f * (std::abs(wi.z) / pdf); }
};

class Bsdf {
public:
    virtual ~Bsdf() = default;
    // f(wo, wi) without the cosine; 0 for specular lobes.
    virtual Spectrum eval(Vec3 wo, Vec3 wi, Transport mode) const = 0;
    // Solid-angle density with which sample() returns wi; 0 for specular lobes.
    virtual float pdf(Vec3 wo, Vec3 wi, Transport mode) const = 0;
    // eval() and pdf() at once, bit for bit the same values: what a light sample weighed
    // by MIS needs. BSDFs whose two share work (the half vector, D(h)) compute it once.
    virtual Spectrum eval_pdf(Vec3 wo, Vec3 wi, Transport mode, float* pdf_out) const {
        *pdf_out = pdf(wo, wi, mode);
        return eval(wo, wi, mode);
    }
    // The diffuse lobes' share of eval(wo, wi) (same frame and measure, no cosine): what
    // a normal map's bump shadowing darkens (integrators/direct_lighting.h). Glossy,
    // specular and transmission lobes have none; 0 unless a model has diffuse lobes.
    virtual Spectrum eval_diffuse(Vec3 wo, Vec3 wi, Transport mode) const { return Spectrum(0); }
    // u_lobe chooses a lobe, u the direction within it. Empty: no valid sample.
    virtual std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Vec2 u,
                                             Transport mode) const = 0;
    // True when some lobe is a Dirac delta (perfect mirror or glass).
    virtual bool has_specular() const = 0;
    // Whether this is a LambertianBsdf: the integrators' inner loops call that model
    // without the virtual dispatch (bsdf_calls.h).
    bool is_lambertian() const { return m_lambertian; }

protected:
    Bsdf() = default;
    explicit Bsdf(bool lambertian) : m_lambertian(lambertian) {}

private:
    bool m_lambertian = false;
};

}  // namespace penumbra
