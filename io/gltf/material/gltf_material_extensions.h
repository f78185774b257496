// Internal to io/: the KHR material extensions that add lobes or media to the
// metallic-roughness base (clearcoat, sheen, volume, iridescence, anisotropy, dispersion,
// diffuse transmission), read into MaterialDesc with the defaults and ranges of their specs.
#pragma once

#include "io/gltf/material/gltf_material_textures.h"

namespace penumbra {

// Reads the extensions of material gm (element path `el`) into d; throws SceneError for
// a value outside its spec's range or a bad texture reference.
void load_material_extensions(const GltfContext& ctx, const tinygltf::Material& gm,
                              const std::string& el, TextureTable& textures, MaterialDesc& d);

}  // namespace penumbra
