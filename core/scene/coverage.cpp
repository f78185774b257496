#include "core/scene/coverage.h"

#include <algorithm>

#include "core/texture.h"

namespace penumbra {

float material_coverage(const Scene& scene, const MaterialDesc& m, Vec2 uv0, Vec2 uv1,
                        float vertex_alpha, const float* uv_width) {
    if (m.alpha_mode == AlphaMode::Opaque) return 1;
    float alpha = m.base_color.w * vertex_alpha;
    if (m.base_color_texture.valid()) {
        const Texture& tex = scene.textures[m.base_color_texture.texture];
        const float width = uv_width ? m.base_color_texture.width(uv_width[0], uv_width[1]) : 0;
        alpha *= lookup(tex, scene.images[tex.image], m.base_color_texture.uv(uv0, uv1), width).w;
    }
    return coverage_from_alpha(m, alpha);
}

}  // namespace penumbra
