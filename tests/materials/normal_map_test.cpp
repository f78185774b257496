// Normal-mapped shading normals the viewer can see (materials/normal_map.h): the bent
// normal faces wo, mirrors it above the surface, stays in the plane of the mapped and
// unmapped normals, and is the mapped one wherever that is already valid.
#include "materials/normal_map.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/sampling/rng.h"
#include "materials/material.h"
#include "support/bsdf/bsdf_properties.h"

namespace penumbra {
namespace {

constexpr Vec3 kUp(0, 0, 1);

Vec3 mirror(Vec3 wo, Vec3 n) { return n * (2 * dot(n, wo)) - wo; }

TEST(ValidReflectionNormal, MirrorsEveryViewAboveTheSurfaceAndBendsNoFurtherThanNeeded) {
    Rng rng(42);
    int bent = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 wo = test::random_direction(rng), n = test::random_direction(rng);
        if (!(wo.z > 1e-3f) || !(n.z > 0)) continue;
        const Vec3 b = valid_reflection_normal(kUp, wo, n);
        const float threshold = std::min(0.9f * wo.z, 0.01f);
        EXPECT_NEAR(length(b), 1, 1e-5f);
        EXPECT_GT(dot(b, wo), 0) << i;
        EXPECT_GE(mirror(wo, b).z, threshold - 2e-4f) << i;
        if (mirror(wo, n).z >= threshold) {
            EXPECT_EQ(b, n) << i;  // valid already: untouched
            continue;
        }
        ++bent;
        // Turned towards the unmapped normal within the plane of the two...
        EXPECT_NEAR(dot(b, normalize(cross(n, kUp))), 0, 1e-4f) << i;
        EXPECT_GE(b.z, n.z - 1e-6f) << i;
        // ...only as far as the threshold: the mirror direction grazes it.
        EXPECT_NEAR(mirror(wo, b).z, threshold, 2e-4f) << i;
    }
    EXPECT_GT(bent, 1000);  // the random normals reach the case often
}

TEST(ValidReflectionNormal, LeavesNormalsAloneWhenTheViewIsBelowTheSurface) {
    const Vec3 n = normalize(Vec3(0.5f, 0, 1));
    EXPECT_EQ(valid_reflection_normal(kUp, normalize(Vec3(1, 0, -0.1f)), n), n);
}

// A plane whose normal map leans every normal 40 degrees towards +u (+x), seen from -x:
// the mapped normal faces away from every view lower than 40 degrees.
TEST(ShadeNormalMap, ShadingNormalFacesTheViewerWhereTheMapLeansAway) {
    Scene scene;
    const float tilt = 40 * kPi / 180;
    const Vec3 local(std::sin(tilt), 0, std::cos(tilt));
    Image img(1, 1, 4);
    for (int c = 0; c < 3; ++c) img.at(0, 0)[c] = (local[c] + 1) / 2;
    img.at(0, 0)[3] = 1;
    scene.images.push_back(TextureImage(img));
    Texture tex;
    tex.image = 0;
    tex.nearest = true;
    scene.textures.push_back(tex);
    MaterialDesc m;
    m.normal_texture.texture = 0;
    scene.materials.push_back(m);
    SurfacePoint sp;
    sp.ng = sp.ns = kUp;
    sp.dpdu = Vec3(1, 0, 0);
    sp.material = 0;
    for (const float deg : {2.0f, 10.0f, 30.0f, 39.0f, 41.0f, 60.0f}) {
        const float e = deg * kPi / 180;
        const Vec3 wo(-std::cos(e), 0, std::sin(e));
        const ShadingData sd = shade(scene, sp, wo);
        EXPECT_GT(dot(sd.frame.n, wo), 0) << deg;
        EXPECT_GT(dot(mirror(wo, sd.frame.n), kUp), 0) << deg;
        EXPECT_GT(sd.frame.n.x, 0) << deg;  // still leaning the way the map leans
        // A view the mapped normal mirrors well above the surface keeps it.
        if (dot(mirror(wo, normalize(Vec3(local.x, 0, local.z))), kUp) > 0.01f)
            EXPECT_NEAR(length(sd.frame.n - Vec3(local.x, 0, local.z)), 0, 1e-5f) << deg;
    }
}

}  // namespace
}  // namespace penumbra
