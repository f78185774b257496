// The scene's media: a homogeneous medium inside every material with KHR_materials_volume
// (thicknessFactor > 0), none for thin-walled ones or the default material; and the same
// from a real file through the loader (AttenuationTest, read in place from ../shared).
#include "core/media/medium_set.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/media/homogeneous_medium.h"
#include "io/gltf/gltf_loader.h"
#include "support/paths.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

Spectrum sigma_of(const MediumSet& media, int material) {
    const auto* m = dynamic_cast<const HomogeneousMedium*>(media.interior(material));
    return m ? m->sigma_a() : Spectrum(-1);
}

TEST(MediumSet, OneMediumPerVolumeMaterial) {
    Scene scene;
    MaterialDesc thin;
    thin.transmission = 1;
    thin.attenuation_color = {0.5f, 0.5f, 0.5f};
    thin.attenuation_distance = 1;  // ignored without a volume
    MaterialDesc clear = thin;
    clear.thickness = 0.01f;
    clear.attenuation_distance = INFINITY;
    MaterialDesc tinted = clear;
    tinted.attenuation_color = {0.25f, 0.5f, 1};
    tinted.attenuation_distance = 2;
    scene.materials = {thin, clear, tinted};
    const MediumSet media(scene);
    EXPECT_FALSE(media.has_volume(-1));
    EXPECT_FALSE(media.has_volume(0));
    EXPECT_EQ(media.interior(0), nullptr);
    ASSERT_TRUE(media.has_volume(1));
    EXPECT_TRUE(media.interior(1)->is_clear());
    const Spectrum s = sigma_of(media, 2);
    EXPECT_NEAR(s.x, std::log(4.0f) / 2, 1e-6f);
    EXPECT_NEAR(s.y, std::log(2.0f) / 2, 1e-6f);
    EXPECT_EQ(s.z, 0.0f);
    EXPECT_FALSE(media.has_volume(3));  // past the end
}

TEST(MediumSet, PointsClearlyOutsideAVolumeInstanceAreOutside) {
    // A unit cube of a volume material scaled to [-1, 1]^3 and one of a thin material:
    // only points beyond the volume's bounds (plus a margin of about 1e-4) are outside,
    // and instances without a volume are never ruled out.
    Scene scene;
    MaterialDesc thin, volume;
    volume.thickness = 1;
    scene.materials = {thin, volume};
    const uint32_t inside = test::add_instance(scene, test::add_cube_object(scene, 1),
                                               Transform::scale(Vec3(2)));
    const uint32_t sheet = test::add_instance(scene, test::add_cube_object(scene, 0),
                                              Transform::scale(Vec3(2)));
    const MediumSet media(scene);
    EXPECT_FALSE(media.surely_outside(int(inside), {0, 0, 0}));
    EXPECT_FALSE(media.surely_outside(int(inside), {-1, 1, 1}));
    EXPECT_FALSE(media.surely_outside(int(inside), {-1, 1.00000012f, 1}));  // rounding
    EXPECT_TRUE(media.surely_outside(int(inside), {-1, 1.001f, 1}));
    EXPECT_TRUE(media.surely_outside(int(inside), {20, 4, -1}));
    EXPECT_FALSE(media.surely_outside(int(sheet), {20, 4, -1}));
    EXPECT_FALSE(media.surely_outside(-1, {20, 4, -1}));
}

TEST(MediumSet, AttenuationTestFileGetsItsMedia) {
    const Scene scene = load_gltf(test::shared_path("scenes/wild/AttenuationTest/AttenuationTest.glb"));
    const MediumSet media(scene);
    int volumes = 0;
    for (int i = 0; i < int(scene.materials.size()); ++i) {
        const MaterialDesc& m = scene.materials[i];
        EXPECT_EQ(media.has_volume(i), m.thickness > 0) << m.name;
        if (!media.has_volume(i)) continue;
        ++volumes;
        // attenuationColor (0.1, 0.5, 0.9) at the material's attenuationDistance.
        const Spectrum s = sigma_of(media, i);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(std::exp(-s[c] * m.attenuation_distance), m.attenuation_color[c], 1e-5f)
                << m.name;
        }
        if (m.name == "R5_Attenuation_2.0") {
            EXPECT_NEAR(m.attenuation_distance, 0.5f, 1e-6f);
            EXPECT_NEAR(s.x, -std::log(m.attenuation_color.x) / 0.5f, 1e-4f);
        }
    }
    EXPECT_GE(volumes, 10);
}

}  // namespace
}  // namespace penumbra
