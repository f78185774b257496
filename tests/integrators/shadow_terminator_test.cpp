// The shadow terminator on a coarse mesh with smooth normals (scenes/hard/
// terminator-sphere.gltf: an 8 x 16 UV sphere lit from the side) against a finely
// tessellated sphere. Without Hanika's lifted ray origins and the interpolated-normal
// side test (core/surface_point.*), facets whose plane faces away from the light go
// black while their normals still face it: a staircase along the terminator.
#include <gtest/gtest.h>

#include <cmath>

#include "core/camera/orthographic_camera.h"
#include "io/gltf/gltf_loader.h"
#include "support/paths.h"
#include "support/render_scene.h"
#include "support/scene_builder.h"

namespace penumbra {
namespace {

struct TerminatorStats {
    float max_diff = 0;    // largest |coarse - fine| over the compared pixels, / lit value
    int black_facets = 0;  // pixels black on the coarse sphere where the fine one is lit
    int compared = 0;
};

TerminatorStats compare_spheres(const std::string& integrator, uint32_t spp) {
    const Scene coarse = load_gltf(test::source_path("scenes/hard/terminator-sphere.gltf"));
    Scene fine = load_gltf(test::source_path("scenes/hard/terminator-sphere.gltf"));
    fine.instances.clear();
    const uint32_t sphere = test::add_sphere_object(fine, 0, 128, 256);
    test::add_instance(fine, sphere, Transform::translate({0, 0, 0}));

    const int res = 96;
    const OrthographicCamera camera(Transform::look_at({0, 0, 3}, {0, 0, 0}, {0, 1, 0}), 1.05f,
                                    1.05f, res, res);
    const test::SceneRender a = test::render_scene(coarse, camera, integrator, spp, 7);
    const test::SceneRender b = test::render_scene(fine, camera, integrator, spp, 7);
    EXPECT_EQ(a.nonfinite_samples + b.nonfinite_samples, 0u);

    // Sun of 1 lux: a surface facing it has radiance albedo / pi.
    const float lit = 0.8f / kPi;
    TerminatorStats s;
    for (int y = 0; y < res; ++y)
        for (int x = 0; x < res; ++x) {
            // Pixel centre in the view plane; keep inside the coarse silhouette (an
            // inscribed 16-gon of radius cos(pi/16) = 0.98) with a margin for the facets.
            const float u = (x + 0.5f) / res * 2.1f - 1.05f, v = (y + 0.5f) / res * 2.1f - 1.05f;
            if (u * u + v * v > 0.85f * 0.85f) continue;
            const float ca = test::pixel_mean(a.image, x, y), cb = test::pixel_mean(b.image, x, y);
            ++s.compared;
            s.max_diff = std::max(s.max_diff, std::abs(ca - cb) / lit);
            if (ca == 0 && cb > 0.02f * lit) ++s.black_facets;
        }
    return s;
}

// The bound: a faceted terminator leaves whole facets black, a difference up to
// sin(22.5 deg) = 0.38 of the lit value right next to the terminator; interpolated
// normals alone stay within a few degrees of the true ones. Measured: 0.031.
TEST(ShadowTerminator, CoarseSmoothSphereMatchesAFineOne) {
    const TerminatorStats s = compare_spheres("basic", 4);
    ASSERT_GT(s.compared, 4000);
    EXPECT_EQ(s.black_facets, 0);
    EXPECT_LT(s.max_diff, 0.1f);
    RecordProperty("max_diff", std::to_string(s.max_diff));
    std::printf("shadow terminator (basic): max |coarse - fine| = %.4f of the lit value over %d "
                "pixels\n",
                s.max_diff, s.compared);
}

TEST(ShadowTerminator, PathTracerToo) {
    // Light sampling and BSDF sampling use the same side test, so MIS stays consistent;
    // with 64 spp the noise adds a few percent to the difference.
    const TerminatorStats s = compare_spheres("path", 64);
    EXPECT_EQ(s.black_facets, 0);
    EXPECT_LT(s.max_diff, 0.15f);
    std::printf("shadow terminator (path): max |coarse - fine| = %.4f of the lit value\n",
                s.max_diff);
}

}  // namespace
}  // namespace penumbra
