// The denoiser's input through band files (io/image/denoise_layers.h): written as full-float
// layers beside a half beauty and assembled from two bands, it comes back bit for bit,
// values no half holds included.
#include "io/image/denoise_layers.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <random>

#include "job/band_merge.h"
#include "support/gltf_builder.h"

namespace penumbra {
namespace {

constexpr int kW = 7, kH = 5, kSplit = 2;  // band 0: rows [0, 2), band 1: [2, 5)

// Random floats over many magnitudes, signs and a few exact zeros.
Image random_image(int channels, std::mt19937& rng) {
    Image img(kW, kH, channels);
    std::uniform_real_distribution<float> mantissa(-1, 1);
    std::uniform_int_distribution<int> exponent(-30, 30);
    for (float& v : img.pixels)
        v = exponent(rng) == 0 ? 0.0f : std::ldexp(mantissa(rng), exponent(rng));
    return img;
}

DenoiseInput random_input(uint32_t seed) {
    std::mt19937 rng(seed);
    DenoiseInput in;
    in.color_a = random_image(3, rng);
    in.color_b = random_image(3, rng);
    in.color_variance = random_image(3, rng);
    in.guide_a = random_image(kGuideChannels, rng);
    in.guide_b = random_image(kGuideChannels, rng);
    in.guide_variance = random_image(kGuideChannels, rng);
    return in;
}

std::string write_band(const test::ScratchDir& dir, const std::string& name,
                       const DenoiseInput& input) {
    const Image rgba(kW, kH, 4);
    std::vector<ExrLayer> layers = {{"", {"R", "G", "B", "A"}, &rgba, false}};
    for (const ExrLayer& l : denoise_input_layers(input)) layers.push_back(l);
    write_exr(dir.file(name), layers, {}, {true, "zip"});
    return dir.file(name);
}

// a's rows [0, kSplit) and b's others, against got, bit for bit.
bool assembled(const Image& got, const Image& a, const Image& b) {
    const size_t split = size_t(kSplit) * kW * size_t(a.channels);
    return got.pixels.size() == a.pixels.size() &&
           std::memcmp(got.pixels.data(), a.pixels.data(), split * sizeof(float)) == 0 &&
           std::memcmp(got.pixels.data() + split, b.pixels.data() + split,
                       (got.pixels.size() - split) * sizeof(float)) == 0;
}

TEST(DenoiseLayers, TwoBandsGiveBackTheirRowsOfTheInputBitForBit) {
    const test::ScratchDir dir;
    const DenoiseInput a = random_input(1), b = random_input(2);
    const MergedImage merged(
        {{write_band(dir, "a.exr", a), 0, kSplit}, {write_band(dir, "b.exr", b), kSplit, kH}});
    const DenoiseInput got = read_denoise_input(
        [&](const std::vector<std::string>& names) { return merged.channels(names); });
    EXPECT_TRUE(assembled(got.color_a, a.color_a, b.color_a));
    EXPECT_TRUE(assembled(got.color_b, a.color_b, b.color_b));
    EXPECT_TRUE(assembled(got.color_variance, a.color_variance, b.color_variance));
    EXPECT_TRUE(assembled(got.guide_a, a.guide_a, b.guide_a));
    EXPECT_TRUE(assembled(got.guide_b, a.guide_b, b.guide_b));
    EXPECT_TRUE(assembled(got.guide_variance, a.guide_variance, b.guide_variance));
}

TEST(DenoiseLayers, LayersAreInternalAndFullFloat) {
    const test::ScratchDir dir;
    const std::string path = write_band(dir, "a.exr", random_input(3));
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    ASSERT_TRUE(in);
    int count = 0;
    for (int c = 0; c < in->spec().nchannels; ++c) {
        const std::string& name = in->spec().channelnames[size_t(c)];
        if (name.rfind(std::string(kDenoiseInputLayer) + ".", 0) != 0) continue;
        ++count;
        EXPECT_EQ(in->spec().channelformat(c), OIIO::TypeDesc::FLOAT) << name;
    }
    EXPECT_EQ(count, 3 * 3 + 3 * kGuideChannels);
    EXPECT_GE(in->spec().channelindex("DenoiseInput.GuideA.Visibility"), 0);
    EXPECT_GE(in->spec().channelindex("DenoiseInput.ColorVariance.B"), 0);
}

}  // namespace
}  // namespace penumbra
