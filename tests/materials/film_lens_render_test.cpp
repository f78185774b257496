// A thin-walled iridescent lens (KHR_materials_transmission and _iridescence, loaded
// from glTF, path traced) between white lights: backlit it passes the complement 1 - R'
// of the film's reflected colour, neither grey nor black; front-lit, a sunglasses lens
// (IOR 1, base colour 0.009) shows the film's R'; between both lights a clear lens
// vanishes (R' + T' = 1).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/camera/perspective_camera.h"
#include "io/gltf/gltf_loader.h"
#include "materials/lobes/thin_dielectric.h"
#include "support/gltf_builder.h"
#include "support/render_scene.h"

namespace penumbra {
namespace {

float spread(Spectrum s) { return max_component(s) - std::min({s.x, s.y, s.z}); }

// The sheet's R' under the lens' film (iridescenceIor 1.8, 300 nm) at cos_theta.
Spectrum sheet_reflectance(float ior, float cos_theta) {
    DielectricParams p;
    p.eta = ior;
    p.iridescence = 1;
    p.film = ThinFilm{1, 1.8f, 300};
    return ThinDielectricBsdf(p).reflectance(cos_theta);
}

// A lens quad (z = 0, facing +z) between two white emitters, each optional: one behind it
// (z = -1) and one behind the camera (z = 3), the camera at z = 2 looking down -z. The
// lens is thin-walled KHR_materials_transmission with KHR_materials_iridescence.
Scene lens_scene(float ior, float base, bool front_light, bool back_light) {
    test::ScratchDir dir;
    test::GltfBuilder b;
    const auto quad = [&](float h, float z) {
        return b.add(std::vector<float>{-h, -h, z, h, -h, z, h, h, z, -h, h, z}, test::kFloat,
                     "VEC3");
    };
    const int idx = b.add(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, test::kUShort, "SCALAR");
    const int lens = quad(1, 0), back = quad(20, -1), front = quad(20, 3);
    const auto prim = [&](int pos, int material) {
        return "{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
               "},\"indices\":" + std::to_string(idx) +
               ",\"material\":" + std::to_string(material) + "}";
    };
    std::ostringstream m;
    m << R"("extensionsUsed":["KHR_materials_transmission","KHR_materials_iridescence",
        "KHR_materials_ior","KHR_materials_specular"],
        "materials":[{"doubleSided":true,"pbrMetallicRoughness":{"baseColorFactor":[)"
      << base << "," << base << "," << base << R"(,1],"metallicFactor":0,"roughnessFactor":0},
        "extensions":{"KHR_materials_transmission":{"transmissionFactor":1},
          "KHR_materials_ior":{"ior":)"
      << ior << R"(},
          "KHR_materials_iridescence":{"iridescenceFactor":1,"iridescenceIor":1.8,
            "iridescenceThicknessMaximum":300}}},
        {"doubleSided":true,"emissiveFactor":[1,1,1],
         "pbrMetallicRoughness":{"baseColorFactor":[0,0,0,1],"metallicFactor":0},
         "extensions":{"KHR_materials_specular":{"specularFactor":0}}}],
        "meshes":[{"primitives":[)"
      << prim(lens, 0);
    if (back_light) m << "," << prim(back, 1);
    if (front_light) m << "," << prim(front, 1);
    m << R"(]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0)";
    return load_gltf(b.write(dir, "lens.gltf", m.str(), test::BufferStorage::DataUri), {});
}

struct PixelStats {
    Spectrum mean, se;
};
PixelStats render_lens(const Scene& scene) {
    // A narrow view of the lens' centre: every ray within 0.25 degrees of its normal.
    const int res = 16;
    const PerspectiveCamera camera(Transform::look_at({0, 0, 2}, {0, 0, 0}, {0, 1, 0}), 0.008f, res,
                                   res);
    const test::SceneRender r = test::render_scene(scene, camera, "path", 64, 3, 8);
    EXPECT_EQ(r.nonfinite_samples, 0u);
    Spectrum sum, sum2;
    for (int y = 0; y < res; ++y)
        for (int x = 0; x < res; ++x) {
            const Spectrum v(r.image.at(x, y)[0], r.image.at(x, y)[1], r.image.at(x, y)[2]);
            sum += v;
            sum2 += v * v;
        }
    const float n = res * res;
    PixelStats s;
    s.mean = sum / n;
    for (int c = 0; c < 3; ++c)
        s.se[c] = std::sqrt(std::max(0.0f, sum2[c] / n - s.mean[c] * s.mean[c]) / (n - 1));
    return s;
}

TEST(IridescentLens, ShowsTheFilmsColoursThroughThePathTracer) {
    // The sheet's reflectance R' near normal incidence, from the model itself; the film's
    // colour changes by less than 1e-4 over the view's 0.25 degrees (cos >= 0.99999).
    const Spectrum R = sheet_reflectance(1.5f, 1);
    const Spectrum R_dark = sheet_reflectance(1.0f, 1);
    ASSERT_GT(spread(R), 0.05f);

    // Backlit clear lens: the transmitted colour is the complement 1 - R' of the
    // reflected one, neither grey nor black.
    const PixelStats back = render_lens(lens_scene(1.5f, 1, false, true));
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(back.mean[c], 1 - R[c], 4 * back.se[c] + 1e-4f) << "channel " << c;
    EXPECT_GT(spread(back.mean), 0.05f);
    EXPECT_GT(std::min({back.mean.x, back.mean.y, back.mean.z}), 0.3f);

    // Front-lit sunglasses lens (IOR 1, base colour 0.009, nothing behind): the film's
    // reflection alone, coloured, not black.
    const PixelStats front = render_lens(lens_scene(1.0f, 0.009f, true, false));
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(front.mean[c], R_dark[c], 4 * front.se[c] + 1e-4f) << "channel " << c;
    EXPECT_GT(max_component(front.mean), 0.1f);
    EXPECT_GT(spread(front.mean), 0.05f);

    // Between two white lights the clear lens vanishes: R' + T' = 1 in every channel.
    const PixelStats both = render_lens(lens_scene(1.5f, 1, true, true));
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(both.mean[c], 1.0f, 4 * both.se[c] + 1e-4f) << "channel " << c;
}

}  // namespace
}  // namespace penumbra
