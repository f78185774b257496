#include "core/scene/emission.h"

namespace penumbra {

Spectrum emitted_radiance(const Scene& scene, const MaterialDesc& m, Vec2 uv0, Vec2 uv1) {
    Spectrum e = m.emissive * m.emissive_strength;
    if (m.emissive_texture.valid() && !is_black(e)) {
        const Texture& tex = scene.textures[m.emissive_texture.texture];
        e *= lookup(tex, scene.images[tex.image], m.emissive_texture.uv(uv0, uv1)).xyz();
    }
    return e;
}

Spectrum mean_emission_texture(const Scene& scene, const MaterialDesc& m) {
    if (!m.emissive_texture.valid()) return Spectrum(1);
    const Image& img = scene.images[scene.textures[m.emissive_texture.texture].image];
    if (img.width == 0 || img.height == 0) return Spectrum(1);
    double sum[3] = {0, 0, 0};
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const Vec4 p = img.rgba(x, y);
            for (int c = 0; c < 3; ++c) sum[c] += p[c];
        }
    const double n = double(img.width) * img.height;
    return {float(sum[0] / n), float(sum[1] / n), float(sum[2] / n)};
}

}  // namespace penumbra
