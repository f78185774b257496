// Recognising glTF image formats by their bytes and reading the dimensions their headers
// claim: real PNG and JPEG files against OIIO's view of them, hand-made WebP headers,
// other formats refused, and sizes checked before any decoder runs.
#include "io/image/image_header.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "io/image/image_reader.h"
#include "support/gltf_builder.h"

namespace penumbra {
namespace {

using test::ScratchDir;

std::vector<uint8_t> bytes_of(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

// A w x h RGB image written by OIIO in the format of the file name's extension.
std::vector<uint8_t> encoded(const ScratchDir& dir, const std::string& name, int w, int h) {
    const std::string path = dir.file(name);
    auto out = OIIO::ImageOutput::create(path);
    EXPECT_TRUE(out && out->open(path, OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::UINT8)));
    const std::vector<uint8_t> px(size_t(w * h * 3), 128);
    out->write_image(OIIO::TypeDesc::UINT8, px.data());
    out->close();
    return bytes_of(path);
}

// RIFF "WEBP" around one chunk: `fourcc` followed by `payload`.
std::vector<uint8_t> webp(const char* fourcc, const std::vector<uint8_t>& payload) {
    std::vector<uint8_t> b = {'R', 'I', 'F', 'F', 0, 0, 0, 0, 'W', 'E', 'B', 'P'};
    b.insert(b.end(), fourcc, fourcc + 4);
    const uint32_t n = uint32_t(payload.size());
    for (int i = 0; i < 4; ++i) b.push_back(uint8_t(n >> (8 * i)));
    b.insert(b.end(), payload.begin(), payload.end());
    return b;
}

void set_be32(std::vector<uint8_t>& b, size_t at, uint32_t v) {
    for (int i = 0; i < 4; ++i) b[at + size_t(i)] = uint8_t(v >> (24 - 8 * i));
}

TEST(ImageHeader, PngAndJpegDimensionsAgreeWithTheDecoder) {
    ScratchDir dir;
    // Sizes with different width and height, and a JPEG wider than one MCU row (16 px).
    for (const auto& [w, h] : {std::pair{3, 2}, std::pair{37, 5}, std::pair{1, 300}}) {
        for (const char* ext : {"png", "jpg"}) {
            SCOPED_TRACE(std::string(ext) + " " + std::to_string(w) + "x" + std::to_string(h));
            const std::vector<uint8_t> b = encoded(dir, std::string("a.") + ext, w, h);
            const ImageHeader hd = read_image_header(b, false);
            EXPECT_EQ(hd.problem, "");
            EXPECT_EQ(hd.format, ext[0] == 'p' ? ImageFormat::Png : ImageFormat::Jpeg);
            EXPECT_EQ(hd.width, uint32_t(w));
            EXPECT_EQ(hd.height, uint32_t(h));
            const TextureImage img = decode_texture_image(b, "a", ImageEncoding::Linear, {});
            EXPECT_EQ(img.width(), w);
            EXPECT_EQ(img.height(), h);
        }
    }
}

TEST(ImageHeader, WebpHeadersOnlyWhenAllowed) {
    // VP8L: signature 0x2f, then 14 bits width - 1 and 14 bits height - 1.
    const uint32_t bits = (100 - 1) | (50 - 1) << 14;
    const std::vector<uint8_t> vp8l = webp("VP8L", {0x2f, uint8_t(bits), uint8_t(bits >> 8),
                                                    uint8_t(bits >> 16), uint8_t(bits >> 24)});
    ImageHeader h = read_image_header(vp8l, true);
    EXPECT_EQ(h.problem, "");
    EXPECT_EQ(h.format, ImageFormat::Webp);
    EXPECT_EQ(h.width, 100u);
    EXPECT_EQ(h.height, 50u);
    EXPECT_EQ(read_image_header(vp8l, false).problem, "not a PNG or JPEG image");
    // VP8X: flags, then 24-bit canvas width - 1 and height - 1.
    const std::vector<uint8_t> vp8x =
        webp("VP8X", {0, 0, 0, 0, 0x0f, 0x27, 0x00, 0xff, 0xff, 0xff});  // 10000 x 2^24
    h = read_image_header(vp8x, true);
    EXPECT_EQ(h.problem, "");
    EXPECT_EQ(h.width, 10000u);
    EXPECT_EQ(h.height, 1u << 24);
    // VP8 (lossy): frame tag, start code 9d 01 2a, 14-bit sizes.
    const std::vector<uint8_t> vp8 =
        webp("VP8 ", {0, 0, 0, 0x9d, 0x01, 0x2a, 0x80, 0x00, 0x40, 0xc0});  // 128 x 64
    h = read_image_header(vp8, true);
    EXPECT_EQ(h.problem, "");
    EXPECT_EQ(h.width, 128u);
    EXPECT_EQ(h.height, 64u);
    std::vector<uint8_t> bad = vp8;
    bad[23] = 0;  // not the start code
    EXPECT_EQ(read_image_header(bad, true).problem, "malformed WebP VP8 header");
    EXPECT_EQ(read_image_header(webp("ALPH", {0, 0, 0, 0}), true).problem,
              "truncated or unknown WebP header");
}

TEST(ImageHeader, OtherFormatsAndBrokenHeadersAreRefused) {
    ScratchDir dir;
    const auto text = [](const std::string& s) { return std::vector<uint8_t>(s.begin(), s.end()); };
    const std::vector<uint8_t> others[] = {
        text("GIF89a\x01\x00\x01\x00"),        // GIF
        text("\xABKTX 20\xBB\r\n\x1a\n"),      // KTX2
        text("<!DOCTYPE html><html></html>"),  // a web page
        text("BM\x3a\0\0\0"),                  // BMP
        encoded(dir, "a.exr", 2, 2),           // EXR, which OIIO would read
        {},
    };
    for (const auto& b : others) {
        const ImageHeader h = read_image_header(b, false);
        EXPECT_EQ(h.problem, "not a PNG or JPEG image");
        EXPECT_EQ(read_image_header(b, true).problem, "not a PNG, JPEG or WebP image");
        try {
            decode_texture_image(b, "x.gltf: images[3]", ImageEncoding::Srgb, {});
            ADD_FAILURE();
        } catch (const ImageDecodeError& e) {
            EXPECT_EQ(e.why(), b.empty() ? "no data" : "not a PNG or JPEG image");
            EXPECT_EQ(std::string(e.what()), "x.gltf: images[3]: cannot decode image: " + e.why());
        }
    }

    std::vector<uint8_t> png = encoded(dir, "a.png", 3, 2);
    EXPECT_EQ(read_image_header({png.begin(), png.begin() + 20}, false).problem,
              "truncated PNG header (no IHDR)");
    // Cut inside the image data, cut exactly at a chunk boundary (IEND missing), and with
    // trailing bytes after IEND (accepted, as libpng does).
    std::vector<uint8_t> cut(png.begin(), png.end() - 14);
    EXPECT_EQ(read_image_header(cut, false).problem,
              "truncated PNG (its IDAT chunk runs past the end of the data)");
    cut.assign(png.begin(), png.end() - 12);
    EXPECT_EQ(read_image_header(cut, false).problem, "truncated PNG (it ends before IEND)");
    std::vector<uint8_t> trailing = png;
    trailing.insert(trailing.end(), {1, 2, 3});
    EXPECT_EQ(read_image_header(trailing, false).problem, "");
    std::vector<uint8_t> cgbi = png;
    cgbi[12] = 'C';  // e.g. Apple's CgBI chunk first
    EXPECT_EQ(read_image_header(cgbi, false).problem,
              "malformed PNG header (the first chunk is not IHDR)");
    set_be32(png, 16, 0);
    EXPECT_EQ(read_image_header(png, false).problem, "header claims a 0x2 image");
    set_be32(png, 16, 0x80000000u);
    EXPECT_EQ(read_image_header(png, false).problem, "PNG header has a dimension above 2^31 - 1");

    std::vector<uint8_t> jpg = encoded(dir, "a.jpg", 3, 2);
    EXPECT_EQ(read_image_header({jpg.begin(), jpg.begin() + 4}, false).problem,
              "truncated JPEG header (no frame header)");
    // The SOF0 segment written by libjpeg: FF C0, length, precision, height, width.
    size_t sof = 2;
    while (sof + 1 < jpg.size() && !(jpg[sof] == 0xFF && jpg[sof + 1] == 0xC0)) ++sof;
    ASSERT_LT(sof + 9, jpg.size());
    jpg[sof + 5] = jpg[sof + 6] = 0;  // height 0: defined later by a DNL marker
    EXPECT_EQ(read_image_header(jpg, false).problem, "header claims a 3x0 image");
}

// The limit applies to the header's claim, before the decoder allocates: a PNG claiming
// 65536 x 65536 pixels whose data is cut off after the IHDR is refused for its size, not
// for its missing data; and the limit is inclusive, to the pixel.
TEST(ImageHeader, SizeLimitBeforeDecoding) {
    ScratchDir dir;
    std::vector<uint8_t> png = encoded(dir, "a.png", 3, 2);
    TextureDecodeLimits limits;
    limits.max_pixels = 6;
    EXPECT_EQ(decode_texture_image(png, "a", ImageEncoding::Linear, limits).width(), 3);
    limits.max_pixels = 5;
    try {
        decode_texture_image(png, "a", ImageEncoding::Linear, limits);
        ADD_FAILURE();
    } catch (const ImageDecodeError& e) {
        EXPECT_EQ(e.why(), "3x2 is more than the limit of 5 pixels (--max-texture-pixels)");
    }
    std::vector<uint8_t> huge(png.begin(), png.begin() + 33);
    set_be32(huge, 16, 65536);
    set_be32(huge, 20, 65536);
    try {
        decode_texture_image(huge, "a", ImageEncoding::Linear, {});
        ADD_FAILURE();
    } catch (const ImageDecodeError& e) {
        EXPECT_EQ(e.why(),
                  "65536x65536 is more than the limit of 268435456 pixels (--max-texture-pixels)");
    }
}

}  // namespace
}  // namespace penumbra
