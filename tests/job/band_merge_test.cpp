// Assembling an image from band files in memory (job/band_merge.h): each band's rows come
// from its own file, every channel in its own format, and the edits before the write
// (overwrite, insert in another channel's format, leave out by prefix) keep every other
// channel's bits.
#include "job/band_merge.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstring>
#include <memory>

#include "core/error.h"
#include "io/image/image_writer.h"
#include "support/exr_pixels.h"
#include "support/gltf_builder.h"

namespace penumbra {
namespace {

constexpr int kW = 5, kH = 6;

// Values exact in half, different for every band, pixel and channel.
Image pattern(int channels, int band) {
    Image img(kW, kH, channels);
    for (size_t i = 0; i < img.pixels.size(); ++i)
        img.pixels[i] = float(band * 64) + float(i % 61) * 0.5f;
    return img;
}

// A band file: RGBA in half, "Depth.Z" and "Extra.X/Y" in float.
std::string write_band(const test::ScratchDir& dir, const std::string& name, int band) {
    const Image rgba = pattern(4, band), depth = pattern(1, band + 10),
                extra = pattern(2, band + 20);
    const std::string path = dir.file(name);
    write_exr(path,
              {{"", {"R", "G", "B", "A"}, &rgba, false},
               {"Depth", {"Z"}, &depth, true},
               {"Extra", {"X", "Y"}, &extra, true}},
              {{"penumbra:spp", std::string("4")}}, {true, "zip"});
    return path;
}

OIIO::TypeDesc format_of(const std::string& path, const std::string& channel) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) return OIIO::TypeDesc::UNKNOWN;
    const int i = in->spec().channelindex(channel);
    return i < 0 ? OIIO::TypeDesc::UNKNOWN : in->spec().channelformat(i);
}

bool same_bits(const Image& a, const Image& b) {
    return a.pixels.size() == b.pixels.size() &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

TEST(BandMerge, EachBandsRowsComeFromItsFile) {
    const test::ScratchDir dir;
    const std::string a = write_band(dir, "a.exr", 1), b = write_band(dir, "b.exr", 2);
    const MergedImage merged({{a, 0, 2}, {b, 2, kH}});
    EXPECT_EQ(merged.width(), kW);
    EXPECT_EQ(merged.height(), kH);
    const Image got = merged.channels({"Depth.Z", "G"});
    const Image depth_a = pattern(1, 11), depth_b = pattern(1, 12);
    const Image rgba_a = pattern(4, 1), rgba_b = pattern(4, 2);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const bool first = y < 2;
            EXPECT_EQ(got.at(x, y)[0], (first ? depth_a : depth_b).at(x, y)[0]) << x << "," << y;
            EXPECT_EQ(got.at(x, y)[1], (first ? rgba_a : rgba_b).at(x, y)[1]) << x << "," << y;
        }
    EXPECT_THROW(merged.channels({"Nope.X"}), SceneError);
    // Written unedited, the formats are the bands'.
    merged.write(dir.file("out.exr"));
    EXPECT_EQ(format_of(dir.file("out.exr"), "R"), OIIO::TypeDesc::HALF);
    EXPECT_EQ(format_of(dir.file("out.exr"), "Depth.Z"), OIIO::TypeDesc::FLOAT);
}

TEST(BandMerge, EditsKeepTheOtherChannelsBits) {
    const test::ScratchDir dir;
    const std::string a = write_band(dir, "a.exr", 1);
    MergedImage merged({{a, 0, kH}});
    const Image before = merged.channels({"R", "G", "B", "A", "Depth.Z"});
    const Image noisy = pattern(3, 5), red = pattern(1, 7);
    merged.insert_channels("A", {"Noisy.R", "Noisy.G", "Noisy.B"}, "R", noisy);
    merged.remove_channels("Extra.");
    merged.set_channels({"R"}, red);
    merged.write(dir.file("out.exr"), {{"penumbra:note", "merged"}});

    const test::Pixels p = test::read_pixels(dir.file("out.exr"));
    ASSERT_TRUE(p.error.empty()) << p.error;
    EXPECT_EQ(p.channels.size(), 8u);  // R G B A, Noisy.R/G/B, Depth.Z
    const MergedImage back({{dir.file("out.exr"), 0, kH}});
    EXPECT_TRUE(same_bits(back.channels({"Noisy.R", "Noisy.G", "Noisy.B"}), noisy));
    EXPECT_TRUE(same_bits(back.channels({"R"}), red));
    Image kept = before;  // all but R
    const Image now = back.channels({"R", "G", "B", "A", "Depth.Z"});
    for (size_t i = 0; i < kept.pixels.size(); i += 5) kept.pixels[i] = now.pixels[i];
    EXPECT_TRUE(same_bits(now, kept));
    EXPECT_THROW(back.channels({"Extra.X"}), SceneError);
    EXPECT_EQ(format_of(dir.file("out.exr"), "Noisy.G"), OIIO::TypeDesc::HALF);
    EXPECT_EQ(format_of(dir.file("out.exr"), "Depth.Z"), OIIO::TypeDesc::FLOAT);
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(dir.file("out.exr"));
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().get_string_attribute("penumbra:note"), "merged");
    EXPECT_EQ(in->spec().get_string_attribute("penumbra:spp"), "4");
    EXPECT_EQ(in->spec().alpha_channel, 3);
}

TEST(BandMerge, LeavingOutEveryFloatChannelLeavesAHalfFile) {
    const test::ScratchDir dir;
    MergedImage merged({{write_band(dir, "a.exr", 1), 0, kH}});
    merged.remove_channels("Extra.");
    merged.remove_channels("Depth.");
    merged.write(dir.file("out.exr"));
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(dir.file("out.exr"));
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().nchannels, 4);
    EXPECT_EQ(in->spec().format, OIIO::TypeDesc::HALF);
    EXPECT_TRUE(in->spec().channelformats.empty());
}

}  // namespace
}  // namespace penumbra
