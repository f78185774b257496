// The light set's bookkeeping: an emissive hit maps back to the light of its instance,
// mesh and triangle (shared objects, several emissive meshes, non-emissive ones), and
// pmf() finds every light it holds (and none it does not) as sample() reports it.
#include "core/lights/light_set.h"

#include <gtest/gtest.h>

#include <memory>
#include <set>

#include "core/lights/point_light.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

// Instances 0 and 2 share an object of a grey quad and two emissive ones (materials 1
// and 2); instance 1 holds only the grey quad; one point light and the environment.
Scene shared_emitters() {
    Scene scene;
    const int grey = test::add_lambertian(scene, Spectrum(0.5f));
    for (float e : {2.0f, 5.0f}) {
        MaterialDesc m;
        m.emissive = Spectrum(e);
        scene.materials.push_back(m);
    }
    const uint32_t plain = test::add_quad_object(scene, {0, 0, 0}, {1, 0, 0}, {1, 0, 1},
                                                 {0, 0, 1}, grey);
    const uint32_t lit = test::add_quad_object(scene, {0, 1, 0}, {1, 1, 0}, {1, 1, 1},
                                               {0, 1, 1}, 1);
    const uint32_t bright = test::add_quad_object(scene, {0, 2, 0}, {2, 2, 0}, {2, 2, 1},
                                                  {0, 2, 1}, 2);
    // One object of the three meshes (the grey one first).
    Object both = scene.objects[plain];
    both.meshes = {scene.objects[plain].meshes[0], scene.objects[lit].meshes[0],
                   scene.objects[bright].meshes[0]};
    scene.objects.push_back(both);
    const uint32_t shared = static_cast<uint32_t>(scene.objects.size() - 1);
    test::add_instance(scene, shared, Transform());
    test::add_instance(scene, plain, Transform::translate({0, -5, 0}));
    test::add_instance(scene, shared, Transform::translate({10, 0, 0}));
    scene.lights.push_back(std::make_unique<PointLight>(Vec3(0, 3, 0), Spectrum(1)));
    return scene;
}

TEST(LightSet, EmissiveHitsFindTheLightOfTheirInstanceMeshAndTriangle) {
    const Scene scene = shared_emitters();
    const LightSet lights(scene, std::make_unique<EnvironmentLight>(Spectrum(0.5f), 10.0f),
                          {LightSamplerType::Power, TriangleSampling::Area});
    ASSERT_EQ(lights.triangle_light_count(), 8u);  // 2 meshes x 2 triangles x 2 instances
    const uint32_t grey_mesh = scene.objects[0].meshes[0];
    const uint32_t lit_mesh = scene.objects[1].meshes[0];
    const uint32_t bright_mesh = scene.objects[2].meshes[0];
    std::set<const TriangleLight*> seen;
    for (uint32_t instance : {0u, 2u})
        for (uint32_t mesh : {lit_mesh, bright_mesh})
            for (uint32_t prim = 0; prim < 2; ++prim) {
                const TriangleLight* light = lights.triangle_light(instance, mesh, prim);
                ASSERT_NE(light, nullptr) << instance << " " << mesh << " " << prim;
                seen.insert(light);
                // Its corners are the mesh's triangle, placed by the instance.
                const TriangleMesh& m = scene.meshes[mesh];
                const Transform& xf = scene.instances[instance].to_world;
                Vec3 lo(1e30f), hi(-1e30f);
                for (int k = 0; k < 3; ++k) {
                    const Vec3 p = xf.point(m.positions[m.indices[3 * prim + k]]);
                    lo = min(lo, p);
                    hi = max(hi, p);
                }
                const std::optional<LightBounds> b = light->bounds();
                ASSERT_TRUE(b);
                EXPECT_EQ(b->lo, lo);
                EXPECT_EQ(b->hi, hi);
            }
    EXPECT_EQ(seen.size(), 8u);
    EXPECT_EQ(lights.triangle_light(0, grey_mesh, 0), nullptr);
    EXPECT_EQ(lights.triangle_light(1, grey_mesh, 0), nullptr);
    EXPECT_EQ(lights.triangle_light(1, lit_mesh, 0), nullptr);  // not in instance 1
    EXPECT_EQ(lights.triangle_light(3, lit_mesh, 0), nullptr);  // no such instance
}

TEST(LightSet, PmfFindsEveryLightItHoldsAndNoOther) {
    const Scene scene = shared_emitters();
    const PointLight stranger(Vec3(0), Spectrum(1));
    for (LightSamplerType type :
         {LightSamplerType::Uniform, LightSamplerType::Power, LightSamplerType::Bvh}) {
        const LightSet lights(scene, std::make_unique<EnvironmentLight>(Spectrum(0.5f), 10.0f),
                              {type, TriangleSampling::Area});
        ASSERT_EQ(lights.lights().size(), 10u);
        const ShadingPoint ref{{0.5f, 0.5f, 0.5f}, {0, 1, 0}};
        // Each light is chosen with the probability pmf() gives it, with and without a
        // receiver: sample() reports the pmf of the index it chose.
        for (int i = 0; i < 1000; ++i) {
            const float u = (i + 0.5f) / 1000;
            if (const auto s = lights.sample(ref, u)) {
                EXPECT_FLOAT_EQ(lights.pmf(ref, s->light), s->pmf);
            }
            const auto s = lights.sample(u);
            ASSERT_TRUE(s);
            EXPECT_FLOAT_EQ(lights.pmf(s->light), s->pmf);
        }
        double sum = 0;
        for (const Light* l : lights.lights()) {
            EXPECT_GT(lights.pmf(l), 0);
            sum += lights.pmf(l);
        }
        EXPECT_NEAR(sum, 1.0, 1e-5);
        EXPECT_EQ(lights.pmf(ref, &stranger), 0);
        EXPECT_EQ(lights.pmf(&stranger), 0);
        EXPECT_EQ(lights.pmf(ref, nullptr), 0);
    }
}

}  // namespace
}  // namespace penumbra
