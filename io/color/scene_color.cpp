#include "io/color/scene_color.h"

#include <set>

namespace penumbra {

void convert_image_colors(Image& img, const Mat3& m) {
    if (m.is_identity() || img.channels < 3) return;
    for (size_t i = 0; i < img.pixels.size(); i += size_t(img.channels)) {
        const Vec3 c = m * Vec3(img.pixels[i], img.pixels[i + 1], img.pixels[i + 2]);
        img.pixels[i] = c.x;
        img.pixels[i + 1] = c.y;
        img.pixels[i + 2] = c.z;
    }
}

void convert_scene_colors(Scene& scene, const Mat3& m) {
    if (m.is_identity()) return;
    std::set<uint32_t> colour_images;
    auto note = [&](const TextureRef& r) {
        if (r.valid()) colour_images.insert(scene.textures[size_t(r.texture)].image);
    };
    for (MaterialDesc& mat : scene.materials) {
        mat.base_color = Vec4(m * mat.base_color.xyz(), mat.base_color.w);
        mat.emissive = m * mat.emissive;
        mat.specular_color = m * mat.specular_color;
        mat.sheen_color = m * mat.sheen_color;
        mat.attenuation_color = m * mat.attenuation_color;
        mat.diffuse_transmission_color = m * mat.diffuse_transmission_color;
        // The sRGB-encoded textures are the colour ones (gltf_material*.cpp); A channels
        // (specular-glossiness's glossiness) are left alone by convert_image_colors.
        for (const TextureRef* r :
             {&mat.base_color_texture, &mat.emissive_texture, &mat.specular_color_texture,
              &mat.sheen_color_texture, &mat.diffuse_transmission_color_texture,
              &mat.specular_glossiness_texture})
            note(*r);
    }
    // The loader decodes an image once per encoding, so an image that a colour texture
    // uses holds colour only, even if a data texture shares the file. Texels stay as the
    // file has them (8-bit sRGB cannot hold another space's values): the lookup applies
    // the matrix after filtering, the same linear map as converting every texel.
    for (uint32_t index : colour_images)
        if (scene.images[index].channels() >= 3) scene.images[index].set_color_matrix(m);
    for (TriangleMesh& mesh : scene.meshes)
        for (Vec4& c : mesh.colors) c = Vec4(m * c.xyz(), c.w);
}

}  // namespace penumbra
