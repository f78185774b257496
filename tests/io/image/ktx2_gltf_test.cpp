// KHR_texture_basisu end to end: glTFast's TextureVariants-Embedded-KTX.gltf (the extension
// required, a UASTC + Zstandard KTX2 image in a bufferView, no PNG fallback) loads with its
// one image decoded once, its 3 mip levels from the file, used by both textures.
#include <gtest/gtest.h>

#include "io/gltf_loader.h"
#include "support/paths.h"

namespace penumbra {
namespace {

TEST(Ktx2Gltf, TextureVariantsEmbeddedKtxLoads) {
    const Scene s = load_gltf(test::shared_path("scenes/ktx2/TextureVariants-Embedded-KTX.gltf"));
    ASSERT_EQ(s.images.size(), 1u);
    const TextureImage& img = s.images[0];
    EXPECT_EQ(img.width(), 4);
    EXPECT_EQ(img.height(), 4);
    EXPECT_EQ(img.levels(), 3);
    EXPECT_EQ(img.channels(), 3);
    EXPECT_TRUE(img.srgb());
    ASSERT_EQ(s.materials.size(), 2u);
    for (const auto& m : s.materials) {
        ASSERT_TRUE(m.base_color_texture.valid());
        EXPECT_EQ(s.textures.at(size_t(m.base_color_texture.texture)).image, 0u);
    }
}

}  // namespace
}  // namespace penumbra
