// Homogeneous absorption: KHR_materials_volume's attenuation colour is what is left at
// attenuation distance, Beer-Lambert in between and beyond, and the edge cases (infinite
// distance, colour 0 or 1, zero or infinite path length) stay finite.
#include "core/media/homogeneous_medium.h"

#include <gtest/gtest.h>

#include <cmath>

namespace penumbra {
namespace {

const Ray kRay{{0, 0, 0}, {0, 0, 1}};

TEST(HomogeneousMedium, AttenuationColourIsReachedAtAttenuationDistance) {
    const Spectrum color(0.8f, 0.5f, 0.05f);
    for (float d : {0.01f, 0.7f, 3.0f, 250.0f}) {
        const HomogeneousMedium m(HomogeneousMedium::sigma_a_from_attenuation(color, d));
        const Spectrum at_d = m.transmittance(kRay, d);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(at_d[c], color[c], 2e-6f * color[c] + 1e-7f) << "d " << d;
            // Beer-Lambert: twice the distance is the colour squared, half its root.
            EXPECT_NEAR(m.transmittance(kRay, 2 * d)[c], color[c] * color[c], 2e-6f);
            EXPECT_NEAR(m.transmittance(kRay, 0.5f * d)[c], std::sqrt(color[c]), 2e-6f);
        }
        const MediumSample s = m.sample(kRay, 1.5f * d, 0.3f);
        EXPECT_FALSE(s.scattered);
        EXPECT_EQ(s.t, 1.5f * d);
        EXPECT_EQ(s.weight, m.transmittance(kRay, 1.5f * d));
    }
}

TEST(HomogeneousMedium, EdgeCasesStayFinite) {
    const float inf = std::numeric_limits<float>::infinity();
    // The spec's default distance (infinity) and colour 1 are clear.
    EXPECT_EQ(HomogeneousMedium::sigma_a_from_attenuation({0.5f, 0.5f, 0.5f}, inf), Spectrum(0));
    EXPECT_TRUE(HomogeneousMedium(HomogeneousMedium::sigma_a_from_attenuation(Spectrum(1), 2))
                    .is_clear());
    // Colours above 1 would amplify light: clamped to clear.
    EXPECT_EQ(HomogeneousMedium::sigma_a_from_attenuation({1.5f, 1, 1}, 1), Spectrum(0));
    // Colour 0 is opaque, but a zero-length segment still transmits everything.
    const HomogeneousMedium black(HomogeneousMedium::sigma_a_from_attenuation({0, 1, 0.5f}, 1));
    EXPECT_EQ(black.transmittance(kRay, 0), Spectrum(1));
    const Spectrum t = black.transmittance(kRay, 1e-3f);
    EXPECT_EQ(t.x, 0.0f);
    EXPECT_EQ(t.y, 1.0f);
    // An escaping ray: non-absorbing channels keep everything, the others nothing.
    const Spectrum far = black.transmittance(kRay, inf);
    EXPECT_EQ(far, Spectrum(0, 1, 0));
}

}  // namespace
}  // namespace penumbra
