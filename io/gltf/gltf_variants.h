// Internal to io/: KHR_materials_variants. The file names variants at its root; each
// primitive may map variants to other materials. The default material applies unless a
// variant is chosen by name and the primitive maps it.
#pragma once

#include <string>

#include "io/gltf/gltf_context.h"

namespace penumbra {

// The index of the variant called `name` in the file's root variants list; -1 for an
// empty name. Throws SceneError listing the file's variants when none has that name.
int find_variant(const GltfContext& ctx, const std::string& name);

// The material index primitive `prim` (element path `el`) uses for variant ctx.variant:
// the first of its mappings that lists the variant, else prim.material. Checks every
// mapping's material and variant indices, chosen or not.
int primitive_material(const GltfContext& ctx, const tinygltf::Primitive& prim,
                       const std::string& el);

}  // namespace penumbra
