// Coverage of a glTF material (alphaMode): how much of a surface is there. One rule for
// the material at a hit (shade's opacity), shadow rays crossing the surface and the area
// lights that sample emissive triangles, so that every estimator sees the same surface.
#pragma once

#include <algorithm>

#include "core/scene/scene.h"

namespace penumbra {

// From the alpha (baseColorFactor's, times COLOR_0's, times the base colour texture's):
// 1 for OPAQUE, 0 or 1 by alphaCutoff for MASK, the alpha clamped to [0, 1] for BLEND.
// Inline: shade() asks at every hit.
inline float coverage_from_alpha(const MaterialDesc& m, float alpha) {
    switch (m.alpha_mode) {
        case AlphaMode::Opaque:
            return 1;
        case AlphaMode::Mask:
            return alpha >= m.alpha_cutoff ? 1.0f : 0.0f;
        case AlphaMode::Blend:
            return std::clamp(alpha, 0.0f, 1.0f);
    }
    return 1;
}

// The coverage at a point with texture coordinates uv0 / uv1 and COLOR_0 alpha
// vertex_alpha. uv_width: the footprint in each UV set (SurfacePoint::uv_width); null
// (light sampling, which has no ray cone) reads the finest level.
float material_coverage(const Scene& scene, const MaterialDesc& m, Vec2 uv0, Vec2 uv1,
                        float vertex_alpha, const float* uv_width = nullptr);

}  // namespace penumbra
