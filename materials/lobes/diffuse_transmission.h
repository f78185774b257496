// KHR_materials_diffuse_transmission's lobe: Lambertian transmission to the other side
// of a thin surface, color / pi, weighted like the diffuse base by what glTF's
// dielectric specular layer transmits (SpecularLayerTransmittance).
#pragma once

#include "materials/bsdf.h"
#include "materials/metal_rough_bsdf.h"

namespace penumbra {

// The share of light that the dielectric specular layer of MetalRoughBsdf leaves to the
// base, for a pair of directions; the same formulas as its diffuse term (the base of
// MetalRoughBsdf with the same parameters has f = base_color / pi * weight()):
// AlbedoScaled: (1 - E(|cos_o|)) (1 - E(|cos_i|)) / (1 - E_avg); Spec: 1 - F(v.h) with wi
// mirrored onto wo's side (the glTF Sample Viewer's diffuse transmission does the same).
class SpecularLayerTransmittance {
public:
    explicit SpecularLayerTransmittance(const MetalRoughParams& p);
    // 1 - E(mu) (AlbedoScaled) or 1 - F(mu) (Spec, and mirror layers), scalar as the
    // spec's max_value(F).
    float at(float mu) const;
    float weight(Vec3 wo, Vec3 wi) const;

private:
    GltfLayering m_layering;
    bool m_delta;
    float m_f0, m_f90;
    SpecularAlbedo m_albedo;
    float m_norm = 1;
};

// f = color / pi * layer.weight(wo, wi) for wo and wi on opposite sides, else 0;
// cosine-weighted sampling of the far hemisphere. Symmetric in wo and wi, and it does
// not refract, so both transport modes agree and BsdfSample::eta is 1.
class DiffuseTransmissionLobe {
public:
    DiffuseTransmissionLobe(Spectrum color, const SpecularLayerTransmittance& layer)
        : m_color(color), m_layer(layer) {}
    Spectrum eval(Vec3 wo, Vec3 wi) const;
    float pdf(Vec3 wo, Vec3 wi) const;
    std::optional<Vec3> sample(Vec3 wo, Vec2 u) const;
    Spectrum color() const { return m_color; }
    const SpecularLayerTransmittance& layer() const { return m_layer; }

private:
    Spectrum m_color;
    SpecularLayerTransmittance m_layer;
};

}  // namespace penumbra
