// Cryptomatte: MurmurHash3_x86_32 against the specification's manifest example and the
// reference implementation's values, the float conversion that keeps IDs finite and
// normal, the manifest and header keys, and a pixel's ranked coverage in the film.
#include "core/film/cryptomatte.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "core/film/film.h"
#include "job/aov_list.h"

namespace penumbra {
namespace {

uint32_t bits(float f) {
    uint32_t u;
    std::memcpy(&u, &f, 4);
    return u;
}

TEST(Cryptomatte, HashesAsTheSpecificationAndMurmurHash3) {
    // The specification's manifest example, and MurmurHash3_x86_32 (seed 0) test values.
    EXPECT_EQ(cryptomatte_hash("bunny"), 0x13851a76u);
    EXPECT_EQ(cryptomatte_hash("default"), 0x42c9679fu);
    EXPECT_EQ(cryptomatte_hash(""), 0u);
    EXPECT_EQ(cryptomatte_hash("a"), 0x3c2569b2u);
    EXPECT_EQ(cryptomatte_hash("abc"), 0xb3dd93fau);
    EXPECT_EQ(cryptomatte_hash("abcd"), 0x43ed676au);
}

TEST(Cryptomatte, IdsAreNormalFiniteFloats) {
    EXPECT_EQ(bits(cryptomatte_float(0x42c9679f)), 0x42c9679fu);  // exponent 133: kept
    // Exponent 0 (a denormal) and 255 (Inf or NaN): bit 23 flipped.
    EXPECT_EQ(bits(cryptomatte_float(0x00001234)), 0x00801234u);
    EXPECT_EQ(bits(cryptomatte_float(0x7f812345)), 0x7f012345u);
    for (uint32_t h : {0u, 0x7f800000u, 0xff800001u, 0x80000000u, 0x13851a76u}) {
        const float f = cryptomatte_float(h);
        EXPECT_TRUE(std::isfinite(f)) << h;
        EXPECT_TRUE(std::isnormal(f)) << h;
    }
}

TEST(Cryptomatte, ManifestAndHeaderKeys) {
    // In order, each name once, as JSON strings (escaped).
    EXPECT_EQ(cryptomatte_manifest({"bunny", "default", "bunny"}),
              "{\"bunny\":\"13851a76\",\"default\":\"42c9679f\"}");
    EXPECT_EQ(cryptomatte_manifest({"a\"b"}).rfind("{\"a\\\"b\":\"", 0), 0u);
    // The key is the first 7 hex digits of the layer name's hash (Blender's rule).
    EXPECT_EQ(cryptomatte_key("CryptoObject", "name"), "cryptomatte/3ae39a5/name");
    const auto header = cryptomatte_header("CryptoObject", {"bunny"});
    ASSERT_EQ(header.size(), 4u);
    EXPECT_EQ(header[0].second, "CryptoObject");
    EXPECT_EQ(header[1].second, "MurmurHash3_32");
    EXPECT_EQ(header[2].second, "uint32_to_float32");
    EXPECT_EQ(header[3].first, "cryptomatte/3ae39a5/manifest");
    EXPECT_EQ(header[3].second, "{\"bunny\":\"13851a76\"}");
}

AovRecord hit_of(uint32_t object, uint32_t material) {
    AovRecord r;
    r.hit = true;
    r.object_hash = object;
    r.material_hash = material;
    return r;
}

TEST(Cryptomatte, FilmRanksEachPixelsIdsByCoverage) {
    EXPECT_FALSE(parse_aovs("all").has(Aov::CryptoObject));
    const AovSet both = parse_aovs("cryptomatte");
    ASSERT_TRUE(both.has(Aov::CryptoObject) && both.has(Aov::CryptoMaterial));
    Film film(2, 1, both);
    // Pixel 0: object 7 weight 3, object 5 weight 4, a miss weight 1, and a non-finite
    // sample that the colour drops (and so the coverage).
    film.add_sample(0, 0, Spectrum(1), 1, hit_of(7, 1));
    film.add_sample(0, 0, Spectrum(1), 4, hit_of(5, 1));
    film.add_sample(0, 0, Spectrum(1), 2, hit_of(7, 2));
    film.add_sample(0, 0, Spectrum(0), 1, AovRecord{});
    film.add_sample(0, 0, Spectrum(std::numeric_limits<float>::quiet_NaN()), 9, hit_of(9, 9));
    const Image objects = film.resolve_aov(Aov::CryptoObject),
                materials = film.resolve_aov(Aov::CryptoMaterial);
    ASSERT_EQ(objects.channels, 2 * kCryptomatteRanks);
    const float* o = objects.at(0, 0);
    EXPECT_EQ(bits(o[0]), bits(cryptomatte_float(5)));
    EXPECT_FLOAT_EQ(o[1], 0.5f);
    EXPECT_EQ(bits(o[2]), bits(cryptomatte_float(7)));
    EXPECT_FLOAT_EQ(o[3], 0.375f);
    for (int c = 4; c < 2 * kCryptomatteRanks; ++c) EXPECT_EQ(o[c], 0.0f) << c;
    // Materials: 1 has weight 5 of 8, 2 has 2 of 8.
    EXPECT_EQ(bits(materials.at(0, 0)[0]), bits(cryptomatte_float(1)));
    EXPECT_FLOAT_EQ(materials.at(0, 0)[1], 0.625f);
    EXPECT_FLOAT_EQ(materials.at(0, 0)[3], 0.25f);
    // Pixel 1: no samples, no IDs.
    for (int c = 0; c < 2 * kCryptomatteRanks; ++c) EXPECT_EQ(objects.at(1, 0)[c], 0.0f);
}

}  // namespace
}  // namespace penumbra
