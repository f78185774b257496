// The files of a transparent-background render: the PNG preview carries the alpha with
// straight colour (PNG's convention) only where some alpha is below 1 and the format has
// alpha, and a denoised beauty keeps the film's alpha and stays black where it is 0.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "io/color/color.h"
#include "io/image/image_writer.h"
#include "io/image/render_writer.h"
#include "support/gltf_builder.h"

namespace penumbra {
namespace {

struct Read {
    int channels = 0;
    std::vector<unsigned char> bytes;
};

Read read_8bit(const std::string& path) {
    // The file's own bytes: OIIO would premultiply PNG colour by alpha while reading.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path, &config);
    EXPECT_TRUE(in) << OIIO::geterror();
    Read r;
    if (!in) return r;
    r.channels = in->spec().nchannels;
    r.bytes.resize(size_t(in->spec().width) * in->spec().height * r.channels);
    EXPECT_TRUE(in->read_image(0, 0, 0, r.channels, OIIO::TypeDesc::UINT8, r.bytes.data()));
    return r;
}

TEST(TransparentOutput, PreviewCarriesStraightAlpha) {
    const test::ScratchDir dir;
    Image img(2, 1, 4);
    // A half-covered pixel of premultiplied 0.1 (the surface's own 0.2), and an empty one.
    const float px[] = {0.1f, 0.1f, 0.1f, 0.5f, 0, 0, 0, 0};
    img.pixels.assign(px, px + 8);
    write_preview(dir.file("a.png"), img);
    // The opaque preview of the surface's own colour, for comparison.
    Image own(1, 1, 4);
    own.pixels = {0.2f, 0.2f, 0.2f, 1};
    write_preview(dir.file("own.png"), own);
    const Read a = read_8bit(dir.file("a.png")), o = read_8bit(dir.file("own.png"));
    ASSERT_EQ(a.channels, 4);
    ASSERT_EQ(o.channels, 3);
    EXPECT_EQ(a.bytes[0], o.bytes[0]);
    EXPECT_NE(a.bytes[0], 0);
    EXPECT_EQ(a.bytes[3], 128);
    EXPECT_EQ(a.bytes[4], 0);
    EXPECT_EQ(a.bytes[7], 0);
    // JPEG has no alpha: the premultiplied colour, over black.
    write_preview(dir.file("a.jpg"), img);
    EXPECT_EQ(read_8bit(dir.file("a.jpg")).channels, 3);
    // Alpha 1 everywhere: an RGB preview, as before transparent backgrounds.
    img.pixels[3] = img.pixels[7] = 1;
    write_preview(dir.file("b.png"), img);
    const Read b = read_8bit(dir.file("b.png"));
    ASSERT_EQ(b.channels, 3);
    EXPECT_LT(b.bytes[0], a.bytes[0]);  // 0.1, not divided by an alpha of 1
}

TEST(TransparentOutput, DenoisedBeautyKeepsAlphaAndEmptyPixels) {
    Image rgb(3, 1, 3), film(3, 1, 4);
    rgb.pixels = {0.3f, 0.3f, 0.3f, 0.2f, 0.2f, 0.2f, 0.05f, 0.05f, 0.05f};
    film.pixels = {9, 9, 9, 1, 9, 9, 9, 0.5f, 9, 9, 9, 0};
    DenoisedBeauty d;
    d.color = &rgb;
    const Beauty b = denoised_beauty(d, film, 0, ColorPipeline::builtin());
    const std::vector<float> expected = {0.3f, 0.3f, 0.3f, 1, 0.2f, 0.2f, 0.2f, 0.5f, 0, 0, 0, 0};
    EXPECT_EQ(b.working.pixels, expected);
}

}  // namespace
}  // namespace penumbra
