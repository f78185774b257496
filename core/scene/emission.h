// Emitted radiance of a glTF material at a surface point: emissiveFactor times
// emissiveStrength times the emissive texture. One place, used by both the material at a
// hit and the area lights that sample emissive triangles.
#pragma once

#include "core/scene/scene.h"

namespace penumbra {

Spectrum emitted_radiance(const Scene& scene, const MaterialDesc& m, Vec2 uv0, Vec2 uv1);
// Mean of the emissive texture's RGB over the image (1 without a texture): an estimate
// of an emitter's power for light selection.
Spectrum mean_emission_texture(const Scene& scene, const MaterialDesc& m);

}  // namespace penumbra
