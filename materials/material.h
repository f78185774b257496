// A material at a hit: looks up the glTF material's textures at the surface point and
// builds the shading frame (with the normal map) and the BSDF that integrators use.
#pragma once

#include <utility>
#include <variant>

#include "core/math/frame.h"
#include "core/scene/scene.h"
#include "core/surface_point.h"
#include "materials/lobes/conductor.h"
#include "materials/lobes/cook_torrance.h"
#include "materials/lobes/dielectric.h"
#include "materials/gltf_bsdf.h"
#include "materials/gltf_transmission_bsdf.h"
#include "materials/lobes/lambertian.h"
#include "materials/metal_rough_bsdf.h"
#include "materials/lobes/oren_nayar.h"

namespace penumbra {

// Holds whichever model the material turned into, without a heap allocation per hit.
// The model is also kept as a pointer, so that the integrators' BSDF calls (one per light
// sample and bounce) do not each go through std::visit; a copy points into its own storage.
// It may instead refer to a model held elsewhere (a material's prototype, which outlives
// every hit, when the model keeps no state): its own storage then stays empty, and copies
// refer to the same model.
class BsdfStorage {
public:
    BsdfStorage() = default;
    BsdfStorage(const BsdfStorage& o) : m_v(o.m_v), m_bsdf(o.m_bsdf) { rebind(); }
    BsdfStorage& operator=(const BsdfStorage& o) {
        m_v = o.m_v;
        m_bsdf = o.m_bsdf;
        rebind();
        return *this;
    }
    // The model that proto holds, referred to where it is, not copied: the models keep
    // no state between calls (MetalRoughBsdf's last wo's terms are per thread), so one
    // serves every thread's hits. A copy per hit would move a few hundred bytes.
    void use(const BsdfStorage& proto) {
        m_v = std::monostate{};
        m_bsdf = proto.get();
    }
    // Constructs the model in place from its constructor's arguments: a model built
    // first and then copied in would move its few hundred bytes twice per hit.
    template <typename T, typename... Args>
    void emplace(Args&&... args) {
        m_bsdf = &m_v.template emplace<T>(std::forward<Args>(args)...);
    }
    // Null before emplace.
    const Bsdf* get() const { return m_bsdf; }

private:
    const Bsdf* held() const;  // the alternative m_v holds (std::visit)
    // After a copy: a model of its own is pointed to in this storage, one referred to
    // stays where it is.
    void rebind() {
        if (m_v.index() != 0) m_bsdf = held();
    }
    std::variant<std::monostate, LambertianBsdf, OrenNayarBsdf, MetalRoughBsdf,
                 GltfTransmissionBsdf, DielectricBsdf, ConductorBsdf, CookTorranceBsdf, GltfBsdf>
        m_v;
    const Bsdf* m_bsdf = nullptr;
};

class BsdfPrototypes;

struct ShadingData {
    Frame frame;          // z = shading normal (normal-mapped), on the side of wo
    Vec3 ng;              // geometric normal, on the side of wo
    // The interpolated normal before any normal map, on the side of wo (side_normal(sp,
    // ng)): the normal that decides on which side a light or BSDF sample lies. Once per
    // hit here, where every sample asked for it (four times a path vertex).
    Vec3 n_side;
    // frame.n differs from n_side (a normal map): light there takes bump_shadowing.
    bool bumped = false;
    BsdfStorage bsdf;
    Spectrum emission;    // Le towards wo
    Spectrum base_color;  // for the albedo AOV and debug views
    float opacity = 1;    // coverage from alphaMode: 1 opaque, 0 a hole, else partial
    // wo arrives on the side the unflipped geometric normal points to: outside a closed
    // mesh, so a refracting BSDF goes from IOR 1 into the material (else out of it).
    bool front_face = true;
};

// How glTF materials become BSDFs, chosen per render.
struct MaterialOptions {
    // The microfacet distribution of glTF's specular lobes: GGX as the spec says, or
    // Beckmann to compare (--microfacet).
    MicrofacetType gltf_distribution = MicrofacetType::Ggx;
    // How the diffuse base of dielectrics layers under the specular lobe (--gltf-layering).
    GltfLayering gltf_layering = GltfLayering::AlbedoScaled;
    // The least roughness of the specular and clearcoat lobes: the path tracer's
    // regularization raises it after a rough bounce (IntegratorOptions). 0: as authored.
    float min_roughness = 0;
    // Models built once per material where nothing varies over the surface
    // (bsdf_prototypes.h; RenderContext owns them); null: build every hit's.
    const BsdfPrototypes* prototypes = nullptr;
};

// What a path knows about the volumes around a hit (integrators/path_media.h).
struct PathVolume {
    // The RGB channel (0-2) whose IOR dispersive volumes refract at (materials/
    // dispersion.h); -1: the material's own IOR.
    int dispersion_channel = -1;
    // For a material with a volume: the IOR beyond the surface over the IOR on wo's side,
    // from the media the path is in (liquid in glass); 0: the material against IOR 1.
    float eta = 0;
};

// wo: unit world direction towards the viewer (-ray.d). Materials with a clearcoat,
// sheen or diffuse transmission become a GltfBsdf; the rest keep the plain models.
// KHR_materials_unlit: the base colour is emitted and the BSDF is black, so paths end
// there; such surfaces are not light-sampled (MaterialDesc::is_emissive is false), yet
// light every path that reaches them, unlike Blender's importer, which makes unlit
// materials visible to camera rays only (emission mixed with transparency by the
// "Is Camera Ray" light path output).
ShadingData shade(const Scene& scene, const SurfacePoint& sp, Vec3 wo,
                  const MaterialOptions& options = {}, const PathVolume& path = {});

// Coverage of the surface at sp from glTF's alphaMode: OPAQUE is 1, MASK is 0 or 1 by
// alphaCutoff, BLEND is the alpha itself (rendered as stochastic transparency).
float surface_opacity(const Scene& scene, const SurfacePoint& sp);
// True when some material is MASK or BLEND, so rays must test coverage.
bool scene_has_alpha(const Scene& scene);
// True when some material can give a hit emission (shade's sd.emission): an emissive
// factor times strength that is not black, or KHR_materials_unlit.
bool scene_has_emission(const Scene& scene);

}  // namespace penumbra
