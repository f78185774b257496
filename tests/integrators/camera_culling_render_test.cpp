// Camera rays pass through the backs of single-sided surfaces in every integrator, the
// AOVs and the denoiser's guides, with the same image from Embree and the BVH; light
// paths (shadow rays, bounces, a mirror's reflection) still see both sides, so a closed
// room seen from outside shows its inside, lit exactly as it is seen from inside.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/camera/camera_culling.h"
#include "core/camera/perspective_camera.h"
#include "core/lights/point_light.h"
#include "integrators/denoise_guide.h"
#include "integrators/first_hit.h"
#include "integrators/render.h"
#include "materials/lobes/fresnel.h"
#include "support/scene_builder.h"
#include "support/option_names.h"

namespace penumbra {
namespace {

const int kSize = 16;  // whole 4 x 2 packets: the render loop hands the path tracer first hits
const char* const kIntegrators[] = {"path", "direct", "basic"};
const AccelType kAccels[] = {AccelType::Embree, AccelType::BvhSah};

// A single-sided square [-1, 1]^2 at z = 0, its front facing +z.
Scene square_scene() {
    Scene scene;
    const int m = test::add_lambertian(scene, Spectrum(0.5f));
    test::add_instance(
        scene, test::add_quad_object(scene, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, m),
        Transform());
    return scene;
}

// The room [-1, 1]^3 with single-sided (unless double_sided) Lambertian walls of albedo
// 1/2 facing inwards, with a point light inside when lit.
Scene room(bool double_sided, bool lit) {
    Scene scene;
    const int walls = test::add_lambertian(scene, Spectrum(0.5f));
    scene.materials[size_t(walls)].double_sided = double_sided;
    const uint32_t cube = test::add_cube_object(scene, walls);
    TriangleMesh& mesh = scene.meshes[scene.objects[cube].meshes[0]];
    for (size_t i = 0; i < mesh.indices.size(); i += 3)
        std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
    for (Vec3& n : mesh.normals) n = -n;
    test::add_instance(scene, cube, Transform::scale({2, 2, 2}));
    if (lit) scene.lights.push_back(std::make_unique<PointLight>(Vec3(0.3f, 0.5f, 0), Spectrum(2)));
    return scene;
}

// Outside the room, in front of its z = +1 wall: the 0.3 radian view stays within the
// wall (half-width 3 tan 0.15 = 0.45 at z = 1), so every pixel looks through it.
const Transform kOutside = Transform::look_at({0, 0, 4}, {0, 0, 0}, {0, 1, 0});

Film render_view(const Scene& scene, AccelType type, const std::string& integrator,
                 const Transform& eye, float yfov, float environment, AovSet aovs = {}) {
    const auto accel = make_accel(type, scene);
    const LightSet lights(
        scene, environment > 0 ? std::make_unique<EnvironmentLight>(Spectrum(environment), 10.0f)
                               : nullptr);
    const RenderContext ctx{scene, *accel, lights};
    const auto integ = make_integrator(test::integrator_named(integrator), {});
    const PerspectiveCamera camera(eye, yfov, kSize, kSize);
    RenderOptions opt;
    opt.spp = 4;
    opt.seed = 9;
    opt.progress = false;
    opt.filter = FilterType::Box;
    opt.aovs = aovs;
    return render(ctx, camera, *integ, opt);
}

// The image of every integrator from Embree and the BVH, checked to agree, and `check` run
// on each. Their hits agree to float rounding (barycentrics 3e-8 apart here), which moves
// these pixels by at most 4e-6 (measured, path); a hit culled by one and not the other
// would move its pixel by a sample's worth, 1/4 of a value of 0.05 to 1 at 4 spp.
template <typename Check>
void for_each_image(const Scene& scene, const Transform& eye, float yfov, float environment,
                    Check check) {
    for (const char* integrator : kIntegrators) {
        const Image embree =
            render_view(scene, AccelType::Embree, integrator, eye, yfov, environment).resolve();
        const Image bvh =
            render_view(scene, AccelType::BvhSah, integrator, eye, yfov, environment).resolve();
        ASSERT_EQ(embree.pixels.size(), bvh.pixels.size());
        float worst = 0;
        for (size_t i = 0; i < embree.pixels.size(); ++i)
            worst = std::max(worst, std::abs(embree.pixels[i] - bvh.pixels[i]));
        EXPECT_LT(worst, 1e-4f) << integrator;
        check(embree, integrator);
        check(bvh, integrator);
    }
}

float min_over(const Image& img, int c) {
    float m = img.at(0, 0)[c];
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) m = std::min(m, img.at(x, y)[c]);
    return m;
}
float max_over(const Image& img, int c) {
    float m = img.at(0, 0)[c];
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) m = std::max(m, img.at(x, y)[c]);
    return m;
}

// Under a white sky the square's front shows its albedo times the sky (1/2, 0 for the
// basic integrator, which takes no environment light), its back the sky itself.
TEST(CameraCullingRender, ASingleSidedSquareSeenFromBehindIsInvisible) {
    const Scene scene = square_scene();
    const float yfov = 0.5f;  // half-height 3 tan 0.25 = 0.77 at the square: all square
    for_each_image(scene, Transform::look_at({0, 0, -3}, {0, 0, 0}, {0, 1, 0}), yfov, 1,
                   [](const Image& img, const char* integrator) {
                       EXPECT_NEAR(min_over(img, 1), 1.0f, 1e-6f) << integrator;
                       EXPECT_NEAR(max_over(img, 1), 1.0f, 1e-6f) << integrator;
                   });
    for_each_image(scene, Transform::look_at({0, 0, 3}, {0, 0, 0}, {0, 1, 0}), yfov, 1,
                   [](const Image& img, const char* integrator) {
                       EXPECT_LT(max_over(img, 1), 0.9f) << integrator;
                   });
}

TEST(CameraCullingRender, ADoubleSidedSquareIsSeenFromBothSides) {
    Scene scene = square_scene();
    scene.materials[0].double_sided = true;
    for_each_image(scene, Transform::look_at({0, 0, -3}, {0, 0, 0}, {0, 1, 0}), 0.5f, 1,
                   [](const Image& img, const char* integrator) {
                       EXPECT_LT(max_over(img, 1), 0.9f) << integrator;
                   });
}

// The dollhouse: from outside, the camera sees the lit inside of the far walls, where
// without culling it sees the dark outside of the near wall.
TEST(CameraCullingRender, AClosedRoomSeenFromOutsideShowsItsInside) {
    for_each_image(room(false, true), kOutside, 0.3f, 0,
                   [](const Image& img, const char* integrator) {
                       EXPECT_GT(min_over(img, 1), 0.01f) << integrator;
                   });
    for_each_image(room(true, true), kOutside, 0.3f, 0,
                   [](const Image& img, const char* integrator) {
                       EXPECT_EQ(max_over(img, 1), 0.0f) << integrator;
                   });
}

// Light paths see the walls from both sides: a sky outside the closed room lights
// nothing inside it.
TEST(CameraCullingRender, NoLightLeaksIntoAClosedRoom) {
    for_each_image(room(false, false), kOutside, 0.3f, 1,
                   [](const Image& img, const char* integrator) {
                       EXPECT_EQ(max_over(img, 0), 0.0f) << integrator;
                       EXPECT_EQ(max_over(img, 1), 0.0f) << integrator;
                       EXPECT_EQ(max_over(img, 2), 0.0f) << integrator;
                   });
}

// Inside, each camera ray carries the radiance of the same ray started just beyond the
// wall in the room without culling, bit for bit: the light inside is unchanged, and a
// culled wall is no vertex of the path (it draws no sample).
TEST(CameraCullingRender, TheInsideIsLitAsWithoutCulling) {
    const Scene culled = room(false, true), reference = room(true, true);
    const PerspectiveCamera camera(kOutside, 0.3f, kSize, kSize);
    for (const char* integrator : kIntegrators) {
        const auto integ = make_integrator(test::integrator_named(integrator), {});
        const auto accel = make_accel(AccelType::Embree, culled);
        const auto ref_accel = make_accel(AccelType::Embree, reference);
        const LightSet lights(culled, nullptr), ref_lights(reference, nullptr);
        const RenderContext ctx{culled, *accel, lights}, ref_ctx{reference, *ref_accel, ref_lights};
        auto sampler = make_sampler(SamplerType::Independent, 1, 3);
        int lit = 0;
        for (int i = 0; i < 64; ++i) {
            CameraSample cs;
            cs.film = {i % 8 * 2 + 0.5f, i / 8 * 2 + 0.5f};
            const Ray ray = camera.generate_ray(cs);
            // Where the path from outside goes on: beyond the near wall.
            Ray inside = ray;
            const std::optional<Hit> wall = accel->intersect(ray);
            ASSERT_TRUE(wall);
            const SurfacePoint sp = make_surface_point(culled, ray, *wall);
            ASSERT_TRUE(camera_culls(culled, sp, ray.d));
            pass_culled(sp, inside);
            for (uint32_t s = 0; s < 4; ++s) {
                sampler->start_pixel_sample({i, 0}, s);
                const Spectrum L = integ->Li(ray, ctx, *sampler);
                sampler->start_pixel_sample({i, 0}, s);
                const Spectrum L_ref = integ->Li(inside, ref_ctx, *sampler);
                EXPECT_EQ(L.x, L_ref.x) << integrator << " ray " << i << " sample " << s;
                EXPECT_EQ(L.y, L_ref.y) << integrator << " ray " << i << " sample " << s;
                EXPECT_EQ(L.z, L_ref.z) << integrator << " ray " << i << " sample " << s;
                lit += L.y > 0;
            }
        }
        EXPECT_GT(lit, 128) << integrator;  // not vacuous: most samples see light
    }
}

// A single-sided square at y = 1 between a point light above it and the floor shadows the
// floor under it (direct light only, so the shadow is exactly black; without the square
// the floor there is lit), whichever face the shadow rays meet. Facing down, the camera
// above sees through its back to the shadow; facing up, a camera below it sees the
// shadow obliquely, and the shadow rays meet the square's back.
TEST(CameraCullingRender, ACulledSurfaceStillCastsItsShadow) {
    struct Case {
        bool facing_up;
        Transform eye;
        float yfov;
    };
    // Above: half-width 4 tan 0.1 = 0.4 at the floor. Below: the view meets the floor
    // within z in [-0.55, 0.4], |x| < 0.1. Both inside the shadow, [-0.75, 0.75]^2.
    const Case cases[] = {{false, Transform::look_at({0, 4, 0}, {0, 0, 0}, {0, 0, -1}), 0.2f},
                          {true, Transform::look_at({0, 0.5f, 3}, {0, 0, 0}, {0, 1, 0}), 0.05f}};
    for (const Case& k : cases)
        for (bool occluder : {true, false}) {
            Scene scene;
            const int m = test::add_lambertian(scene, Spectrum(0.5f));
            test::add_instance(
                scene,
                test::add_quad_object(scene, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, {-5, 0, -5}, m),
                Transform());
            if (occluder) {
                const Vec3 c0(-0.5f, 1, -0.5f), c1(0.5f, 1, -0.5f), c2(0.5f, 1, 0.5f),
                    c3(-0.5f, 1, 0.5f);  // counter-clockwise from below
                test::add_instance(scene,
                                   k.facing_up ? test::add_quad_object(scene, c0, c3, c2, c1, m)
                                               : test::add_quad_object(scene, c0, c1, c2, c3, m),
                                   Transform());
            }
            scene.lights.push_back(std::make_unique<PointLight>(Vec3(0, 3, 0), Spectrum(4)));
            for (const char* integrator : {"direct", "basic"})
                for (AccelType type : kAccels) {
                    const Image img =
                        render_view(scene, type, integrator, k.eye, k.yfov, 0).resolve();
                    if (occluder)
                        EXPECT_EQ(max_over(img, 1), 0.0f) << integrator << " up " << k.facing_up;
                    else
                        EXPECT_GT(min_over(img, 1), 0.01f) << integrator << " up " << k.facing_up;
                }
        }
}

// The first-hit AOVs and the guides describe the surface the beauty shows: the far wall,
// 5 away along the axis, not the culled near wall 3 away.
TEST(CameraCullingRender, AovsAndGuidesSeeWhatTheBeautyShows) {
    const Scene scene = room(false, true);
    for (AccelType type : kAccels) {
        const Film film = render_view(scene, type, "path", kOutside, 0.3f, 0,
                                      {Aov::Albedo, Aov::Depth, Aov::Normal});
        const Image depth = film.resolve_aov(Aov::Depth);
        // A corner ray runs along (tan 0.15, tan 0.15, -1): 5 sqrt(1 + 2 tan^2 0.15) = 5.113.
        EXPECT_GT(min_over(depth, 0), 4.9999f);
        EXPECT_LT(max_over(depth, 0), 5.12f);
        EXPECT_NEAR(film.resolve_aov(Aov::Albedo).at(8, 8)[0], 0.5f, 1e-6f);

        const auto accel = make_accel(type, scene);
        const LightSet lights(scene, nullptr);
        const RenderContext ctx{scene, *accel, lights};
        Ray axis;
        axis.o = Vec3(0, 0, 4);
        axis.d = Vec3(0, 0, -1);
        for (uint64_t key : {1u, 2u}) {
            const AovRecord aov = first_hit_aovs(axis, ctx, key);
            EXPECT_TRUE(aov.hit);
            EXPECT_NEAR(aov.depth, 5.0f, 1e-5f);
            EXPECT_NEAR(aov.normal.z, 1.0f, 1e-6f);
            const GuideRecord guide = denoise_guide(axis, ctx, key);
            EXPECT_NEAR(guide.depth, 5.0f, 1e-5f);
            EXPECT_NEAR(guide.albedo.x, 0.5f, 1e-6f);
        }
    }
}

// After a specular bounce the path carries light and sees both sides: a mirror shows the
// back of a single-sided wall. The camera at the origin looks down -z at a mirror turned
// 45 degrees about y, which reflects the ray to +x, onto the wall x = 2 whose front faces
// +x, away from it.
TEST(CameraCullingRender, AMirrorShowsTheBackOfASingleSidedSurface) {
    Scene scene;
    MaterialDesc metal;
    metal.base_color = Vec4(0.9f, 0.6f, 0.3f, 1);
    metal.metallic = 1;
    metal.roughness = 0;
    scene.materials.push_back(metal);
    const Vec3 c(0, 0, -2), u = normalize(Vec3(1, 0, -1)) * 0.5f, v(0, 0.5f, 0);
    test::add_instance(scene,
                       test::add_quad_object(scene, c - u - v, c + u - v, c + u + v, c - u + v, 0),
                       Transform());
    const int wall = test::add_lambertian(scene, Spectrum(0.2f, 0.5f, 0.8f));
    test::add_instance(
        scene, test::add_quad_object(scene, {2, -2, 0}, {2, -2, -4}, {2, 2, -4}, {2, 2, 0}, wall),
        Transform());
    // A point light on that side of the wall, 1 from where the reflected ray meets it.
    scene.lights.push_back(std::make_unique<PointLight>(Vec3(1, 0, -2), Spectrum(1)));
    const auto accel = make_accel(AccelType::Embree, scene);
    const LightSet lights(scene, nullptr);
    const RenderContext ctx{scene, *accel, lights};
    Ray ray;
    ray.d = Vec3(0, 0, -1);
    const GuideRecord g = denoise_guide(ray, ctx, 1);
    EXPECT_NEAR(g.depth, 4.0f, 1e-4f);
    const Spectrum f = fresnel_schlick(Spectrum(0.9f, 0.6f, 0.3f), 1, std::sqrt(0.5f));
    EXPECT_NEAR(g.albedo.z, f.z * 0.8f, 1e-5f);
    // The beauty: the wall's lit back in the mirror, about f 0.8 / pi (1 / 1^2) in blue;
    // exactly 0 if the reflected ray passed through the wall (no environment).
    for (const char* integrator : kIntegrators) {
        auto sampler = make_sampler(SamplerType::Independent, 1, 3);
        sampler->start_pixel_sample({0, 0}, 0);
        const Spectrum L = make_integrator(test::integrator_named(integrator), {})->Li(ray, ctx, *sampler);
        EXPECT_GT(L.z, 0.5f * f.z * 0.8f / kPi) << integrator;
    }
}

}  // namespace
}  // namespace penumbra
