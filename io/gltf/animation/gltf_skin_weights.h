// Internal to io/: a skinned primitive's JOINTS_n/WEIGHTS_n, read, validated and
// normalised per vertex as three.js and Blender's importer do, and the one summary
// warning per file for the vertices whose weights did not sum to one.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "io/gltf/gltf_context.h"

namespace penumbra {

struct SkinWeights {
    // 4 per vertex and set, set after set: entry set * 4 * vertices + 4 * v + c.
    std::vector<float> joints, weights;
    size_t influences = 0;    // sets of 4 influences
    size_t renormalized = 0;  // vertices whose sum was off by more than float rounding
    size_t example = 0;       // the first of them, and its sum before normalisation
    double example_sum = 0;
};

// Scales each vertex's weights, over all its sets, by 1 / sum |w| (three.js's
// SkinnedMesh.normalizeSkinWeights; Blender's importer divides by the sum too). A vertex
// whose sum is 0 or not finite gets weight 1 on its first influence (JOINTS_0's first
// joint) and 0 elsewhere: three.js's fallback for a zero sum. Counts in `renormalized`
// the vertices whose sum differed from 1 by more than glTF-Validator allows before it
// reports ACCESSOR_WEIGHTS_NON_NORMALIZED: 2e-7 (float32 rounding) per nonzero weight.
void normalize_skin_weights(SkinWeights& w, size_t vertices);

// The primitive's JOINTS_n/WEIGHTS_n sets (`el` names it in errors), normalised; every
// joint index with a nonzero weight must be below `joint_count`. Throws SceneError for a
// missing or mismatched set, a wrong accessor type or count, or a joint out of range.
SkinWeights read_skin_weights(const GltfContext& ctx, const std::string& el,
                              const tinygltf::Primitive& prim, size_t vertices, size_t joint_count);

// One warning for the file (strict: an error) naming the skinned meshes of the scene's
// instances whose vertices were renormalised, how many, and the first example. Reads the
// weights of the primitives loaded (`origins`) of every mesh a skinned node draws.
void warn_unnormalized_skin_weights(const GltfContext& ctx, const Scene& scene,
                                    const std::vector<MeshOrigin>& origins);

}  // namespace penumbra
