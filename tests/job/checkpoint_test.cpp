// Checkpoints: a film with every AOV, or with the denoising buffers, survives the round
// trip bit for bit; a checkpoint of other options (fingerprint), of another film layout,
// or damaged is refused and leaves the film untouched.
#include "job/checkpoint.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>

#include "support/gltf_builder.h"
#include "job/aov_list.h"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

const AovSet kAll = parse_aovs("albedo,normal,depth,position,variance,samples");

// Random samples (some NaN, some missing the scene) into every buffer.
Film random_film(AovSet aovs, uint32_t seed) {
    Film film(13, 7, aovs);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 2.0f);
    for (int i = 0; i < 400; ++i) {
        const int x = int(rng() % 13), y = int(rng() % 7);
        Spectrum L(u(rng), u(rng), u(rng));
        if (i % 97 == 0) L.x = std::numeric_limits<float>::quiet_NaN();
        AovRecord aov;
        aov.hit = i % 5 != 0;
        aov.albedo = {u(rng), u(rng), u(rng)};
        aov.normal = {u(rng) - 1, u(rng) - 1, u(rng) - 1};
        aov.position = {u(rng), u(rng), u(rng)};
        aov.depth = u(rng) * 10;
        aov.odd = i % 2 == 1;
        aov.guide = {aov.albedo, aov.normal, aov.depth};
        film.add_sample(x, y, L, u(rng), aov);
    }
    return film;
}

bool same_bits(const Image& a, const Image& b) {
    return a.pixels.size() == b.pixels.size() &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

void expect_same_film(const Film& a, const Film& b) {
    EXPECT_TRUE(same_bits(a.resolve(), b.resolve()));
    for (Aov aov :
         {Aov::Albedo, Aov::Normal, Aov::Depth, Aov::Position, Aov::Variance, Aov::Samples})
        EXPECT_TRUE(same_bits(a.resolve_aov(aov), b.resolve_aov(aov))) << int(aov);
    EXPECT_EQ(a.nonfinite_samples(), b.nonfinite_samples());
}

TEST(Checkpoint, RoundTripKeepsEveryBufferBitForBit) {
    const test::ScratchDir dir;
    const Film film = random_film(kAll, 1);
    ASSERT_GT(film.nonfinite_samples(), 0u);
    const std::string path = dir.file("a.exr.ckpt");
    write_checkpoint(path, film, {"fp", 5, 123456789012ull, 1.25});
    Film back(13, 7, kAll);
    std::string why;
    const auto state = read_checkpoint(path, "fp", back, &why);
    ASSERT_TRUE(state) << why;
    EXPECT_EQ(state->spp, 5u);
    EXPECT_EQ(state->rays, 123456789012ull);
    EXPECT_EQ(state->seconds, 1.25);
    expect_same_film(film, back);
    // The same buffer list (names and sizes) on both sides.
    const auto a = film.buffers(), b = back.buffers();
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_STREQ(a[i].name, b[i].name);
        EXPECT_EQ(a[i].bytes, b[i].bytes);
    }
}

TEST(Checkpoint, DenoisingBuffersSurviveTheRoundTrip) {
    const test::ScratchDir dir;
    const AovSet aovs = {Aov::Denoise};
    const Film film = random_film(aovs, 4);
    const std::string path = dir.file("d.exr.ckpt");
    write_checkpoint(path, film, {"fp", 2, 0, 0});
    Film back(13, 7, aovs);
    std::string why;
    ASSERT_TRUE(read_checkpoint(path, "fp", back, &why)) << why;
    const DenoiseInput a = film.denoise_input(), b = back.denoise_input();
    EXPECT_TRUE(same_bits(a.color_a, b.color_a));
    EXPECT_TRUE(same_bits(a.color_b, b.color_b));
    EXPECT_TRUE(same_bits(a.color_variance, b.color_variance));
    EXPECT_TRUE(same_bits(a.guide_a, b.guide_a));
    EXPECT_TRUE(same_bits(a.guide_b, b.guide_b));
    EXPECT_TRUE(same_bits(a.guide_variance, b.guide_variance));
    // A film without them does not take the checkpoint.
    Film plain(13, 7, kAll);
    EXPECT_FALSE(read_checkpoint(path, "fp", plain, &why));
}

TEST(Checkpoint, OtherFingerprintIsRefusedAndTheFilmUntouched) {
    const test::ScratchDir dir;
    const std::string path = dir.file("a.ckpt");
    write_checkpoint(path, random_film(kAll, 2), {"scene=a spp=16", 3, 0, 0});
    Film film = random_film(kAll, 3);
    const Film before = film;
    std::string why;
    EXPECT_FALSE(read_checkpoint(path, "scene=a spp=32", film, &why));
    EXPECT_NE(why.find("another scene or other options"), std::string::npos) << why;
    expect_same_film(before, film);
}

TEST(Checkpoint, OtherAovsOrSizeAreRefused) {
    const test::ScratchDir dir;
    const std::string path = dir.file("a.ckpt");
    write_checkpoint(path, random_film(kAll, 4), {"fp", 3, 0, 0});
    Film fewer(13, 7, parse_aovs("albedo"));
    std::string why;
    EXPECT_FALSE(read_checkpoint(path, "fp", fewer, &why));
    EXPECT_NE(why.find("does not match"), std::string::npos) << why;
    Film wider(14, 7, kAll);
    EXPECT_FALSE(read_checkpoint(path, "fp", wider, &why));
    EXPECT_NE(why.find("image size"), std::string::npos) << why;
}

TEST(Checkpoint, DamagedOrTruncatedFilesAreRefused) {
    const test::ScratchDir dir;
    const std::string path = dir.file("a.ckpt");
    write_checkpoint(path, random_film(kAll, 5), {"fp", 3, 0, 0});
    const auto size = fs::file_size(path);
    std::string bytes(size, '\0');
    std::ifstream(path, std::ios::binary).read(bytes.data(), std::streamsize(size));
    // One flipped bit in the middle of the accumulators, and a file cut short.
    std::string flipped = bytes;
    flipped[size / 2] ^= 0x10;
    std::ofstream(dir.file("flipped.ckpt"), std::ios::binary) << flipped;
    std::ofstream(dir.file("short.ckpt"), std::ios::binary) << bytes.substr(0, size - 100);
    for (const char* name : {"flipped.ckpt", "short.ckpt"}) {
        Film film(13, 7, kAll);
        std::string why;
        EXPECT_FALSE(read_checkpoint(dir.file(name), "fp", film, &why)) << name;
        EXPECT_NE(why.find("damaged"), std::string::npos) << why;
        EXPECT_EQ(film.resolve().pixels, Film(13, 7, kAll).resolve().pixels);
    }
    Film film(13, 7, kAll);
    std::string why;
    EXPECT_FALSE(read_checkpoint(dir.file("none.ckpt"), "fp", film, &why));
    EXPECT_EQ(why, "no checkpoint");
}

}  // namespace
}  // namespace penumbra
