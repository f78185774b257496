// Emitted radiance of a glTF material at a surface point (emissiveFactor times
// emissiveStrength times the emissive texture) and the faces it leaves. One place, used
// by both the material at a hit and the area lights that sample emissive triangles.
#pragma once

#include "core/scene/scene.h"

namespace penumbra {

// uv_width: the footprint in each UV set (SurfacePoint::uv_width); null (light sampling,
// which has no ray cone) reads the finest level.
Spectrum emitted_radiance(const Scene& scene, const MaterialDesc& m, Vec2 uv0, Vec2 uv1,
                          const float* uv_width = nullptr);
// Whether the material emits towards w from a surface whose glTF front face looks along
// n_front: a single-sided material (doubleSided false, the default) emits from its front
// only, a double-sided one from both faces. The one rule of the area lights and shade().
inline bool emits_towards(const MaterialDesc& m, Vec3 n_front, Vec3 w) {
    return m.double_sided || dot(n_front, w) > 0;
}
// Mean of the emissive texture's RGB over the image (1 without a texture): an estimate
// of an emitter's power for light selection.
Spectrum mean_emission_texture(const Scene& scene, const MaterialDesc& m);

}  // namespace penumbra
