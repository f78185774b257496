// The film's alpha under a transparent background (the mean of the samples' coverage,
// with the colour's weights, so the colour is premultiplied by it), the ID layers (the
// IDs of the sample nearest the pixel's centre, never averaged) and the checkpoint
// buffers both add.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "core/film/film.h"
#include "job/aov_list.h"

namespace penumbra {
namespace {

AovRecord covered(float coverage, bool odd = false) {
    AovRecord r;
    r.coverage = coverage;
    r.odd = odd;
    return r;
}

AovRecord ids(int32_t object, int32_t material, float offset2) {
    AovRecord r;
    r.hit = object != kNoHitId;
    r.object = object;
    r.material = material;
    r.offset2 = offset2;
    return r;
}

TEST(FilmCoverage, AlphaIsOneWithoutCoverage) {
    Film film(1, 1, parse_aovs("depth"));
    film.add_sample(0, 0, {0.5f, 0.5f, 0.5f}, 1, covered(0));
    EXPECT_EQ(film.resolve().at(0, 0)[3], 1.0f);
}

TEST(FilmCoverage, AlphaIsTheWeightedMeanOfTheSamplesCoverage) {
    Film film(3, 1, AovSet{Aov::Coverage});
    // Pixel 0: a hit of colour 0.8 (weight 1), a miss (colour 0, weight 3).
    film.add_sample(0, 0, Spectrum(0.8f), 1, covered(1));
    film.add_sample(0, 0, Spectrum(0), 3, covered(0));
    // Pixel 1: a partly covered sample, and a non-finite one the colour drops, so alpha
    // drops it too.
    film.add_sample(1, 0, Spectrum(0.2f), 1, covered(0.4f));
    film.add_sample(1, 0, Spectrum(std::numeric_limits<float>::quiet_NaN()), 1, covered(1));
    const Image img = film.resolve();
    EXPECT_FLOAT_EQ(img.at(0, 0)[3], 0.25f);
    // Premultiplied: colour / alpha is the covering sample's colour.
    EXPECT_FLOAT_EQ(img.at(0, 0)[0] / img.at(0, 0)[3], 0.8f);
    EXPECT_FLOAT_EQ(img.at(1, 0)[3], 0.4f);
    EXPECT_FLOAT_EQ(img.at(1, 0)[0] / img.at(1, 0)[3], 0.5f);
    // Pixel 2 has no samples: nothing covers it.
    EXPECT_EQ(img.at(2, 0)[3], 0.0f);
    EXPECT_EQ(img.at(2, 0)[0], 0.0f);
}

TEST(FilmCoverage, AlphaJoinsTheAdaptiveErrorEstimate) {
    // Both pixels' colour halves agree exactly (a black object), their alpha halves do not
    // in pixel 0: only alpha can say that pixel 0 is noisy.
    Film film(2, 1, AovSet{Aov::Coverage, Aov::Error});
    film.add_sample(0, 0, Spectrum(0), 1, covered(1, false));
    film.add_sample(0, 0, Spectrum(0), 1, covered(0, true));
    film.add_sample(1, 0, Spectrum(0), 1, covered(1, false));
    film.add_sample(1, 0, Spectrum(0), 1, covered(1, true));
    // Halves 1 and 0: variance (1 - 0)^2 * 1 * 1 / 4 = 0.25 over mean 0.5: the fourth
    // channel of sqrt(mean of var / (mean^2 + 0.01)).
    EXPECT_NEAR(film.relative_error(0, 0), std::sqrt(0.25 / (0.25 + 0.01) / 4), 1e-6);
    EXPECT_EQ(film.relative_error(1, 0), 0.0f);
    // Without coverage the same colour says nothing is noisy.
    Film plain(1, 1, AovSet{Aov::Error});
    plain.add_sample(0, 0, Spectrum(0), 1, covered(1, false));
    plain.add_sample(0, 0, Spectrum(0), 1, covered(0, true));
    EXPECT_EQ(plain.relative_error(0, 0), 0.0f);
}

TEST(FilmIds, TheSampleNearestTheCentreDecides) {
    Film film(3, 1, parse_aovs("object_id,material_id"));
    EXPECT_TRUE(parse_aovs("object_id").needs_first_hit());
    EXPECT_TRUE(parse_aovs("all").has(Aov::ObjectId));
    EXPECT_TRUE(parse_aovs("all").has(Aov::MaterialId));
    // Pixel 0: the second sample is nearest; a later, equally near one does not replace it.
    film.add_sample(0, 0, Spectrum(1), 1, ids(4, 2, 0.20f));
    film.add_sample(0, 0, Spectrum(1), 1, ids(7, 5, 0.01f));
    film.add_sample(0, 0, Spectrum(1), 1, ids(9, 9, 0.01f));
    film.add_sample(0, 0, Spectrum(1), 1, ids(3, 3, 0.30f));
    // Pixel 1: the nearest sample missed, the default material elsewhere.
    film.add_sample(1, 0, Spectrum(1), 1, ids(4, kDefaultMaterialId, 0.5f));
    film.add_sample(1, 0, Spectrum(1), 1, ids(kNoHitId, kNoHitId, 0.1f));
    film.add_sample(2, 0, Spectrum(1), 1, ids(6, kDefaultMaterialId, 0.5f));
    const Image object = film.resolve_aov(Aov::ObjectId),
                material = film.resolve_aov(Aov::MaterialId);
    ASSERT_EQ(object.channels, 1);
    EXPECT_EQ(object.at(0, 0)[0], 7.0f);
    EXPECT_EQ(material.at(0, 0)[0], 5.0f);
    EXPECT_EQ(object.at(1, 0)[0], -1.0f);
    EXPECT_EQ(material.at(1, 0)[0], -1.0f);
    EXPECT_EQ(object.at(2, 0)[0], 6.0f);
    EXPECT_EQ(material.at(2, 0)[0], -2.0f);
}

TEST(FilmIds, APixelWithoutSamplesIsAMiss) {
    const Film film(1, 1, parse_aovs("object_id"));
    EXPECT_EQ(film.resolve_aov(Aov::ObjectId).at(0, 0)[0], float(kNoHitId));
}

TEST(FilmCoverage, CheckpointBuffersHoldCoverageAndIds) {
    Film film(2, 1, AovSet{Aov::Coverage, Aov::ObjectId, Aov::Error});
    film.add_sample(0, 0, Spectrum(1), 1, covered(0.5f, true));
    film.add_sample(1, 0, Spectrum(1), 1, ids(3, 1, 0.2f));
    Film copy(2, 1, AovSet{Aov::Coverage, Aov::ObjectId, Aov::Error});
    const std::vector<Film::Buffer> from = film.buffers();
    std::vector<Film::Buffer> to = copy.buffers();
    ASSERT_EQ(from.size(), to.size());
    bool coverage = false, id = false;
    for (size_t i = 0; i < from.size(); ++i) {
        ASSERT_EQ(from[i].bytes, to[i].bytes) << from[i].name;
        if (from[i].bytes) std::memcpy(to[i].data, from[i].data, from[i].bytes);
        coverage |= std::string(from[i].name) == "coverage" && from[i].bytes > 0;
        id |= std::string(from[i].name) == "ids" && from[i].bytes > 0;
    }
    EXPECT_TRUE(coverage);
    EXPECT_TRUE(id);
    EXPECT_EQ(copy.resolve().pixels, film.resolve().pixels);
    EXPECT_EQ(copy.resolve_aov(Aov::ObjectId).pixels, film.resolve_aov(Aov::ObjectId).pixels);
    EXPECT_EQ(copy.relative_error(0, 0), film.relative_error(0, 0));
}

}  // namespace
}  // namespace penumbra
