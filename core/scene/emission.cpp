#include "core/scene/emission.h"

namespace penumbra {

Spectrum emitted_radiance(const Scene& scene, const MaterialDesc& m, Vec2 uv0, Vec2 uv1,
                          const float* uv_width) {
    Spectrum e = m.emissive * m.emissive_strength;
    if (m.emissive_texture.valid() && !is_black(e)) {
        const Texture& tex = scene.textures[m.emissive_texture.texture];
        const float width = uv_width ? m.emissive_texture.width(uv_width[0], uv_width[1]) : 0;
        e *= lookup(tex, scene.images[tex.image], m.emissive_texture.uv(uv0, uv1), width).xyz();
    }
    return e;
}

Spectrum mean_emission_texture(const Scene& scene, const MaterialDesc& m) {
    if (!m.emissive_texture.valid()) return Spectrum(1);
    const TextureImage& img = scene.images[scene.textures[m.emissive_texture.texture].image];
    if (img.empty()) return Spectrum(1);
    // Over level 0, not the 1x1 level, which holds the mean rounded to the format.
    double sum[3] = {0, 0, 0};
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const Vec4 p = img.texel(0, x, y);
            for (int c = 0; c < 3; ++c) sum[c] += p[c];
        }
    const double n = double(img.width()) * img.height();
    const Spectrum mean(float(sum[0] / n), float(sum[1] / n), float(sum[2] / n));
    return img.color_matrix() ? *img.color_matrix() * mean : mean;
}

}  // namespace penumbra
